"""The recommended point: the most robust point of the plausible set, and observables that say nothing.

The recommended point minimises the implausibility ``I(x) = max_k |ŷ_k(x) - y_k*| / H_k(x)`` (H the
plausible half-width of :data:`~demid.sampling.residuals.PLAUSIBLE_DEFINITION`): the point with the
largest margin ``1 - I`` to every band.  It is plausible when ``I <= 1``.  Searched on the grid of the
plausible sets (above three factors, 2^14 scrambled Sobol points, seed 0); its digits are set by the plausible interval it is
shown with (:func:`digits_for`).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from ..sampling import uses_grid

if TYPE_CHECKING:
    from ..scenario import JudgedScenario

#: An observable is uninformative when its band alone leaves at least this share of Ω admissible.
UNINFORMATIVE_FRACTION = 0.99


def _points(domain, n: int, seed: int = 0) -> np.ndarray:
    lo, hi = domain.search_bounds()
    if uses_grid(domain.dim):
        n = n if domain.dim <= 2 else min(n, 61)
        axes = [np.linspace(a, b, n) for a, b in zip(lo, hi)]
        unit = np.column_stack([g.ravel() for g in np.meshgrid(*axes, indexing="ij")])
    else:
        from scipy.stats import qmc

        unit = lo + qmc.Sobol(domain.dim, scramble=True, seed=seed).random(2 ** 14) * (hi - lo)
    return domain.to_actual(unit)


def recommended_point(judged: JudgedScenario, n: int = 401) -> dict:
    """``{"scenario", "point", "implausibility", "plausible"}`` for one judged scenario (its observables'
    targets), by the scenario's own implausibility and membership test."""
    spec = judged.spec
    points = _points(spec.domain, n)
    values = judged.implausibility(points)
    best = int(np.argmin(values))
    return {"scenario": judged.name, "point": dict(zip(spec.factor_names, points[best].tolist())),
            "implausibility": float(values[best]), "plausible": bool(judged.contains(points[best:best + 1])[0])}


def digits_for(width: float) -> int:
    """Decimals that show a value to a tenth of an interval ``width`` (at least 0)."""
    if not (np.isfinite(width) and width > 0):
        return 4
    return max(0, 1 - int(math.floor(math.log10(width))))


def uninformative_observables(ranking, labels: dict | None = None) -> dict[str, str]:
    """Observables whose band alone removes less than 1 % of Ω (their single-observable strict fraction is at
    least :data:`UNINFORMATIVE_FRACTION`), with the reason in words."""
    out = {}
    if ranking is None or not len(ranking) or "n_observables" not in ranking:
        return out
    singles = ranking[ranking["n_observables"] == 1]
    for _, row in singles.iterrows():
        share = float(row["feasible_fraction_pct"])
        if share >= 100 * UNINFORMATIVE_FRACTION:
            o = str(row["observables"])
            bits = float(row.get("information_gain_bits", float("nan")))
            gain = f" ({bits:.2f} bit: the likelihood only tilts across the range)" if np.isfinite(bits) else ""
            out[o] = (f"its tolerance band covers (almost) its whole simulated range: alone it leaves {share:.3g} % of "
                      f"the search range admissible, so it removes less than {100 - 100 * UNINFORMATIVE_FRACTION:g} % "
                      f"and its information gain is ~0{gain}")
    return out

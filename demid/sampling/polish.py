"""Span polishing: the ends of an admissible set's spans moved onto the exact set boundary.

Each span end found on the grid (or among Sobol points) starts an SLSQP search
that pushes the factor as far as the residual constraints allow.
"""

from __future__ import annotations

import warnings
from typing import TYPE_CHECKING

import numpy as np

from .residuals import _fields, residual_evaluator

if TYPE_CHECKING:
    from .domain import Domain
    from ..surrogate import Surrogate
    from .grid import AdmissibleSet


# =========================================================================== span polishing
def start_points(evaluate, domain: Domain, aset: AdmissibleSet) -> np.ndarray:
    """Grid nodes to start polishing from: admissible nodes, else the least-violating ones."""
    d = domain.dim
    n = int(round(aset.n_nodes ** (1.0 / d)))
    mask = np.asarray(aset.mask, dtype=bool)
    if mask.any():
        axes = domain.axes(n)
        return np.column_stack([axes[i][j] for i, j in enumerate(np.unravel_index(np.flatnonzero(mask), (n,) * d))])
    nodes = domain.grid(min(n, int(1e6 ** (1.0 / d))))
    worst = np.max(np.abs(evaluate(nodes)), axis=0)
    return nodes[np.argsort(worst)[:max(16, 2 * d)]]


def _polish(evaluate, domain: Domain, eps: float, lower: np.ndarray, upper: np.ndarray,
            candidates: np.ndarray, starts: int) -> tuple[np.ndarray, np.ndarray]:
    """Extend span ends by SLSQP from the most extreme candidate points (actual units)."""
    from scipy import optimize  # on first use: exact sets never polish

    lo_u, hi_u = domain.search_bounds()
    scale = hi_u - lo_u

    def to_actual(v):
        return domain.to_actual(lo_u + np.clip(v, 0.0, 1.0) * scale)

    def constraints(v):
        r = evaluate(to_actual(v))[:, 0]
        return np.concatenate([eps - r, eps + r])

    unit = (domain.to_search(candidates) - lo_u) / scale
    lower_v = (domain.to_search(lower)[0] - lo_u) / scale
    upper_v = (domain.to_search(upper)[0] - lo_u) / scale
    for i in range(domain.dim):
        for sign in (1.0, -1.0):
            if (lower_v[i] <= 1e-12) if sign > 0 else (upper_v[i] >= 1 - 1e-12):
                continue  # the span already reaches the domain bound
            for v0 in unit[np.argsort(sign * unit[:, i])[:starts]]:
                with warnings.catch_warnings():
                    # SLSQP may step marginally outside the bounds; the point is re-checked below.
                    warnings.simplefilter("ignore", RuntimeWarning)
                    res = optimize.minimize(
                        lambda v, i=i, sign=sign: sign * v[i], v0,
                        jac=lambda v, i=i, sign=sign: sign * np.eye(len(v))[i],
                        method="SLSQP", bounds=[(0.0, 1.0)] * domain.dim,
                        constraints=[{"type": "ineq", "fun": constraints}],
                        options={"ftol": 1e-12, "maxiter": 300})
                v = np.clip(res.x, 0.0, 1.0)
                if np.max(np.abs(evaluate(to_actual(v))[:, 0])) > eps * (1 + 1e-9):
                    continue  # not admissible: keep the grid value
                if sign > 0:
                    lower_v[i] = min(lower_v[i], v[i])
                else:
                    upper_v[i] = max(upper_v[i], v[i])
    return domain.to_actual(lo_u + lower_v * scale)[0], domain.to_actual(lo_u + upper_v * scale)[0]


def polish_spans(surrogates: dict[str, Surrogate], domain: Domain, observables, targets: dict[str, float],
                 tolerance: float, admissible_set: AdmissibleSet, *, z: float = 0.0,
                 sigma: dict[str, float] | None = None, starts: int = 3) -> tuple[np.ndarray, np.ndarray]:
    """Span ends moved to the exact set boundary by SLSQP (``min/max x_i`` s.t. ``|r_k(x)| <= eps``).

    Starts from the grid's extreme admissible nodes (the ``starts`` nodes with the most
    extreme x_i; the least-violating nodes when no node is admissible).  A polished end is
    accepted only if the optimiser's point is admissible (to 1e-9 relative) and extends
    the span, so the result is never worse than the grid value.  Pass ``z``/``sigma`` to
    polish a plausible set.  Works in search units (log10 for log factors) scaled to
    [0, 1].  Verified against the exact extent of annuli.
    """
    observables = tuple(observables)
    eps = float(tolerance)
    lower = np.array(admissible_set.lower, dtype=float, copy=True)
    upper = np.array(admissible_set.upper, dtype=float, copy=True)
    if admissible_set.empty or not np.isfinite(lower).all():
        return lower, upper
    fields = _fields(surrogates, observables, targets, eps, z, sigma)
    evaluate = residual_evaluator(fields, observables, targets)
    return _polish(evaluate, domain, eps, lower, upper, start_points(evaluate, domain, admissible_set), starts)

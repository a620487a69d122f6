"""Tolerance sweeps: the feasible fraction Phi(eps) and spans as functions of eps."""

from __future__ import annotations

from typing import TYPE_CHECKING

import pandas as pd

from ..sampling import uses_grid
from ..sampling.grid import predict_grid
from ..spec import join_observables
from .plausible import summarise_set

if TYPE_CHECKING:
    from ..sampling import Domain
    from ..surrogate import Surrogate


SWEEP_COLUMNS = ["scenario", "observables", "tolerance", "feasible_fraction_pct", "factor",
                 "lower", "upper", "width"]


def tolerance_sweep(surrogates: dict[str, Surrogate], domain: Domain, scenarios: dict,
                    targets: dict[str, float], tolerances, n: int, *, z: float = 0.0,
                    sigma: dict[str, float] | None = None, with_error: bool = True, polish: bool = False,
                    sobol_points: int = 2 ** 14, seed: int = 0, strict_sets: dict | None = None) -> pd.DataFrame:
    """Phi(eps) and spans for every scenario at every tolerance (long form, one row per factor).

    ``scenarios``: name -> (observables, nominal tolerance); the nominal tolerance is added
    to ``tolerances``.  Strict sets by default (exact for polynomial surrogates in up to 3
    factors, see :func:`~demid.sampling.evaluate.evaluate_set`), plausible sets when ``z > 0``.  With
    ``with_error`` a trailing ``fraction_error_pct`` column bounds the numerical error of
    each fraction.  More than 3 factors: ``sobol_points`` scrambled Sobol points (2^14 unless given, scramble
    ``seed`` 0) instead of the grid, spans read off the sample unless ``polish``.
    ``strict_sets`` (name -> the scenario's strict set at its nominal tolerance) are reused
    for the nominal row, so it repeats Table 3.
    """
    needed = sorted({o for obs, _ in scenarios.values() for o in obs})
    base = (predict_grid({o: surrogates[o] for o in needed}, domain, n)
            if z == 0 and uses_grid(domain.dim) else None)
    frames = []
    for name, (observables, nominal) in scenarios.items():
        observables = tuple(observables)
        for eps in sorted(set(float(t) for t in tolerances) | {float(nominal)}):
            given = (strict_sets or {}).get(name) if z == 0 and eps == float(nominal) else None
            res = summarise_set(surrogates, domain, observables, targets, eps, n, z=z, sigma=sigma, polish=polish,
                                with_error=with_error, sobol_points=sobol_points, seed=seed, grid_predictions=base,
                                grid_set=given if given is not None and given.exact is not None else None)
            frame = pd.DataFrame({
                "scenario": name, "observables": join_observables(observables), "tolerance": eps,
                "feasible_fraction_pct": 100.0 * res.fraction, "factor": list(domain.factors),
                "lower": res.lower, "upper": res.upper, "width": res.width})
            if with_error:
                frame["fraction_error_pct"] = 100.0 * res.error
            frames.append(frame)
    return pd.concat(frames, ignore_index=True)


# =========================================================================== one material
#: Default tolerances of the sweep (the config's ``sweep_tolerances`` default).
DEFAULT_SWEEP_TOLERANCES = (0.005, 0.01, 0.02, 0.03, 0.05, 0.075, 0.1, 0.15, 0.2)

"""Per-observable tolerance: ``responses.<r>.tolerance`` (relative) or ``tolerance_abs`` (response units).

A scenario's tolerance ε applies to every observable that declares neither key.  An observable with
its own band a_k (``tolerance_abs``, or ``tolerance`` x |y*|) is judged by |ŷ - y*| <= a_k in every set
(strict, plausible, ranking).  Every set evaluator takes one tolerance per scenario; the override is
carried by the surrogate instead: the residual surrogate ``y* + c (ŷ - y*)`` with ``c = ε |y*| / a_k`` meets
``|ŷ' - y*| <= ε |y*|`` exactly where ``|ŷ - y*| <= a_k``.  It is a polynomial again (coefficients
scaled, the intercept shifted), so the exact set evaluator applies unchanged, and its standard errors,
measurement sd and discrepancy sd scale by the same c, so the plausible set is the one of the
original units.  In a tolerance sweep the override scales with the scenario tolerance.

This module is arithmetic on bands and polynomials and imports nothing of the package; a scenario's
measurement bands, its plausible fields and sets live in :mod:`demid.scenario`.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np


def observable_band(response, target: float, tolerance: float) -> float:
    """Half-width (response units) of the observable's tolerance band in a scenario of ``tolerance``."""
    if getattr(response, "tolerance_abs", None) is not None:
        return float(response.tolerance_abs)
    if getattr(response, "tolerance", None) is not None:
        return float(response.tolerance) * abs(float(target))
    return float(tolerance) * abs(float(target))


def band_scale(response, target: float, tolerance: float) -> float:
    """c = ε |y*| / a_k: 1 for an observable without its own tolerance."""
    own = observable_band(response, target, tolerance)
    return float(tolerance) * abs(float(target)) / own if own > 0 else 1.0


def rescaled_surrogate(surrogate, target: float, scale: float):
    """The polynomial ``y* + scale (ŷ - y*)`` with standard errors times ``scale``."""
    if scale == 1.0:
        return surrogate
    if hasattr(surrogate, "rescaled"):  # not a polynomial (demid.kriging): it rescales its own output
        return surrogate.rescaled(target, scale)
    coefficients = scale * np.asarray(surrogate.coefficients, dtype=float)
    intercept = [i for i, t in enumerate(surrogate.terms) if not any(t)]
    coefficients[intercept[0]] += (1.0 - scale) * float(target)
    return replace(surrogate, coefficients=coefficients, covariance=scale ** 2 * np.asarray(surrogate.covariance),
                   resid_var=scale ** 2 * float(surrogate.resid_var))


def relative_tolerances(spec, observables, tolerance: float) -> dict[str, float]:
    """Per observable, its band as a fraction of its target: a_k / |y*| (the scenario's ``tolerance`` without
    an override).  Level 2 judges each observable's relative error against this, as the sets do."""
    out = {}
    for o in observables:
        target = spec.targets[o]
        band = observable_band(spec.response(o), target, tolerance)
        out[o] = band / abs(float(target)) if target else float(tolerance)
    return out


def same_tolerances(tolerance: float, tolerances) -> bool:
    """Every own tolerance in ``tolerances`` (observable -> ε_k) is the scenario's ``tolerance`` (to round-off):
    the texts then speak of one tolerance, and weighted errors are plain relative errors."""
    return all(abs(float(v) - tolerance) <= 1e-12 * tolerance for v in (tolerances or {}).values())


def has_own_band(response) -> bool:
    """The response declares its own ``tolerance`` or ``tolerance_abs``."""
    return getattr(response, "tolerance", None) is not None or getattr(response, "tolerance_abs", None) is not None


def has_own_tolerance(spec) -> bool:
    return any(has_own_band(r) for r in spec.responses)


def scenario_scales(spec, tolerance: float) -> dict[str, float]:
    """Per response with a target: c at the scenario tolerance (1 without an override)."""
    return {r.name: band_scale(r, r.target, tolerance) for r in spec.responses if r.target is not None}


def scenario_surrogates(surrogates: dict, spec, tolerance: float) -> dict:
    """The surrogates a scenario of ``tolerance`` judges: rescaled where a response has its own tolerance."""
    if not has_own_tolerance(spec):
        return surrogates
    scales = scenario_scales(spec, tolerance)
    return {r: rescaled_surrogate(s, spec.targets[r], scales[r]) if r in scales else s
            for r, s in surrogates.items()}


def scenario_grid(grid, spec, tolerance: float):
    """Grid predictions (a frame with one column per response) transformed as :func:`scenario_surrogates`."""
    if grid is None or not has_own_tolerance(spec):
        return grid
    grid = grid.copy()
    for r, c in scenario_scales(spec, tolerance).items():
        if c != 1.0 and r in grid.columns:
            target = spec.targets[r]
            grid[r] = target + c * (grid[r].to_numpy(dtype=float) - target)
    return grid

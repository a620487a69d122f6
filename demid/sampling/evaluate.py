"""evaluate_set: the one evaluator of a strict admissible set, used by every consumer.

Polynomial surrogates in up to :data:`~demid.sampling.exact.MAX_EXACT_DIM` factors get the
exact set (:mod:`demid.sampling.exact`: roots along lines, span ends by bisection); anything
else (more factors, or fields that are not polynomials) gets the grid or Sobol estimator that
:func:`~demid.sampling.domain.uses_grid` picks.  The grid is still evaluated when a caller
needs its node mask (figures) or its closest approach; the numbers (fraction, its error,
spans) then come from the exact set.
"""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING

import numpy as np

from ..formulas import relative_error
from .domain import uses_grid
from .exact import MAX_EXACT_DIM, exact_set, polynomial_from_surrogate
from .grid import AdmissibleSet, admissible_set

if TYPE_CHECKING:
    import pandas as pd

    from ..surrogate import Surrogate
    from .domain import Domain
    from .exact import ExactSet

#: Method names written next to the numbers.
EXACT_METHOD = "exact (roots along lines, span ends by bisection)"


def uses_exact(surrogates: dict, observables, domain: Domain) -> bool:
    """True when the set of ``observables`` is computed exactly: polynomial surrogates on the
    domain's factors (same log scales), at most :data:`MAX_EXACT_DIM` factors."""
    from ..surrogate import Surrogate

    if domain.dim > MAX_EXACT_DIM:
        return False
    log = {f for f, lg in zip(domain.factors, domain.log) if lg}
    return all(isinstance(surrogates[o], Surrogate) and list(surrogates[o].factors) == list(domain.factors)
               and set(surrogates[o].log_factors) == log for o in observables)


def exact_set_on_domain(surrogates: dict, domain: Domain, observables, targets: dict[str, float],
                        tolerance: float, reference: dict | None = None) -> ExactSet:
    """The exact set of polynomial surrogates over ``domain`` (search units: log10 for log factors)."""
    lo, hi = domain.search_bounds()
    ref = None
    if reference is not None:
        ref = domain.to_search(np.array([[float(reference[f]) for f in domain.factors]]))[0]
    return exact_set([polynomial_from_surrogate(surrogates[o]) for o in observables],
                     [targets[o] for o in observables], tolerance, lo, hi, reference=ref,
                     factors=domain.factors, log=domain.log)


def relative_errors(surrogates: dict, domain: Domain, observables, targets: dict[str, float],
                    u: np.ndarray) -> np.ndarray:
    """Signed relative errors (prediction - target) / |target|, one row per observable, at points of the unit
    cube over the search box."""
    x = domain.from_unit(u)
    return np.stack([relative_error(surrogates[o].predict(x), targets[o]) for o in observables])


def start_nodes(domain: Domain) -> np.ndarray:
    """Nodes of a small grid (unit coordinates) from which the local searches over the domain start."""
    return domain.to_unit(domain.grid(21 if domain.dim <= 3 else 5))


#: Local searches of a closest approach: from the given start or the start grid's best node, and from the best node
#: of each of the grid's other basins up to this many in all (the largest error of several observables has a
#: basin per way of trading them off, and the best node's basin need not hold the lowest point).
CLOSEST_STARTS = 4


def basin_nodes(values: np.ndarray, per_axis: int, dim: int, count: int) -> np.ndarray:
    """Indices of the nodes of a ``per_axis``-per-axis grid ('ij' order) no higher than any neighbour along an
    axis, lowest first (the first of equal values first), at most ``count``: the best node of each basin."""
    grid = values.reshape((per_axis,) * dim)
    lowest = np.ones(grid.shape, dtype=bool)
    for axis in range(dim):
        pad = [(1, 1) if a == axis else (0, 0) for a in range(dim)]
        padded = np.pad(grid, pad, constant_values=np.inf)
        below = np.take(padded, np.arange(per_axis), axis=axis)
        above = np.take(padded, np.arange(2, per_axis + 2), axis=axis)
        lowest &= (grid <= below) & (grid <= above)
    idx = np.flatnonzero(lowest.ravel())
    return idx[np.argsort(values[idx], kind="stable")][:count]


def closest_approach(surrogates: dict, domain: Domain, observables, targets: dict[str, float],
                     start: np.ndarray | None) -> tuple[float, np.ndarray]:
    """min over the domain of max_k |relative residual| (Nelder-Mead in unit coordinates from ``start``, actual
    units, or the best node of a small grid, and from the best nodes of the grid's other basins)."""
    from scipy import optimize

    obs = tuple(observables)

    def worst(u):
        return np.max(np.abs(relative_errors(surrogates, domain, obs, targets, u)), axis=0)

    nodes = start_nodes(domain)
    per_axis = int(round(len(nodes) ** (1.0 / domain.dim)))
    basins = nodes[basin_nodes(worst(nodes), per_axis, domain.dim, CLOSEST_STARTS)]
    starts = basins if start is None else np.vstack([domain.to_unit(start)[:1], basins[:CLOSEST_STARTS - 1]])
    best_value, best_point = np.inf, None
    for u0 in starts:
        res = optimize.minimize(lambda u: float(worst(u)[0]) + float(np.sum(np.abs(u - np.clip(u, 0, 1)))), u0,
                                method="Nelder-Mead", options={"xatol": 1e-10, "fatol": 1e-12, "maxfev": 2000})
        u = np.clip(res.x, 0.0, 1.0)
        value, point = float(worst(u)[0]), domain.from_unit(u)[0]
        start_value = float(worst(u0)[0])
        if start_value <= value:
            value, point = start_value, domain.from_unit(u0)[0]
        # another basin's lowest point replaces the first search's only when lower beyond round-off
        if best_point is None or value < best_value * (1 - 1e-9):
            best_value, best_point = value, point
    return best_value, best_point


def evaluate_set(surrogates: dict[str, Surrogate], domain: Domain, observables, targets: dict[str, float],
                 tolerance: float, n: int, predictions: pd.DataFrame | None = None, *,
                 grid: bool = False, reference: dict | None = None) -> AdmissibleSet:
    """The strict admissible set of ``observables`` at ``tolerance``: exact for polynomial
    surrogates in up to 3 factors, else on the n-per-axis grid (up to 3 factors) or n scrambled
    Sobol points.  ``predictions`` are the surrogates' values at those evaluation points when
    the caller already has them; ``grid`` asks for the node mask too (figures) when the set is
    exact.  ``reference`` (actual units) is passed to the exact set for its distance.  ``at_bound``
    of the result says, per factor, which ends of the search range the set's spans reach.
    """
    aset = _evaluate_set(surrogates, domain, observables, targets, tolerance, n, predictions, grid, reference)
    return replace(aset, at_bound=domain.at_bound(aset.lower, aset.upper))


def _evaluate_set(surrogates, domain, observables, targets, tolerance, n, predictions, grid, reference):
    observables = tuple(observables)
    if not uses_exact(surrogates, observables, domain):
        if uses_grid(domain.dim):
            return admissible_set(surrogates, domain, observables, targets, tolerance, n, grid_predictions=predictions)
        from .sobol import sobol_admissible_set  # scipy.stats: only above 3 factors

        return sobol_admissible_set(surrogates, domain, observables, targets, tolerance, n, predictions)
    exact = exact_set_on_domain(surrogates, domain, observables, targets, tolerance, reference)
    spans = exact.spans
    lower, upper = spans["lower"].to_numpy(dtype=float), spans["upper"].to_numpy(dtype=float)
    if grid and uses_grid(domain.dim):
        base = admissible_set(surrogates, domain, observables, targets, tolerance, n, grid_predictions=predictions)
    else:
        base = AdmissibleSet(observables=observables, tolerance=float(tolerance), factors=tuple(domain.factors),
                             fraction=np.nan, node_fraction=np.nan, n_nodes=0, n_admissible_nodes=0,
                             n_refined_cells=0, lower=lower, upper=upper, mask=np.zeros(0, dtype=bool))
    best_error, best_point = base.best_error, base.best_point
    if exact.fraction <= 0:
        # closest approach of an empty set (the grid node, polished by a local search)
        best_error, best_point = closest_approach(surrogates, domain, observables, targets,
                                                   best_point if len(best_point) else None)
        if np.isfinite(base.best_error) and base.best_error < best_error:
            best_error, best_point = base.best_error, base.best_point
    return replace(base, fraction=float(exact.fraction), fraction_error=float(exact.fraction_error),
                   lower=lower, upper=upper, best_error=float(best_error), best_point=np.asarray(best_point),
                   method=EXACT_METHOD, exact=exact)

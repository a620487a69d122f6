"""Where level 2 stands on the edge of what was searched or simulated.

Two things make a calibration answer less than it seems: the best point or the admissible
set sitting on a bound of the search range (the answer may lie beyond it: widen the range),
and search bounds or a reference point outside the region the design runs cover (the
surrogate's predictions there are extrapolated).  Touching a bound is
:meth:`~demid.sampling.domain.Domain.at_bound`, the same test as the identifiability
table's ``at_bound`` column.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
from scipy import optimize

from .models import short_number

if TYPE_CHECKING:
    from ..sampling.domain import Domain



def touching(at_bound) -> dict[str, tuple[str, ...]]:
    """{factor: sides} of an ``at_bound`` mapping (factor -> none/lower/upper/both), touching factors only."""
    from ..sampling.domain import SIDES_OF

    return {f: SIDES_OF[v] for f, v in at_bound.items() if SIDES_OF[v]}


def movable_sides(domain: Domain, touch: dict[str, tuple[str, ...]]) -> dict[str, tuple[str, ...]]:
    """``touch`` ({factor: sides}) without the sides at the factor's physical limit: the bounds a wider
    range could move."""
    from ..sampling.domain import sides_at_limit

    out = {}
    for f, sides in touch.items():
        i = domain.factors.index(f)
        fixed = sides_at_limit((domain.lower[i], domain.upper[i]), domain.limits[i])
        kept = tuple(s for s in sides if s not in fixed)
        if kept:
            out[f] = kept
    return out


def widen_advice(domain: Domain, best: dict[str, tuple[str, ...]], aset: dict[str, tuple[str, ...]]) -> list[str]:
    """"Widen the range of X" sentences: per factor whose best point or admissible set sits on a bound that is
    not its physical limit (up to the limit, where it has one)."""
    best, aset = movable_sides(domain, best), movable_sides(domain, aset)
    out = []
    for i, f in enumerate(domain.factors):
        best_sides, set_sides = best.get(f, ()), aset.get(f, ())
        sides = sorted(set(best_sides) | set(set_sides), key=("lower", "upper").index)
        if not sides:
            continue
        what = []
        if best_sides:
            what.append(f"the best point lies on its {' and '.join(best_sides)} bound, so a better match may lie "
                        f"outside the searched range")
        if set_sides:
            what.append(f"the admissible set reaches its {' and '.join(set_sides)} bound and may extend beyond it")
        limits = dict(zip(("lower", "upper"), domain.limits[i]))
        beyond = " and ".join(f"{'below' if s == 'lower' else 'above'} "
                              f"{short_number(domain.lower[i] if s == 'lower' else domain.upper[i])}"
                              + (f" ({'down' if s == 'lower' else 'up'} to its physical limit "
                                 f"{short_number(limits[s])})"
                                 if limits[s] is not None else "")
                              for s in sides)
        out.append(f"Widen the range of {f}: {'; '.join(what)}. Simulate runs {beyond} and search there.")
    return out


def extrapolation_warnings(domain: Domain, runs: np.ndarray | None, reference_point: dict | None) -> list[str]:
    """Search bounds beyond the runs' range of a factor, and a reference point outside the runs' region.

    ``runs`` are the design runs in actual units (rows, factor columns in ``domain`` order).  The
    region the runs cover is their range per factor and, for the reference point, their convex hull
    (in search units: log10 for log factors).  Every search range has a width (config refuses equal ends, and a
    log factor's ends of one log10).
    """
    if runs is None or not len(runs):
        return []
    lo, hi = domain.search_bounds()
    span = hi - lo
    z = (domain.to_search(np.asarray(runs, dtype=float)) - lo) / span
    z_lo, z_hi = z.min(axis=0), z.max(axis=0)
    tol = 1e-3
    out = []
    run_lo, run_hi = domain.to_actual(lo + z_lo * span)[0], domain.to_actual(lo + z_hi * span)[0]
    for i, f in enumerate(domain.factors):
        sides = [s for s, beyond in (("lower", z_lo[i] > tol), ("upper", z_hi[i] < 1 - tol)) if beyond]
        if sides:
            out.append(f"Extrapolation: the search range of {f}, {short_number(domain.lower[i])} to "
                       f"{short_number(domain.upper[i])}, "
                       f"reaches beyond the runs, which cover {short_number(run_lo[i])} to {short_number(run_hi[i])}; "
                       f"predictions beyond "
                       f"them are the quadratic's extrapolation, not backed by any simulation. Narrow the range to "
                       f"the runs, or simulate runs out to the {' and '.join(sides)} bound.")
    if reference_point:
        ref = np.array([[float(reference_point[f]) for f in domain.factors]])
        u = (domain.to_search(ref)[0] - lo) / span
        outside = [f"{f} = {short_number(float(reference_point[f]))} (runs: {short_number(run_lo[i])} to "
                   f"{short_number(run_hi[i])})"
                   for i, f in enumerate(domain.factors) if u[i] < z_lo[i] - tol or u[i] > z_hi[i] + tol]
        beyond = [f"{f} = {short_number(float(reference_point[f]))} (search range {short_number(domain.lower[i])} to "
                  f"{short_number(domain.upper[i])})"
                  for i, f in enumerate(domain.factors) if u[i] < -tol or u[i] > 1 + tol]
        if beyond:
            out.append(f"The reference point lies outside the search range ({'; '.join(beyond)}): no admissible set "
                       f"or Pareto front can contain it; check its value against the bounds.")
        if outside:
            out.append(f"Extrapolation: the reference point lies outside the range of the runs ({'; '.join(outside)}); "
                       f"its predicted values are extrapolated and its errors are not evidence about the simulation.")
        elif not in_hull(z, u, tol):
            out.append("Extrapolation: the reference point lies outside the region the design runs cover (their "
                       "convex hull), although within each factor's range; its predicted values are extrapolated.")
    return out


def in_hull(points: np.ndarray, u: np.ndarray, tol: float) -> bool:
    """True when u is within ``tol`` (per coordinate) of the convex hull of ``points`` (linear program)."""
    n, d = points.shape
    # lambda >= 0, sum lambda = 1, |points^T lambda - u| <= tol
    a_ub = np.vstack([points.T, -points.T])
    b_ub = np.concatenate([u + tol, -(u - tol)])
    res = optimize.linprog(np.zeros(n), A_ub=a_ub, b_ub=b_ub, A_eq=np.ones((1, n)), b_eq=[1.0],
                           bounds=[(0, None)] * n, method="highs")
    return bool(res.status == 0)

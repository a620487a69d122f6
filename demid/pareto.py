"""Pareto extraction for two minimised objectives (e.g. diameter error vs crack-shape index)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from .formulas import relative_error


def pareto_front(first: np.ndarray, second: np.ndarray) -> np.ndarray:
    """Indices of the non-dominated points when both objectives are minimised.

    A point is dominated when another is no worse in both objectives and
    strictly better in one.  Of exact duplicates only the first is kept.
    Returned in order of increasing ``first``.  O(n log n).
    """
    first = np.asarray(first, dtype=float)
    second = np.asarray(second, dtype=float)
    ok = np.isfinite(first) & np.isfinite(second)
    idx = _within_front_box(first, second, np.flatnonzero(ok))
    order = by_first_then_second(first, second, idx)
    s = second[order]
    running = np.minimum.accumulate(s)
    keep = np.empty(len(s), dtype=bool)
    if len(s):
        keep[0] = True
        keep[1:] = s[1:] < running[:-1]
    return order[keep]


def _within_front_box(first: np.ndarray, second: np.ndarray, idx: np.ndarray) -> np.ndarray:
    """The points of ``idx`` the front can contain, before sorting (on a dense grid most are not).

    The first point in sorted order (least ``first``, ties by ``second``, then index) is on the
    front, and every other front point has a smaller ``second``; a point with a larger ``first``
    than the least-``second`` point is dominated by it.  Dropping the rest changes neither which
    points :func:`pareto_front` keeps nor their order: none of them precedes a kept point with a
    smaller ``second`` than the first point's."""
    if len(idx) == 0:
        return idx
    f, s = first[idx], second[idx]
    tied = idx[f == f.min()]
    head = tied[np.lexsort((tied, second[tied]))[0]]
    inside = (s < second[head]) & (f <= f[s == s.min()].min())
    return idx[inside | (idx == head)]


def by_first_then_second(first: np.ndarray, second: np.ndarray, idx: np.ndarray) -> np.ndarray:
    """``idx[np.lexsort((second[idx], first[idx]))]``: sorted by ``first``, ties by ``second``, then
    by index.  A two-key lexsort of a dense grid (8 million points) costs five times one
    quicksort, and ties in the first objective are rare, so only the tied runs get the full sort."""
    order = idx[np.argsort(first[idx])]
    values = first[order]
    tied = np.concatenate([[False], values[1:] == values[:-1]])  # ties with the previous position
    if tied.any():
        group = np.cumsum(~tied)  # runs of equal first values, numbered in sorted order
        in_run = np.isin(group, group[tied])
        pos = np.flatnonzero(in_run)
        members = order[pos]
        order[pos] = members[np.lexsort((members, second[members], group[pos]))]
    return order


@dataclass
class ParetoResult:
    """Non-dominated grid points and the factor intervals over those with error below a cap."""

    factors: list[str]
    error_of: str
    minimise: str
    max_error: float
    front: pd.DataFrame
    intervals: pd.DataFrame

    def to_frame(self) -> pd.DataFrame:
        """One CSV: front rows (kind='front') followed by interval summary rows (kind='interval')."""
        front = self.front.copy()
        front.insert(0, "kind", "front")
        summ = self.intervals.copy()
        summ.insert(0, "kind", "interval")
        return pd.concat([front, summ], ignore_index=True)


def pareto_analysis(grid: pd.DataFrame, factors: list[str], error_of: str, target: float, minimise: str,
                    max_error: float) -> ParetoResult:
    """Relative error of ``error_of`` against ``target`` versus the predicted ``minimise`` response."""
    error = np.abs(relative_error(grid[error_of].to_numpy(), target))
    objective = grid[minimise].to_numpy()
    idx = pareto_front(error, objective)
    front = grid.iloc[idx][factors].reset_index(drop=True)
    front["error"] = error[idx]
    front["objective"] = objective[idx]
    return ParetoResult(list(factors), error_of, minimise, float(max_error), front,
                        front_intervals(front, factors, max_error))


def polish_front(surrogates: dict, domain, factors: list[str], error_of: str, target: float, minimise: str,
                 max_error: float, front: pd.DataFrame, levels: int = 21) -> pd.DataFrame:
    """Sampled front points refined by optimisation, for domains sampled by Sobol points.

    Above three factors a few ten thousand points leave a front of a handful of points far from the
    true one (a 4-factor front of 6 points, its intervals outside the optimum).  For error caps from 0 to
    ``max_error`` and on to the front's end (the error where the objective is least), and at each sampled
    point's own error below ``max_error``, the predicted ``minimise`` is minimised subject to the error staying
    under the cap (SLSQP from the best sampled point under it); the polished points join the sampled front,
    which is then recomputed.
    """
    from scipy import optimize

    if front.empty or target == 0:
        return front
    scale = abs(target)

    def predicted(name, u):
        return float(surrogates[name].predict(domain.from_unit(u))[0])

    sampled = domain.to_unit(front[factors].to_numpy(dtype=float))
    found = [front]
    own = front["error"].to_numpy()
    # the front ends where the objective is least: its error is the last cap; a sampled point's own error is
    # a cap too, so that it survives only where nothing better exists at its error
    lowest = optimize.minimize(lambda u: predicted(minimise, u), sampled[np.argmin(front["objective"].to_numpy())],
                               method="L-BFGS-B", bounds=[(0.0, 1.0)] * domain.dim)
    end = max(float(own.max()), abs(predicted(error_of, lowest.x) - target) / scale, max_error)
    beyond = np.linspace(max_error, end, levels)  # the rest of the front too
    for cap in np.unique(np.r_[np.linspace(0.0, max_error, levels)[1:], own[own < max_error], beyond]):
        under = front["error"].to_numpy() <= cap
        start = sampled[under][np.argmin(front["objective"].to_numpy()[under])] if under.any() else \
            sampled[np.argmin(front["error"].to_numpy())]
        limits = [{"type": "ineq", "fun": lambda u, c=cap: c * scale - (predicted(error_of, u) - target)},
                  {"type": "ineq", "fun": lambda u, c=cap: c * scale + (predicted(error_of, u) - target)}]
        res = optimize.minimize(lambda u: predicted(minimise, u), start, method="SLSQP", constraints=limits,
                                bounds=[(0.0, 1.0)] * domain.dim, options={"ftol": 1e-12, "maxiter": 200})
        u = np.clip(res.x, 0.0, 1.0)
        u[u < 1e-9], u[u > 1 - 1e-9] = 0.0, 1.0  # on the bound, not 3e-14 from it
        error = abs(predicted(error_of, u) - target) / scale
        if error <= cap * (1 + 1e-6):
            row = dict(zip(factors, domain.from_unit(u)[0]))
            row.update(error=error, objective=predicted(minimise, u))
            found.append(pd.DataFrame([row]))
    pool = pd.concat(found, ignore_index=True)
    # a point polished at a sampled point's own error reaches that error to within round-off: it dominates
    same_error = np.round(pool["error"].to_numpy() / max_error, 9)
    keep = pareto_front(same_error, pool["objective"].to_numpy())
    return pool.iloc[keep].reset_index(drop=True)


def front_intervals(front: pd.DataFrame, factors: list[str], max_error: float) -> pd.DataFrame:
    """Per factor, the range over front points with error below ``max_error``."""
    below = front[front["error"] < max_error]
    return pd.DataFrame([{"factor": f, "lower": below[f].min() if len(below) else np.nan,
                          "upper": below[f].max() if len(below) else np.nan, "n_points": int(len(below))}
                         for f in factors])

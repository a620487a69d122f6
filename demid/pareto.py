"""Pareto extraction for two minimised objectives (e.g. diameter error vs crack-shape index)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd


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
    order = _by_first_then_second(first, second, idx)
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


def _by_first_then_second(first: np.ndarray, second: np.ndarray, idx: np.ndarray) -> np.ndarray:
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
    error = np.abs(grid[error_of].to_numpy() - target) / abs(target)
    objective = grid[minimise].to_numpy()
    idx = pareto_front(error, objective)
    front = grid.iloc[idx][factors].reset_index(drop=True)
    front["error"] = error[idx]
    front["objective"] = objective[idx]
    below = front[front["error"] < max_error]
    rows = []
    for f in factors:
        vals = below[f]
        rows.append({"factor": f, "lower": vals.min() if len(vals) else np.nan,
                     "upper": vals.max() if len(vals) else np.nan, "n_points": int(len(vals))})
    return ParetoResult(list(factors), error_of, minimise, float(max_error), front, pd.DataFrame(rows))

"""The searches of level 2 (:func:`demid.criticism.level2.calibration_check`): the point of the domain that
minimises the largest weighted relative error (grid, then SLSQP), the same with a shared relative bias on all
targets, and the bottleneck observable whose removal lets the others be met, with the smallest bias it implies.
"""

from __future__ import annotations

import warnings

import numpy as np
from scipy import optimize

from ..formulas import relative_error


class Level2Problem:
    """Relative errors of all observables as a function of a point in unit-scaled search space.

    ``weights`` (ε/ε_k per observable) turn a relative error into the weighted one the searches minimise."""

    def __init__(self, surrogates, domain, targets, observables, weights=None):
        self.surrogates, self.domain = surrogates, domain
        self.observables = list(observables)
        self.targets = np.array([targets[o] for o in self.observables], dtype=float)
        self.weights = np.ones(len(self.observables)) if weights is None else np.asarray(weights, dtype=float)
        self.lo, self.hi = domain.search_bounds()

    def actual(self, s: np.ndarray) -> np.ndarray:
        return self.domain.to_actual(self.lo + np.atleast_2d(s) * (self.hi - self.lo))

    def values(self, s: np.ndarray) -> np.ndarray:
        x = self.actual(s)
        return np.stack([np.asarray(self.surrogates[o].predict(x), dtype=float) for o in self.observables])

    def errors(self, s: np.ndarray) -> np.ndarray:
        return relative_error(self.values(s), self.targets[:, None])


def spread_starts(order: np.ndarray, grid_s: np.ndarray, starts: int) -> list[int]:
    """Up to ``starts`` grid nodes in the ranking ``order``, each more than 0.1 (search units, largest coordinate)
    from those taken before it, so that the local searches start in different places."""
    picks = [order[0]]
    for i in order[1:]:
        if len(picks) >= starts:
            break
        if np.min(np.max(np.abs(grid_s[picks] - grid_s[i]), axis=1)) > 0.1:
            picks.append(i)
    return picks


def _worst(err: np.ndarray, weights: np.ndarray, shared: bool) -> np.ndarray:
    """Largest weighted |error| w_k |e_k| per column; with a shared bias, what is left after the best one
    (:func:`_shared_bias_envelope`)."""
    if not shared:
        return (weights[:, None] * np.abs(err)).max(axis=0)
    return _shared_bias_envelope(err, weights)[0]


def _shared_bias_envelope(err: np.ndarray, weights: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per column of ``err`` (observables x points), min over δ of max_k w_k |e_k - δ| and the δ attaining it,
    for one relative bias δ shared by every observable: the V-shaped terms of two observables i, j meet at
    height w_i w_j |e_i - e_j| / (w_i + w_j) where δ = (w_i e_i + w_j e_j) / (w_i + w_j), and the lowest point
    of their upper envelope is the highest of these pairwise meetings (half the spread when the weights are
    equal)."""
    value = np.zeros(err.shape[1])
    delta = err[0].astype(float)  # level 2 has at least one observable (calibration_check refuses none)
    for i in range(len(err)):
        for j in range(i + 1, len(err)):
            wi, wj = weights[i], weights[j]
            meet = wi * wj * np.abs(err[i] - err[j]) / (wi + wj)
            higher = meet > value
            value = np.where(higher, meet, value)
            delta = np.where(higher, (wi * err[i] + wj * err[j]) / (wi + wj), delta)
    return value, delta


def _shared_bias(e: np.ndarray, w: np.ndarray) -> tuple[float, float]:
    """(value, δ) of the shared bias at one point (:func:`_shared_bias_envelope`)."""
    value, delta = _shared_bias_envelope(np.asarray(e, dtype=float)[:, None], w)
    return float(value[0]), float(delta[0])


def minimax(problem: Level2Problem, grid_s: np.ndarray, grid_err: np.ndarray, rows: list[int],
             shared: bool = False, starts: int = 4) -> tuple[float, np.ndarray, float]:
    """min over the domain of the largest |relative error| of ``rows`` (+ optional shared bias).

    Grid search, then SLSQP on the epigraph form (min t s.t. |e_k(x) - delta| <= t)
    from the best few grid nodes.  Returns (value, unit point, delta).
    """
    weights = problem.weights[rows]
    worst = _worst(grid_err[rows], weights, shared)
    order = np.argsort(worst, kind="stable")
    picks = spread_starts(order, grid_s, starts)
    d = grid_s.shape[1]

    def evaluate(s):
        e = problem.errors(s)[rows, 0]
        if shared:
            return _shared_bias(e, weights)
        return float(np.max(weights * np.abs(e))), 0.0

    best_val, best_s = float(worst[order[0]]), grid_s[order[0]].copy()
    best_delta = evaluate(best_s)[1]
    for i in picks:
        v0, delta0 = evaluate(grid_s[i])
        x0 = np.concatenate([grid_s[i], [v0], [delta0] if shared else []])

        def cons(v):
            e = weights * (problem.errors(v[:d])[rows, 0] - (v[d + 1] if shared else 0.0))
            return np.concatenate([v[d] - e, v[d] + e])

        bounds = [(0.0, 1.0)] * d + [(0.0, None)] + ([(None, None)] if shared else [])
        with warnings.catch_warnings(), np.errstate(all="ignore"):
            warnings.simplefilter("ignore")
            res = optimize.minimize(lambda v: v[d], x0, method="SLSQP", bounds=bounds,
                                    constraints=[{"type": "ineq", "fun": cons}],
                                    options={"maxiter": 200, "ftol": 1e-12})
        s = np.clip(res.x[:d], 0.0, 1.0)
        val, delta = evaluate(s)
        if val < best_val:
            best_val, best_s, best_delta = val, s, delta
    return best_val, best_s, best_delta


#: Weight of the bias sought against the others' largest error in :func:`_smallest_bias`: the others are met
#: to within this fraction of the range the bias could take.
_BIAS_WEIGHT = 1e-5


def _smallest_bias(problem: Level2Problem, grid_s: np.ndarray, grid_err: np.ndarray, row: int,
                   others: list[int], starts: int = 4) -> float:
    """The relative error of observable ``row`` closest to zero among the points that meet the ``others``
    best.  With fewer other observables than parameters those points form a curve or a surface (or, where
    the others do not change, the whole domain), and the error at one arbitrary point of it is no bias the
    data imply; the smallest is.  Solved as min t + w u subject to |e_j| <= t (others), |e_row| <= u, with
    w = ``_BIAS_WEIGHT``: always feasible, so SLSQP needs no feasible start.
    """
    d = grid_s.shape[1]
    w = problem.weights[others]
    score = np.max(w[:, None] * np.abs(grid_err[others]), axis=0) + _BIAS_WEIGHT * np.abs(grid_err[row])
    order = np.argsort(score, kind="stable")
    picks = spread_starts(order, grid_s, starts)

    def cons(v):
        e = problem.errors(v[:d])[:, 0]
        return np.concatenate([v[d] - w * e[others], v[d] + w * e[others], [v[d + 1] - e[row], v[d + 1] + e[row]]])

    best_score, best_s = np.inf, grid_s[order[0]]
    for i in picks:
        e0 = problem.errors(grid_s[i])[:, 0]
        x0 = np.concatenate([grid_s[i], [np.max(w * np.abs(e0[others])), abs(e0[row])]])
        with warnings.catch_warnings(), np.errstate(all="ignore"):
            warnings.simplefilter("ignore")
            res = optimize.minimize(lambda v: v[d] + _BIAS_WEIGHT * v[d + 1], x0, method="SLSQP",
                                    bounds=[(0.0, 1.0)] * d + [(0.0, None), (0.0, None)],
                                    constraints=[{"type": "ineq", "fun": cons}],
                                    options={"maxiter": 300, "ftol": 1e-15})
        s = np.clip(res.x[:d], 0.0, 1.0)
        e = problem.errors(s)[:, 0]
        value = np.max(w * np.abs(e[others])) + _BIAS_WEIGHT * abs(e[row])
        if value < best_score:
            best_score, best_s = value, s
    return float(problem.errors(best_s)[row, 0])


def reference_point_errors(surrogates, targets, observables, factors, reference_point):
    """(values, relative errors) of the observables at the reference point, or (None, None)."""
    if reference_point is None:
        return None, None
    x_ref = np.array([[float(reference_point[f]) for f in factors]])
    vals = np.stack([np.asarray(surrogates[o].predict(x_ref), dtype=float) for o in observables])[:, 0]
    ref_values = dict(zip(observables, vals.tolist()))
    return ref_values, {o: relative_error(v, targets[o]) for o, v in ref_values.items()}


def bottleneck_analysis(problem: Level2Problem, grid_s, grid_err, tolerance: float, feasible: bool):
    """(without, implied, bottleneck, candidates, biased): per observable the smallest error left when it
    is dropped and the bias it would need; where no point meets every target, the observable whose
    target is the bottleneck, those whose bias alone would restore feasibility, and that one if unique."""
    observables = problem.observables
    every = list(range(len(observables)))
    without, implied = {}, {}
    if len(observables) > 1:
        for i, o in enumerate(observables):
            others = [j for j in every if j != i]
            val, _, _ = minimax(problem, grid_s, grid_err, others)
            without[o] = val
            # where every target is met within the tolerance, no observable needs a bias
            implied[o] = 0.0 if feasible else _smallest_bias(problem, grid_s, grid_err, i, others)
    if feasible:
        return without, implied, None, [], None
    # Smallest error left when the observable is dropped; near-ties (common when the rest is
    # exactly solvable) go to the observable needing the smallest bias.
    bottleneck = (min(without, key=lambda o: (round(without[o] / (1e-3 * tolerance)), abs(implied[o])))
                  if without else observables[0])
    candidates = [o for o in observables if without.get(o, np.inf) <= tolerance + 1e-12]
    return without, implied, bottleneck, candidates, candidates[0] if len(candidates) == 1 else None

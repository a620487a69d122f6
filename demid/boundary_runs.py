"""Runs where the set's boundary is decided: level-set (contour) placement over the whole search range.

A simulated material's waves analyse every run over the search range Omega, so the next wave's runs may go
anywhere in it.  They go where they decide the answer, the scenario's set:

* **boundary runs**: where the strict classification "every observable within its band" is most uncertain.
  Each observable's mean response at x is taken as normal around the surrogate's prediction ŷ with the
  surrogate's prediction standard error s (its ``se_prediction``: for a quadratic it carries the residual
  variance, the only sign of its misfit between the runs); the probability p(x) that x is in the set is the
  product over the observables of P(|y - y*| <= band), and the classification's error probability is
  min(p, 1 - p) (expected classification error, the level-set estimation criterion; the straddle heuristic
  is its linear cousin).  Chosen greedily in batch, each pick multiplied by a space-filling factor
  min(1, d / spacing) with d its distance to every earlier and already chosen run, so that one wave's runs
  spread along the boundary instead of piling up where it is most uncertain.
* **exploring runs** (a share :data:`EXPLORE_SHARE` of the design): where the classification would be
  uncertain if the surrogate's error were :data:`EXPLORE_INFLATION` times as large, times the distance to the
  nearest run (no cap): the least certain places of the surrogate that could still hold part of the set, so
  that a part of the set the first model missed can appear in a later wave.

Candidates are a grid over Omega (search units: log10 for log-scale factors).  Every quantity is asked of
the :class:`~demid.scenario.JudgedScenario` (its rescaled surrogates, targets and bands), and of the
surrogates only through ``predict`` and ``se_prediction``, so a surrogate other than the
quadratic with the same interface places runs the same way.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from .scenario import JudgedScenario

#: The share of a wave's design runs that explores where the surrogate is least certain over Omega.
EXPLORE_SHARE = 1 / 4
#: The exploring runs take the surrogate's error this many times as large: they go where the set could still be if
#: the surrogate were that far off (a quadratic that misfits is, between its runs), the farthest from every run.
#: On the benchmark (benchmarks/loop_vs_lhs.py, 4 seeds) 3 beat the standard error of the mean over the band as
#: the exploring score (which sends a quadratic's exploring runs to the corners): loop/LHS 0.78 against 0.84.
EXPLORE_INFLATION = 3.0
#: Runs closer than this many times the spacing of a space-filling design of all the runs (earlier and new) are
#: penalised in proportion to their distance: half the spacing lets boundary runs sit closer than a uniform
#: design would, but not on top of each other.
SPACING_FACTOR = 0.5
#: Candidate grid: points per factor for one or two factors; above, about this many points in all.
GRID_POINTS_2D = 41
GRID_POINTS_ALL = 4096
#: Scores below this share of the largest count as nil, and distance alone breaks ties between them.
NIL_SCORE = 1e-6
TIE_BREAK = 1e-12


def omega_candidates(judged: JudgedScenario) -> np.ndarray:
    """The candidate grid over Omega in search units."""
    lo, hi = judged.spec.domain.search_bounds()
    k = len(lo)
    n = GRID_POINTS_2D if k <= 2 else max(5, int(round(GRID_POINTS_ALL ** (1 / k))))
    axes = [np.linspace(a, b, n) for a, b in zip(lo, hi)]
    return np.column_stack([g.ravel() for g in np.meshgrid(*axes, indexing="ij")])


def _normal_cdf(x: np.ndarray) -> np.ndarray:
    from scipy.special import ndtr

    return ndtr(x)


def set_probability(judged: JudgedScenario, points: np.ndarray, inflation: float = 1.0) -> np.ndarray:
    """P(x in the strict set) at ``points`` (actual units): per observable P(|y - y*| <= band) with y normal
    around the surrogate's prediction, sd ``inflation`` times its prediction standard error; the product over the
    observables."""
    p = np.ones(len(points))
    for o in judged.observables:
        surrogate, target = judged.surrogates[o], judged.targets[o]
        band = judged.tolerance * abs(target)
        mean = surrogate.predict(points)
        sd = inflation * np.maximum(surrogate.se_prediction(points), 1e-12 * max(band, 1e-300))
        p *= _normal_cdf((target + band - mean) / sd) - _normal_cdf((target - band - mean) / sd)
    return p


def classification_error(judged: JudgedScenario, points: np.ndarray, inflation: float = 1.0) -> np.ndarray:
    """The probability that the strict classification at ``points`` (actual units) is wrong, min(p, 1 - p), with
    the surrogate's error taken ``inflation`` times as large."""
    p = set_probability(judged, points, inflation)
    return np.minimum(p, 1.0 - p)


def _unit(judged: JudgedScenario, u: np.ndarray) -> np.ndarray:
    lo, hi = judged.spec.domain.search_bounds()
    return (np.asarray(u, dtype=float) - lo) / (hi - lo)


def spacing(n_runs: int, k: int) -> float:
    """The distance (Omega scaled to the unit cube) below which two runs are penalised: SPACING_FACTOR times
    the spacing of a space-filling design of ``n_runs`` runs in ``k`` factors."""
    return SPACING_FACTOR * max(n_runs, 1) ** (-1.0 / k)


def greedy_batch(score: np.ndarray, candidates: np.ndarray, existing: np.ndarray, count: int,
                 length: float | None) -> list[int]:
    """``count`` candidate indices (unit-cube points), each the largest ``score`` times a space-filling factor:
    min(1, d / length), or d itself when ``length`` is None, d the distance to the nearest existing or chosen
    point.  Ties go to the earlier candidate (the grid's order), so the choice is deterministic."""
    dist = (np.min(np.linalg.norm(candidates[:, None, :] - existing[None, :, :], axis=2), axis=1)
            if len(existing) else np.full(len(candidates), np.sqrt(candidates.shape[1])))
    # a floor keeps the space-filling factor deciding where the score is nil everywhere (no point near the
    # set's boundary): the picks then spread out instead of following the grid's order
    score = np.asarray(score, dtype=float) + NIL_SCORE * max(float(np.max(score, initial=0.0)), 1e-300) + 1e-300
    chosen = []
    for _ in range(count):
        factor = dist if length is None else np.minimum(1.0, dist / length)
        value = score * factor + TIE_BREAK * dist
        # the same choice whatever the last bits of the arithmetic; every candidate already a run (one factor's
        # 41 nodes, a large count): all values 0, a tie, so the earliest candidate not chosen yet
        value = np.round(value / max(value.max(), 1e-300), 9)
        if chosen:
            value[chosen] = -np.inf
        best = int(np.argmax(value))
        chosen.append(best)
        dist = np.minimum(dist, np.linalg.norm(candidates - candidates[best], axis=1))
    return chosen


def boundary_runs(judged: JudgedScenario, earlier_u: np.ndarray, count: int,
                  explore: int | None = None) -> tuple[np.ndarray, list[str]]:
    """``count`` runs (search units) over Omega and their kinds (``boundary`` or ``explore``), given the earlier
    runs ``earlier_u`` (search units); ``explore`` of them (default a share :data:`EXPLORE_SHARE`) explore."""
    domain = judged.spec.domain
    cand_u = omega_candidates(judged)
    cand_x = domain.to_actual(cand_u)
    cand = _unit(judged, cand_u)
    existing = _unit(judged, np.asarray(earlier_u, dtype=float).reshape(-1, cand.shape[1]))
    n_explore = int(round(EXPLORE_SHARE * count)) if explore is None else min(int(explore), count)
    length = spacing(len(existing) + count, cand.shape[1])
    picked = greedy_batch(classification_error(judged, cand_x), cand, existing, count - n_explore, length)
    existing = np.vstack([existing, cand[picked]])
    picked += greedy_batch(classification_error(judged, cand_x, EXPLORE_INFLATION), cand, existing, n_explore,
                           None)
    return cand_u[picked].reshape(-1, cand.shape[1]), ["boundary"] * (count - n_explore) + ["explore"] * n_explore

"""The boundary runs' every output against computations written here, over generated scenarios: 1-3 factors (some
on a log scale, ranges away from the origin), 1-3 observables with targets of either sign, tolerances, standard
errors down to zero, inflations; the set probability (scipy's normal), the classification error, the candidate grid
over Omega, the spacing, and a wave's runs and kinds (each pick by the documented greedy rule written out, the
boundary runs scored by the classification error, the exploring runs by the inflated one times the distance);
near-ties within the ninth decimal go to the earlier candidate."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.stats import norm

from demid.boundary_runs import (boundary_runs, classification_error, greedy_batch, omega_candidates,
                                 set_probability, spacing)
from demid.sampling import Domain

_FAST = settings(max_examples=15, deadline=None, derandomize=True)


class _Plane:
    """A stand-in surrogate: a plane in the search units with a standard error growing from a point (zero there)."""

    def __init__(self, domain, coef, offset, se_scale, centre):
        self.domain, self.coef, self.offset, self.se_scale, self.centre = domain, coef, offset, se_scale, centre

    def _u(self, points):
        return self.domain.to_search(np.asarray(points, dtype=float))

    def predict(self, points):
        return self.offset + self._u(points) @ self.coef

    def se_prediction(self, points):
        return self.se_scale * np.sum((self._u(points) - self.centre) ** 2, axis=1)


def _judged(k, observables, seed, log_mask, tolerance):
    rng = np.random.default_rng(seed)
    lower = rng.uniform(-2.0, 2.0, k)
    upper = lower + rng.uniform(0.5, 3.0, k)
    log = tuple(bool(log_mask >> i & 1) for i in range(k))
    factors = tuple(f"f{i}" for i in range(k))
    actual_lo = [10 ** a if lg else a for a, lg in zip(lower, log)]
    actual_hi = [10 ** b if lg else b for b, lg in zip(upper, log)]
    domain = Domain(factors, tuple(actual_lo), tuple(actual_hi), log)
    names = [f"y{i}" for i in range(observables)]
    targets, surrogates = {}, {}
    for name in names:
        target = float(rng.choice([-1.0, 1.0]) * rng.uniform(1.0, 50.0))
        coef = rng.normal(0.0, abs(target) * tolerance * 3, k)
        centre = lower + rng.random(k) * (upper - lower)
        # the plane meets the target near the centre of the range, so the band crosses the grid
        offset = target - float((lower + upper) / 2 @ coef)
        surrogates[name] = _Plane(domain, coef, offset, abs(target) * tolerance * rng.uniform(0.05, 1.0), centre)
        targets[name] = target
    return SimpleNamespace(spec=SimpleNamespace(domain=domain), observables=names, targets=targets,
                           surrogates=surrogates, tolerance=tolerance), rng


def _probability(judged, points, inflation):
    p = np.ones(len(points))
    for o in judged.observables:
        s, t = judged.surrogates[o], judged.targets[o]
        band = judged.tolerance * abs(t)
        sd = inflation * np.maximum(s.se_prediction(points), 1e-12 * band)
        p = p * (norm.cdf((t + band - s.predict(points)) / sd) - norm.cdf((t - band - s.predict(points)) / sd))
    return p


_SCENARIOS = dict(k=st.integers(1, 3), observables=st.integers(1, 3), seed=st.integers(0, 10_000),
                  log_mask=st.integers(0, 7), tolerance=st.sampled_from([0.01, 0.05, 0.2]))


@_FAST
@given(**_SCENARIOS, inflation=st.sampled_from([1.0, 3.0, 0.5]))
def test_set_probability_and_classification_error_are_the_normal_masses_inside_every_band(k, observables, seed,
                                                                                         log_mask, tolerance,
                                                                                         inflation):
    judged, rng = _judged(k, observables, seed, log_mask, tolerance)
    lo, hi = judged.spec.domain.search_bounds()
    u = lo + rng.random((25, k)) * (hi - lo)
    u[0] = judged.surrogates[judged.observables[0]].centre  # a point with no error: the floor decides
    points = judged.spec.domain.to_actual(u)
    expected = _probability(judged, points, inflation)
    assert set_probability(judged, points, inflation) == pytest.approx(expected, rel=1e-9, abs=1e-12)
    assert classification_error(judged, points, inflation) == pytest.approx(np.minimum(expected, 1 - expected),
                                                                            rel=1e-9, abs=1e-12)
    assert set_probability(judged, points) == pytest.approx(_probability(judged, points, 1.0), rel=1e-9, abs=1e-12)


@pytest.mark.parametrize("k, per_axis", [(1, 41), (2, 41), (3, 16), (4, 8), (5, 5), (6, 5), (7, 5)])
def test_the_candidate_grid_spans_the_search_range_at_its_documented_size(k, per_axis):
    lower = tuple(float(v) for v in np.linspace(-1.0, 2.0, k))
    upper = tuple(v + 1.5 for v in lower)
    log = tuple(i % 2 == 1 for i in range(k))
    domain = Domain(tuple(f"f{i}" for i in range(k)), tuple(10 ** a if lg else a for a, lg in zip(lower, log)),
                    tuple(10 ** b if lg else b for b, lg in zip(upper, log)), log)
    grid = omega_candidates(SimpleNamespace(spec=SimpleNamespace(domain=domain)))
    assert grid.shape == (per_axis ** k, k)
    for i in range(k):
        assert np.unique(grid[:, i]) == pytest.approx(np.linspace(lower[i], upper[i], per_axis), rel=1e-12)


@pytest.mark.parametrize("n, k", [(0, 1), (1, 2), (9, 2), (20, 3), (100, 4)])
def test_spacing_is_half_the_spacing_of_a_space_filling_design(n, k):
    assert spacing(n, k) == pytest.approx(0.5 * max(n, 1) ** (-1 / k), rel=1e-12)


def _greedy(score, cand, existing, count, length):
    """The documented rule, pick by pick: the largest (score + a nil floor) x space-filling factor + a tie break
    by distance, values compared to nine decimals of the largest, ties to the earlier candidate."""
    score = score + 1e-6 * max(score.max(), 1e-300) + 1e-300
    chosen = []
    for _ in range(count):
        pts = list(existing) + [cand[c] for c in chosen]
        dist = np.array([min((np.linalg.norm(c - p) for p in pts), default=np.sqrt(cand.shape[1])) for c in cand])
        factor = dist if length is None else np.minimum(1.0, dist / length)
        value = score * factor + 1e-12 * dist
        value = np.round(value / value.max(), 9)
        value[chosen] = -np.inf
        chosen.append(int(np.flatnonzero(value == value.max())[0]))
    return chosen


@settings(max_examples=8, deadline=None, derandomize=True)
@given(k=st.integers(1, 2), observables=st.integers(1, 2), seed=st.integers(0, 10_000), log_mask=st.integers(0, 3),
       tolerance=st.sampled_from([0.02, 0.1]), earlier=st.integers(0, 4), count=st.integers(1, 6),
       explore=st.sampled_from([None, 0, 1, 9]))
def test_a_waves_runs_are_the_greedy_picks_of_each_score_and_their_kinds_are_counted(k, observables, seed, log_mask,
                                                                                    tolerance, earlier, count,
                                                                                    explore):
    judged, rng = _judged(k, observables, seed, log_mask, tolerance)
    domain = judged.spec.domain
    lo, hi = domain.search_bounds()
    earlier_u = lo + rng.random((earlier, k)) * (hi - lo)
    runs, kinds = boundary_runs(judged, earlier_u, count, explore)
    n_explore = int(round(count / 4)) if explore is None else min(explore, count)
    assert kinds == ["boundary"] * (count - n_explore) + ["explore"] * n_explore
    axes = [np.linspace(a, b, 41) for a, b in zip(lo, hi)]
    cand_u = np.column_stack([g.ravel() for g in np.meshgrid(*axes, indexing="ij")])
    cand = (cand_u - lo) / (hi - lo)
    cand_x = domain.to_actual(cand_u)
    existing = (earlier_u - lo) / (hi - lo)
    p = _probability(judged, cand_x, 1.0)
    boundary = _greedy(np.minimum(p, 1 - p), cand, existing, count - n_explore,
                       0.5 * (earlier + count) ** (-1 / k))
    p3 = _probability(judged, cand_x, 3.0)
    explore_picks = _greedy(np.minimum(p3, 1 - p3), cand, np.vstack([existing, cand[boundary]]), n_explore, None)
    assert runs.shape == (count, k)
    assert runs == pytest.approx(cand_u[boundary + explore_picks], rel=1e-12, abs=1e-12)


def test_scores_equal_to_the_ninth_decimal_tie_and_go_to_the_earlier_candidate():
    """The same choice whatever the last bits of the arithmetic: scores that differ in the tenth decimal are a tie
    (the earlier candidate), in the ninth or the eighth they are not."""
    cand = np.array([[0.2, 0.5], [0.8, 0.5], [0.5, 0.9]])
    for gap, pick in ((3e-10, 0), (3e-9, 1), (3e-8, 1)):
        score = np.array([0.4, 0.4 * (1 + gap), 0.1])
        assert greedy_batch(score, cand, np.empty((0, 2)), 1, 0.1) == [pick]


def test_once_every_candidate_holds_a_run_the_picks_go_to_the_earliest_not_yet_chosen():
    """More runs than candidates: once every candidate holds a run, every value is 0, a tie, and each further pick
    is the earliest candidate the batch has not chosen yet (no division by a zero largest value)."""
    cand = np.linspace(0.0, 1.0, 5)[:, None]
    # nodes 0, 2 and 4 are 0.25 from the runs at nodes 1 and 3 (factor 1 at length 0.2): a tie, in grid order
    assert greedy_batch(np.full(5, 0.3), cand, cand[[1, 3]], 5, 0.2) == [0, 2, 4, 1, 3]
    assert greedy_batch(np.full(5, 0.3), cand, cand[[1, 3]], 5, None) == [0, 2, 4, 1, 3]
    # one factor's wave of 50 runs over its 41 nodes: every node once, then the exploring runs' earliest others
    judged, rng = _judged(1, 1, 3, 0, 0.1)
    lo, hi = judged.spec.domain.search_bounds()
    nodes = np.linspace(lo[0], hi[0], 41)
    runs, kinds = boundary_runs(judged, lo + rng.random((3, 1)) * (hi - lo), 50)
    assert kinds == ["boundary"] * 38 + ["explore"] * 12
    index = [int(np.argmin(np.abs(nodes - r))) for r in runs[:, 0]]
    assert runs[:, 0] == pytest.approx(nodes[index], rel=1e-12, abs=1e-12)
    assert sorted(index[:41]) == list(range(41))
    assert index[41:] == [i for i in range(41) if i not in index[38:41]][:9]

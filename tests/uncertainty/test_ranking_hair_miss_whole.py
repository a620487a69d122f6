"""The observable ranking when one target is missed by a hair: a set holding a target that no point of the domain
meets within the tolerance is out of reach, even when the other targets of the set are met at the very point of
that target's closest approach (where a search over the whole set, with its own round-off slack, could take the
set for met).  Lines y = c + d a on [0, 1] give every band an interval in closed form: the reachable sets, their
fractions, their best subsets, contractions, gains and the order are recomputed from those intervals, over 1-3
reached observables, both ends of the range and both signs of the targets."""

from __future__ import annotations

from itertools import combinations

import numpy as np
import pytest

from demid.sampling.domain import Domain
from demid.spec import join_observables
from demid.surrogate import Surrogate
from demid.uncertainty.posterior import NO_OBSERVABLE
from demid.uncertainty.ranking import rank_observable_sets

from .test_ranking_whole import _Posterior

LINE = Domain(("a",), (0.0,), (1.0,))
TOLERANCE = 0.1
N = 401  # grid nodes: a fraction is an interval's length to within a few steps


def _line(name: str, c: float, d: float) -> Surrogate:
    return Surrogate(name, ["a"], [(0,), (1,)], np.array([c, d]), np.eye(2) * 1e-6, 0.01, 5)


def _band(c: float, d: float, t: float) -> tuple[float, float]:
    """The a of [0, 1] with |c + d a - t| <= TOLERANCE |t| (empty: lo > hi)."""
    ends = sorted(((t - TOLERANCE * abs(t) - c) / d, (t + TOLERANCE * abs(t) - c) / d))
    return max(ends[0], 0.0), min(ends[1], 1.0)


def _case(seed: int, k: int, end: int, sign: float):
    """k lines whose bands hold the end ``end`` of [0, 1], and 'miss' whose closest approach, at that end, is the
    tolerance times (1 + 5e-7): out of reach by the documented slack of 1e-9, inside a 1e-6 one."""
    rng = np.random.default_rng(seed)
    lines, targets = {}, {}
    for i in range(k):
        c, d = sign * rng.uniform(8, 12), rng.choice([-1.0, 1.0]) * rng.uniform(1, 4)
        at = end + (1 - 2 * end) * rng.uniform(0.0, 0.05)  # met near the end
        lines[f"y{i}"] = (c, d)
        targets[f"y{i}"] = c + d * at
    c, d = sign * rng.uniform(8, 12), rng.choice([-1.0, 1.0]) * rng.uniform(1, 4)
    value = c + d * end  # the line's value at the end; the farther-off side of the line's range lies beyond it
    beyond = 1.0 if (d > 0) == (end == 1) else -1.0  # moving the target past the end's value, away from the range
    # |value - t| = TOLERANCE (1 + e) |t| with t = value + beyond * TOLERANCE (1 + e) |t|; t keeps value's sign
    e = 5e-7
    s = np.sign(value)
    t = value / (1 - beyond * s * TOLERANCE * (1 + e))
    lines["miss"] = (c, d)
    targets["miss"] = float(t)
    assert abs(value - t) / abs(t) == pytest.approx(TOLERANCE * (1 + e), rel=1e-12)
    return lines, targets


@pytest.mark.parametrize("seed, k, end, sign", [(0, 1, 1, 1.0), (1, 2, 0, -1.0), (2, 3, 1, -1.0), (3, 2, 1, 1.0)])
def test_a_set_holding_a_target_missed_by_a_hair_is_out_of_reach(seed, k, end, sign):
    lines, targets = _case(seed, k, end, sign)
    names = list(lines)
    surrogates = {o: _line(o, *lines[o]) for o in names}
    subsets = [s for size in range(1, len(names) + 1) for s in combinations(names, size)]
    rng = np.random.default_rng(100 + seed)
    gains = {s: float(rng.uniform(0.5, 3.0)) for s in subsets}
    posteriors = {s: _Posterior(gains[s], 0.01) for s in subsets}
    frame = rank_observable_sets(surrogates, LINE, names, targets, {o: 1.0 for o in names}, TOLERANCE, N,
                                 posteriors=posteriors)

    # independent: a set's admissible a is the intersection of its members' bands
    bands = {o: _band(*lines[o], targets[o]) for o in names}
    length = {(): 1.0}
    for s in subsets:
        lo, hi = max(bands[o][0] for o in s), min(bands[o][1] for o in s)
        length[s] = max(hi - lo, 0.0)
    reach = {s: "miss" not in s for s in subsets}  # every other band holds the end, so they meet there
    assert length[("miss",)] == 0.0 and all(length[s] > 0.01 for s in subsets if reach[s])

    by_name = {join_observables(s): s for s in subsets}
    assert sorted(frame["observables"]) == sorted(by_name)
    frac = {(): 1.0, **{by_name[r.observables]: r.feasible_fraction_pct / 100 for r in frame.itertuples()}}
    gain = {(): 0.0, **{s: gains[s] if reach[s] else np.nan for s in subsets}}
    for r in frame.itertuples():
        s = by_name[r.observables]
        assert r.feasible_fraction_pct / 100 == pytest.approx(length[s], abs=3.0 / (N - 1))
        assert bool(r.targets_reachable) == reach[s], r.observables
        assert r.n_observables == len(s) and r.tolerance == TOLERANCE
        if reach[s]:
            assert r.information_gain_bits == gains[s]
            assert r.information_gain_error_bits == 0.01
        else:
            assert np.isnan(r.information_gain_bits) and np.isnan(r.information_gain_error_bits)
        proper = [t for size in range(len(s)) for t in combinations(s, size)]
        best = min(proper, key=lambda t: (frac[t], -gain[t]))
        assert r.best_subset == (join_observables(best) or NO_OBSERVABLE)
        expected_gain = gain[s] - gain[best]
        assert (np.isnan(r.gain_vs_best_subset_bits) if np.isnan(expected_gain)
                else r.gain_vs_best_subset_bits == pytest.approx(expected_gain, abs=1e-12))
    # reached sets first by gain down; out of reach last; the rank by fraction puts them last too
    reached = frame[frame["targets_reachable"]]
    assert list(reached["observables"]) == [join_observables(s) for s in
                                            sorted((s for s in subsets if reach[s]), key=lambda s: -gains[s])]
    assert not frame["targets_reachable"].iloc[len(reached):].any()
    assert list(frame["rank"]) == list(range(1, len(frame) + 1))
    out = ~frame["targets_reachable"]
    reached_fractions = reached["feasible_fraction_pct"].to_numpy()
    for r in frame.itertuples():
        expected = (1 + int(np.sum(reached_fractions < r.feasible_fraction_pct)) if r.targets_reachable
                    else len(reached) + 1)
        assert r.rank_by_fraction == expected
    assert out.sum() == sum(1 for s in subsets if not reach[s])

"""The observable ranking where proper subsets leave the same fraction: observables whose tolerance band covers the
whole square (each alone leaves 100 %, as the prior does) next to one that narrows it.  The gain over the best
subset is then taken over the most informative of the equally narrow subsets, never over the prior when a measured
subset is as narrow, so 'it adds N bits' does not count bits another measurement already gave.  Every column is
recomputed by brute force over the subsets, over 1-2 wide observables, target signs and gains."""

from __future__ import annotations

from itertools import combinations

import numpy as np
import pytest

from demid.spec import join_observables
from demid.uncertainty.posterior import NO_OBSERVABLE
from demid.uncertainty.ranking import rank_observable_sets

from .test_ranking_whole import SQUARE, _plane, _Posterior

TOLERANCE = 0.1


def _study(seed: int, wide: int, sign: float):
    rng = np.random.default_rng(seed)
    surrogates, targets, full = {}, {}, {}
    for i in range(wide):  # y = c0 (1 + small slopes): |y - t| <= 0.1 |t| over the whole square
        c0 = sign * rng.uniform(5, 20)
        c = [c0, 0.02 * c0 * rng.uniform(-1, 1), 0.02 * c0 * rng.uniform(-1, 1)]
        surrogates[f"w{i}"], targets[f"w{i}"], full[f"w{i}"] = _plane(f"w{i}", c), c0, True
    c = [sign * rng.uniform(8, 12), rng.uniform(3, 6), rng.uniform(-6, -3)]
    surrogates["n"], targets["n"], full["n"] = _plane("n", c), c[0] + 0.5 * c[1] + 0.5 * c[2], False
    return surrogates, targets, full


@pytest.mark.parametrize("seed, wide, sign", [(0, 1, 1.0), (1, 2, -1.0), (2, 2, 1.0)])
def test_the_gain_over_equally_narrow_subsets_is_over_the_most_informative(seed, wide, sign):
    surrogates, targets, full = _study(seed, wide, sign)
    names = list(surrogates)
    subsets = [s for size in range(1, len(names) + 1) for s in combinations(names, size)]
    rng = np.random.default_rng(50 + seed)
    gains = {s: float(rng.uniform(0.2, 3.0)) for s in subsets}
    posteriors = {s: _Posterior(gains[s], 0.02) for s in subsets}
    frame = rank_observable_sets(surrogates, SQUARE, names, targets, {o: 1.0 for o in names}, TOLERANCE, 41,
                                 posteriors=posteriors)

    by_name = {join_observables(s): s for s in subsets}
    rows = {by_name[r.observables]: r for r in frame.itertuples()}
    frac = {(): 1.0, **{s: rows[s].feasible_fraction_pct / 100 for s in subsets}}
    # independent: a set of wide observables only leaves the whole square; any set with n leaves n's band
    for s in subsets:
        if all(full[o] for o in s):
            assert frac[s] == 1.0
        else:
            assert 0.02 < frac[s] < 0.9 and frac[s] == frac[("n",)]
    gain = {(): 0.0, **gains}
    for s in subsets:
        r = rows[s]
        proper = [t for size in range(len(s)) for t in combinations(s, size)]
        narrowest = min(frac[t] for t in proper)
        tied = [t for t in proper if frac[t] == narrowest]
        best = max(tied, key=lambda t: gain[t])  # gains are distinct: one most informative subset
        assert r.best_subset == (join_observables(best) or NO_OBSERVABLE), r.observables
        assert r.gain_vs_best_subset_bits == pytest.approx(gain[s] - gain[best], abs=1e-12)
        assert r.contraction_pct_vs_best_subset == pytest.approx(100 * (1 - frac[s] / narrowest), abs=1e-9)
        assert r.targets_reachable and r.information_gain_bits == gains[s] and r.n_observables == len(s)
    # a set of two wide observables ties its two halves and the prior: the better half is named
    if wide == 2:
        pair = ("w0", "w1")
        half = max([("w0",), ("w1",)], key=lambda t: gains[t])
        assert rows[pair].best_subset == join_observables(half)
    # order: gain down; ranks by fraction: the narrow sets share the first rank
    assert list(frame["observables"]) == [join_observables(s) for s in sorted(subsets, key=lambda s: -gains[s])]
    narrow = [s for s in subsets if not all(full[o] for o in s)]
    for s in subsets:
        assert rows[s].rank_by_fraction == (1 if s in narrow else len(narrow) + 1)

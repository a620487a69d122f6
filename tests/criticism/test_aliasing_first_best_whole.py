"""The separating run a scan keeps (criticism.aliasing._first_best) against the rule its documentation states,
written out here over generated ranks and log pseudo-determinants: none unless a candidate raises the rank; else
the first of the highest rank, replaced only by one of that rank more than _TIE above the one kept so far.  A
candidate exactly _TIE above (to the last bit) does not replace it: a tie goes to the first in candidate order."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.criticism.aliasing import _TIE, _first_best


def _rule(ranks: np.ndarray, logdets: np.ndarray, rank: int):
    top = max(ranks)
    if top <= rank:
        return None
    kept = None
    for i in range(len(ranks)):
        if ranks[i] == top and (kept is None or logdets[i] - logdets[kept] > _TIE):
            kept = i
    return kept


@given(seed=st.integers(0, 10 ** 5), n=st.integers(1, 49), rank=st.integers(0, 3))
@settings(max_examples=60, deadline=None, derandomize=True)
def test_the_kept_candidate_follows_the_documented_scan(seed, n, rank):
    rng = np.random.default_rng(seed)
    ranks = rng.integers(0, 5, n)
    logdets = np.round(rng.normal(size=n), 1) + rng.choice([0.0, _TIE, 2 * _TIE], n)
    assert _first_best(ranks, logdets, rank) == _rule(ranks, logdets, rank)


def test_a_candidate_exactly_tie_above_the_kept_one_does_not_replace_it():
    first = 1.5
    edge = first + _TIE
    ranks = np.array([1, 2, 2, 2])
    assert _first_best(ranks, np.array([9.0, first, edge, edge]), 0) == 1
    assert _first_best(ranks, np.array([9.0, first, np.nextafter(edge, np.inf), edge]), 0) == 2
    assert _first_best(ranks, np.array([9.0, first, edge, edge]), 2) is None  # no candidate raises the rank
    assert _first_best(ranks, np.array([9.0, first, edge, edge]), 1) == 1

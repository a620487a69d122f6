"""Which causes the runs do not tell apart, against the rules written out in the test over generated candidate
lists (1-7 entries of one-run, step, term, scatter and drift kinds, AICc on a quarter grid so that a gap equal
to the margin occurs, some missing or infinite): one best entry per kind within the margin of the anchor (the
best entry, or the named one), the confirming rivals, the scatter covariates fitted nearly as well."""
from __future__ import annotations

import math

import pytest
from hypothesis import given, settings, strategies as st

from demid.criticism.discrimination import AMBIGUOUS_AICC, CONFIRM_AICC, candidate_kind, close_candidates
from demid.criticism.naming import _nearly_as_good, confirming_rivals

POOL = [("outlier", "4"), ("factor_level", "4"), ("outlier", "7"), ("step", "9"), ("step", "12"),
        ("missing_term", "a^3"), ("missing_term", "b^3"), ("heteroscedasticity", "a"), ("drift", "run"),
        ("response_transform", "boxcox")]


def _kind(e):
    if e["cause"] in ("outlier", "factor_level"):
        return "run " + e["detail"]
    return "step " + e["detail"] if e["cause"] == "step" else e["cause"]


def _close_by_rule(entries, named, margin):
    valid = [e for e in entries if e.get("aicc") is not None and math.isfinite(e["aicc"])]
    if not valid:
        return []
    ordered = sorted(valid, key=lambda e: e["aicc"])
    if named is None:
        anchor = ordered[0]
    else:
        matches = [e for e in ordered if (e["cause"], e["detail"]) == named]
        if not matches:
            return []
        anchor = matches[0]
    best = {}
    for e in ordered:
        best.setdefault(_kind(e), e)
    best[_kind(anchor)] = anchor
    return [e for e in best.values() if e is anchor or e["aicc"] - anchor["aicc"] <= margin]


def _key(e):
    return (e["aicc"], e["cause"], e["detail"])


entries_strategy = st.lists(st.tuples(st.integers(0, len(POOL) - 1),
                                      st.one_of(st.integers(0, 60).map(lambda q: 100.0 + q / 4),
                                                st.sampled_from([None, math.inf]))),
                            min_size=1, max_size=7)


@settings(max_examples=60, deadline=None, derandomize=True)
@given(raw=entries_strategy, named_pick=st.one_of(st.none(), st.integers(0, 6)),
       margin=st.sampled_from([None, 2.5, CONFIRM_AICC, math.inf]))
def test_close_candidates_are_the_best_of_each_kind_within_the_margin(raw, named_pick, margin):
    entries = [{"cause": POOL[i][0], "detail": POOL[i][1], "aicc": a} for i, a in raw]
    named = None if named_pick is None else (entries[named_pick % len(entries)]["cause"],
                                             entries[named_pick % len(entries)]["detail"])
    got = close_candidates(entries, named=named, margin=margin)
    want = _close_by_rule(entries, named, AMBIGUOUS_AICC if margin is None else margin)
    assert sorted(map(_key, got)) == sorted(map(_key, want))
    assert [e["aicc"] for e in got] == sorted(e["aicc"] for e in got)
    assert len({_kind(e) for e in got}) == len(got)
    if named is not None and got:
        assert any((e["cause"], e["detail"]) == named and e in want for e in got)


def test_a_gap_equal_to_the_margin_is_close_and_just_beyond_it_is_not():
    for gap, close in [(AMBIGUOUS_AICC, True), (AMBIGUOUS_AICC + 1e-9, False), (0.0, True)]:
        entries = [{"cause": "outlier", "detail": "3", "aicc": 50.0},
                   {"cause": "drift", "detail": "run", "aicc": 50.0 + gap}]
        assert len(close_candidates(entries)) == (2 if close else 1)
    # a rival better than the named cause is close however far ahead
    entries = [{"cause": "drift", "detail": "run", "aicc": 10.0}, {"cause": "outlier", "detail": "3", "aicc": 40.0}]
    assert [e["cause"] for e in close_candidates(entries, named=("outlier", "3"))] == ["drift", "outlier"]


@pytest.mark.parametrize("cause, detail, kind", [("outlier", 4, ("one run", "4")), ("factor_level", "4", ("one run", "4")),
                                                 ("step", 9, ("step", "9")), ("drift", "run", ("drift",)),
                                                 ("missing_term", "a^3", ("missing_term",))])
def test_candidate_kinds(cause, detail, kind):
    assert candidate_kind(cause, detail) == kind


@settings(max_examples=40, deadline=None, derandomize=True)
@given(raw=entries_strategy, named_pick=st.integers(0, 6))
def test_confirming_rivals_are_every_kind_within_ten_or_else_the_nearest(raw, named_pick):
    entries = [{"cause": POOL[i][0], "detail": POOL[i][1], "aicc": a} for i, a in raw]
    pick = entries[named_pick % len(entries)]
    named = (pick["cause"], pick["detail"])
    got = confirming_rivals(entries, named)
    within = _close_by_rule(entries, named, CONFIRM_AICC)
    if len(within) > 1:
        assert sorted(map(_key, got)) == sorted(map(_key, within))
        return
    every = sorted(_close_by_rule(entries, named, math.inf), key=lambda e: e["aicc"])
    anchor = [e for e in every if (e["cause"], e["detail"]) == named]
    others = [e for e in every if (e["cause"], e["detail"]) != named]
    assert list(map(_key, got)) == list(map(_key, anchor + others[:1]))


@settings(max_examples=30, deadline=None, derandomize=True)
@given(anchor=st.integers(0, 40).map(lambda q: q / 4),
       others=st.lists(st.integers(0, 80).map(lambda q: q / 4), max_size=5))
def test_the_covariates_nearly_as_good_are_those_within_the_margin_best_first(anchor, others):
    pairs = [(a, f"x{i}") for i, a in enumerate(others)]
    got = _nearly_as_good(anchor, pairs)
    want = [name for a, name in sorted(pairs) if a - anchor <= AMBIGUOUS_AICC]
    assert got == want


def test_a_cause_named_by_a_wide_margin_is_confirmed_against_the_nearest_other_kind():
    entries = [{"cause": "missing_term", "detail": "a^3", "aicc": 20.0},
               {"cause": "drift", "detail": "run", "aicc": 45.0},
               {"cause": "outlier", "detail": "3", "aicc": 35.0},
               {"cause": "missing_term", "detail": "b^3", "aicc": 21.0}]
    got = confirming_rivals(entries, ("missing_term", "a^3"))
    assert [(e["cause"], e["detail"]) for e in got] == [("missing_term", "a^3"), ("outlier", "3")]
    # within CONFIRM_AICC: every kind there, and no farther one
    entries[1]["aicc"] = 30.0
    got = confirming_rivals(entries, ("missing_term", "a^3"))
    assert [(e["cause"], e["detail"]) for e in got] == [("missing_term", "a^3"), ("drift", "run")]

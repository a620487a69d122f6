"""The candidates the runs cannot tell apart (criticism.discrimination.close_candidates), whole, against the rule
written out here over generated entries: 1-9 entries of outliers and slipped values (one kind per run), steps (one
kind per change-point), drift, missing terms and unequal scatter, AICc on a grid of half-units (so a rival exactly
the margin behind is drawn: it is a candidate; half a unit further is not), unfitted entries (None, inf), with and
without a named cause (fitted, fitted twice, or not fitted), at the ambiguity margin and the wider confirming one."""

from __future__ import annotations

import math

from hypothesis import given, settings
from hypothesis import strategies as st

from demid.criticism.discrimination import AMBIGUOUS_AICC, CONFIRM_AICC, candidate_kind, close_candidates

_CAUSES = [("outlier", 3), ("outlier", 7), ("factor_level", 3), ("factor_level", 7), ("step", "4"), ("step", "9"),
           ("drift", "run"), ("missing_term", "a^3"), ("missing_term", "a^2 b"), ("heteroscedasticity", "fitted")]


def _kind(e):
    if e["cause"] in ("outlier", "factor_level"):
        return ("one run", str(e["detail"]))
    return ("step", str(e["detail"])) if e["cause"] == "step" else (e["cause"],)


def _expected(entries, named, margin):
    fitted = [e for e in entries if e["aicc"] is not None and math.isfinite(e["aicc"])]
    if not fitted:
        return []
    if named is None:
        anchor = min(fitted, key=lambda e: e["aicc"])
    else:
        mine = [e for e in fitted if (e["cause"], e["detail"]) == named]
        if not mine:
            return []
        anchor = min(mine, key=lambda e: e["aicc"])
    best = {}
    for e in fitted:
        if _kind(e) not in best or e["aicc"] < best[_kind(e)]["aicc"]:
            best[_kind(e)] = e
    best[_kind(anchor)] = anchor  # the named cause stands for its kind, even when another of its kind fits better
    return sorted((e for e in best.values() if e is anchor or e["aicc"] - anchor["aicc"] <= margin),
                  key=lambda e: e["aicc"])


@settings(max_examples=80, deadline=None, derandomize=True)
@given(which=st.lists(st.integers(0, len(_CAUSES) - 1), min_size=1, max_size=9),
       halves=st.lists(st.integers(0, 40), min_size=9, max_size=9, unique=True),
       base=st.sampled_from([0.0, -37.0, 1000.0]), unfitted=st.lists(st.sampled_from([None, math.inf, "fit"]),
                                                                       min_size=9, max_size=9),
       named=st.one_of(st.none(), st.integers(0, 8), st.just(-1)),
       margin=st.sampled_from([None, AMBIGUOUS_AICC, CONFIRM_AICC]))
def test_close_candidates_are_the_named_cause_and_each_kinds_best_within_the_margin(which, halves, base, unfitted,
                                                                                    named, margin):
    entries = []
    for j, i in enumerate(which):
        cause, detail = _CAUSES[i]
        aicc = base + 0.5 * halves[j] if unfitted[j] == "fit" else unfitted[j]
        entries.append({"cause": cause, "detail": detail, "aicc": aicc})
    if named is None:
        name = None
    elif named == -1 or named >= len(entries):
        name = ("drift", "never fitted")
    else:
        name = (entries[named]["cause"], entries[named]["detail"])
    got = close_candidates(entries, named=name, margin=margin)
    want = _expected(entries, name, AMBIGUOUS_AICC if margin is None else margin)
    assert [id(e) for e in got] == [id(e) for e in want]
    assert len({candidate_kind(e["cause"], e["detail"]) for e in got}) == len(got)


def test_a_rival_exactly_the_margin_behind_is_a_candidate_and_a_hair_further_is_not():
    for margin in (AMBIGUOUS_AICC, CONFIRM_AICC):
        named = {"cause": "drift", "detail": "run", "aicc": 20.0}
        at = {"cause": "step", "detail": "4", "aicc": 20.0 + margin}
        beyond = {"cause": "outlier", "detail": 3, "aicc": math.nextafter(20.0 + margin, math.inf)}
        assert close_candidates([beyond, at, named], named=("drift", "run"), margin=margin) == [named, at]
        assert close_candidates([beyond, at, named], margin=margin) == [named, at]


def test_a_named_cause_stands_for_its_kind_when_another_reading_of_its_run_fits_better():
    """The strongest test named run 3 an outlier; its slipped-value reading fits better (same kind, one run): the
    outlier is the candidate of that kind, listed by its own AICc, with the rivals within the margin of it."""
    slip = {"cause": "factor_level", "detail": 3, "aicc": 10.0}
    outlier = {"cause": "outlier", "detail": 3, "aicc": 12.0}
    drift = {"cause": "drift", "detail": "run", "aicc": 11.0}
    step = {"cause": "step", "detail": "4", "aicc": 18.0}
    far = {"cause": "missing_term", "detail": "a^3", "aicc": 18.5}
    assert close_candidates([slip, outlier, drift, step, far], named=("outlier", 3)) == [drift, outlier, step]
    assert close_candidates([slip, outlier, drift, step, far]) == [slip, drift]

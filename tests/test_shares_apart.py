"""A wave's plausible shares printed as "before → after": three significant digits, or as many more (up to six) as
make two different shares read apart, so a stop line never shows "1.61 % → 1.61 %" beside a "+0.4 %" change.
Checked against the rule written out (the fewest digits from 3 to 6 whose texts differ), in the loop's stop line and
in the advice's next-runs sentence."""

from __future__ import annotations

import math
import re

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.precision import SHARE_DIGITS, SHARE_DIGITS_MAX, shares_apart
from demid.waves import WaveEvidence, stop_decision


def _fewest_digits_apart(before: float, after: float) -> int:
    """The digits the rule asks for, found by trying every count from 3 up: the first whose texts differ, else 6."""
    for digits in range(3, 7):
        if f"{before:.{digits}g}" != f"{after:.{digits}g}":
            return digits
    return 6


@given(before=st.floats(1e-3, 100.0), ratio=st.one_of(st.just(1.0), st.floats(0.9, 1.1), st.floats(0.999, 1.001),
                                                       st.floats(0.99999, 1.00001)))
@settings(max_examples=120, deadline=None, derandomize=True)
def test_two_shares_read_apart_with_the_fewest_digits_that_tell_them_apart(before, ratio):
    after = before * ratio
    texts = shares_apart(before, after)
    digits = 3 if before == after else _fewest_digits_apart(before, after)
    assert texts == (f"{before:.{digits}g}", f"{after:.{digits}g}")
    for text, value in zip(texts, (before, after)):  # each within half a unit of its last printed digit
        assert float(text) == pytest.approx(value, rel=0.5 * 10.0 ** (1 - digits) * 1.0001)
    unit_of_sixth_digit = 10.0 ** (math.floor(math.log10(max(before, after))) - 5)
    if abs(after - before) > unit_of_sixth_digit:  # more than a unit of the sixth digit apart: they read apart
        assert texts[0] != texts[1]


def test_the_digit_limits_are_three_and_six():
    assert (SHARE_DIGITS, SHARE_DIGITS_MAX) == (3, 6)
    assert shares_apart(1.606, 1.613) == ("1.606", "1.613")
    assert shares_apart(1.4, 1.55) == ("1.4", "1.55")  # already apart at three digits: no more
    assert shares_apart(2.0, 2.0) == ("2", "2")
    assert shares_apart(2.0, 2.0 + 1e-9) == ("2", "2")  # apart beyond six digits: six digits, equal texts
    assert shares_apart(12.3456, 12.3457) == ("12.3456", "12.3457")


def _evidence(previous: float, now: float) -> WaveEvidence:
    return WaveEvidence(wave=3, max_waves=3, plausible_pct=now, previous_pct=previous,
                        surrogates={"y1": {"q2": 0.97, "lof_p": 0.40, "loo_band": 0.37}}, model_limit=False,
                        proposed=9, criticism_runs=0)


@pytest.mark.parametrize("previous, now", [(1.606, 1.613), (1.61, 1.6104), (0.4437, 0.4441), (10.0, 10.02),
                                           (3.0, 2.5)])
def test_the_stop_line_quotes_both_shares_apart_beside_their_change(previous, now):
    reason = stop_decision(None, _evidence(previous, now))["reason"]
    quoted = re.search(r"went ([\d.]+) % → ([\d.]+) % from wave 2 to wave 3 \(([+-][\d.]+) %\)", reason)
    assert quoted, reason
    assert (quoted[1], quoted[2]) == shares_apart(previous, now)
    assert quoted[1] != quoted[2]
    assert float(quoted[3]) == pytest.approx(100 * (now / previous - 1), abs=0.051)


@pytest.mark.parametrize("contraction", [0.001, 0.004, 0.03])
def test_the_predicted_shrink_quotes_both_shares_apart(contraction):
    value = {"scenario": "both", "count": 9, "plausible_fraction_pct": 1.61,
             "expected_fraction_pct": 1.61 * (1 - contraction), "expected_contraction": contraction, "stop": True}
    evidence = WaveEvidence(wave=1, max_waves=3, plausible_pct=1.61, previous_pct=None,
                            surrogates={"y1": {"q2": 0.97, "lof_p": 0.40, "loo_band": 0.1}}, model_limit=False,
                            proposed=9, criticism_runs=0)
    reason = stop_decision(value, evidence)["reason"]
    quoted = re.search(r"\(([\d.]+) % → ([\d.]+) % of the wave's range\)", reason)
    assert quoted, reason
    assert (quoted[1], quoted[2]) == shares_apart(1.61, 1.61 * (1 - contraction))
    assert quoted[1] != quoted[2]


@pytest.mark.parametrize("stop, contraction", [(True, 0.002), (False, 0.004), (False, 0.35)])
def test_the_advice_quotes_the_shares_as_the_stop_line_does(stop, contraction):
    from demid.spec import MaterialSpec
    from demid.story.advice import _next_wave

    spec = MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "custom"},
        "factors": {"a": {"lower": 0.0, "upper": 1.0}, "b": {"lower": 0.0, "upper": 1.0}},
        "responses": {"y1": {"target": 10.0}}, "scenarios": {"both": {"observables": ["y1"], "tolerance": 0.05}}})
    value = {"scenario": "both", "count": 9, "plausible_fraction_pct": 1.606,
             "expected_fraction_pct": 1.606 * (1 - contraction), "expected_contraction": contraction, "stop": stop}
    (item,) = _next_wave(spec, value, "")
    quoted = re.search(r"\(([\d.]+) % → ([\d.]+) % of the search range\)", item.text)
    assert quoted, item.text
    assert (quoted[1], quoted[2]) == shares_apart(1.606, 1.606 * (1 - contraction))
    assert quoted[1] != quoted[2]

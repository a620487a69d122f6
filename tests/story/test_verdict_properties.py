"""A factor's verdict and the numbers its reason quotes, over generated intervals in linear and log ranges of
different signs and scales: the width is the interval's share of the range (in decades on a log scale), the
verdict follows the two thresholds and the bounds the interval reaches, and each width and strict interval the
reason quotes reads back as the number it stands for."""

from __future__ import annotations

import math
import re

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.story.verdicts import IDENTIFIED_MAX_WIDTH, UNRESOLVED_MIN_WIDTH, _reason, factor_verdict

_RANGES = [(0.0, 1.0, False), (-250.0, -50.0, False), (1e-3, 10.0, True), (2e9, 7e10, True), (-1.0, 3.0, False)]


def _at(lo, hi, log, u):
    return 10 ** (math.log10(lo) + u * (math.log10(hi) - math.log10(lo))) if log else lo + u * (hi - lo)


@given(which=st.integers(0, len(_RANGES) - 1), start=st.floats(0.0, 1.0), share=st.floats(0.005, 1.0))
@settings(max_examples=120, deadline=None, derandomize=True)
def test_a_verdict_follows_the_intervals_share_of_the_range_and_the_bounds_it_reaches(which, start, share):
    lo, hi, log = _RANGES[which]
    a = min(start, 1.0 - share)
    b = a + share
    lower, upper = _at(lo, hi, log, a), _at(lo, hi, log, b)
    verdict, width = factor_verdict(lower, upper, lo, hi, log)
    assert width == pytest.approx(share, rel=1e-9, abs=1e-12)
    low_end, high_end = a <= 1e-3, b >= 1 - 1e-3  # within a thousandth of the range counts as reaching it
    if share >= UNRESOLVED_MIN_WIDTH:
        assert verdict == "unresolved"
    elif (a < 0.01 or b > 0.99) and not (low_end or high_end):
        return  # near a bound, not on it: where the touch tolerance lies is the domain's, not tested here
    elif low_end or high_end:
        sides = " and ".join(s for s, on in (("lower", low_end), ("upper", high_end)) if on)
        assert verdict == f"cut by the search range ({sides} bound)"
    else:
        assert verdict == ("identified" if share <= IDENTIFIED_MAX_WIDTH else "bounded")
    reason = _reason(verdict, width, verdict, width, (lower, upper))
    quoted = re.search(r"([\d.e+-]+) % of the search range", reason)
    assert quoted and float(quoted.group(1)) == pytest.approx(100 * share, rel=5.1e-3), reason


@pytest.mark.parametrize("strict, strict_width, strict_verdict", [
    ((0.25, 0.3125), 0.0625, "identified"), ((-12.5, 40.0), 0.525, "bounded"), ((1e-3, 2.5e-3), 0.04, "identified")])
def test_a_strict_verdict_other_than_the_plausible_one_quotes_its_interval_and_width(strict, strict_width,
                                                                                    strict_verdict):
    reason = _reason("unresolved", 0.95, strict_verdict, strict_width, strict)
    said = re.search(r"\[([-\d.e+]+), ([-\d.e+]+)\], ([\d.e+-]+) % of the search range", reason)
    assert said, reason
    assert float(said.group(1)) == pytest.approx(strict[0], rel=5e-4)
    assert float(said.group(2)) == pytest.approx(strict[1], rel=5e-4)
    assert float(said.group(3)) == pytest.approx(100 * strict_width, rel=5.1e-3)
    assert ("identified if surrogate and measurements were exact" in reason) == (strict_verdict == "identified")
    assert reason.startswith("the plausible interval covers 95 % of the search range")
    empty = _reason("bounded", 0.3, "no admissible point", float("nan"), (float("nan"), float("nan")))
    assert empty.endswith("; strictly (surrogate and measurements exact) no point meets every target")
    assert "identified needs at most 10 %" in empty and "30 % of the search range wide" in empty


def test_a_reason_names_the_physical_limits_an_interval_ends_at():
    one = _reason("identified", 0.05, "identified", 0.05, (0.0, 0.05), {"lower": 0.0})
    assert one.endswith("clear of the upper bound, ending at the physical lower limit (0), beyond which no value lies")
    both = _reason("bounded", 0.5, "bounded", 0.5, (0.0, 1.0), {"lower": 0.0, "upper": 1.0})
    assert "reaches the physical limits at both ends (0 and 1)" in both
    cut = _reason("cut by the search range (upper bound)", 0.2, "cut by the search range (upper bound)", 0.2,
                  (0.8, 1.0), {"lower": 0.25})
    assert "reaches the upper bound: the set may extend beyond the search range; its lower end is the physical " \
           "limit (0.25)" in cut

"""Which numbers demid computes with (demid/numbers.py): zero, or finite with a magnitude in [1e-30, 1e30].

Each value is judged against that rule written out here independently (``math.isfinite`` and the two ends), over
signs, the two ends themselves and their nearest floats, and printed forms that read as 0 or as infinity."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.numbers import LARGEST, SMALLEST, unusable_number


def _usable(value: float) -> bool:
    return value == 0 or (math.isfinite(value) and 1e-30 <= abs(value) <= 1e30)


@given(value=st.floats(allow_nan=True, allow_infinity=True), sign=st.sampled_from([1.0, -1.0]))
@settings(max_examples=300, deadline=None, derandomize=True)
def test_unusable_number_refuses_exactly_the_values_outside_the_rule(value, sign):
    value = sign * value
    assert (unusable_number(value) == "") == _usable(value), value


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_unusable_number_keeps_both_ends_and_refuses_their_outer_neighbours(sign):
    assert (SMALLEST, LARGEST) == (1e-30, 1e30)
    for value in (1e-30, 1e30, 0.0, 1.0, 5e-30, 2e29):
        assert unusable_number(sign * value) == ""
    for value in (math.nextafter(1e-30, 0.0), math.nextafter(1e30, math.inf), 1e31, 1e-31, 5e-324, 1e308):
        message = unusable_number(sign * value)
        assert message == (f"found {sign * value:g}, outside the magnitudes demid computes with (0, or 1e-30 to "
                           "1e30); check the value, or give it in another unit"), value


@pytest.mark.parametrize("text, value, expected", [
    ("1e-400", 0.0, "found '1e-400', too small for a float (it reads as 0); give it in another unit"),
    (" -2.5E-500 ", 0.0, "found '-2.5E-500', too small for a float (it reads as 0); give it in another unit"),
    ("0.000", 0.0, ""),
    ("-0", 0.0, ""),
    ("0e-400", 0.0, ""),  # a zero written with an exponent is a zero, not an underflow
    ("0E10", 0.0, ""),
    ("1e5000", math.inf, "found '1e5000', too large for a float (it overflows to infinity)"),
    ("-1e5000", -math.inf, "found '-1e5000', too large for a float (it overflows to infinity)"),
    ("inf", math.inf, "found 'inf', an infinite value"),
    ("-Infinity", -math.inf, "found '-Infinity', an infinite value"),
    ("nan", math.nan, "found 'nan', not a number"),
    ("1e31", 1e31, "found '1e31', outside the magnitudes demid computes with (0, or 1e-30 to 1e30); check the "
                   "value, or give it in another unit"),
    ("-3.5e-31", -3.5e-31, "found '-3.5e-31', outside the magnitudes demid computes with (0, or 1e-30 to 1e30); "
                           "check the value, or give it in another unit"),
    ("12.5", 12.5, ""),
])
def test_unusable_number_names_the_printed_form_and_why(text, value, expected):
    assert unusable_number(value, text) == expected


def test_unusable_number_without_text_prints_the_value():
    assert unusable_number(math.inf) == "found inf, too large for a float (it overflows to infinity)"
    assert unusable_number(-math.inf) == "found -inf, too large for a float (it overflows to infinity)"
    assert unusable_number(math.nan) == "found nan, not a number"
    # a value that is 0 without its printed form is a plain zero
    assert unusable_number(0.0) == ""

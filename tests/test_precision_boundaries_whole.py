"""The number texts and the round-off floor exactly on each of their thresholds, with the side a reader expects:
a value of exactly half its place rounds to zero there and is written as indistinguishable from zero; a p-value of
exactly 1e-4 is printed, a hair below it is "< 0.0001"; a percentage exactly at 0.01 % or at ten times is a number,
past them words; an uncertainty or value exactly at the fixed form's ends; a residual root mean square exactly at
the floor is round-off; a column tied between reading decimals and significant digits reads decimals; a factor
column printed to exactly four significant digits is read as rounded, one of three is not; the place of an
uncertainty's second digit against Decimal."""

from __future__ import annotations

from decimal import Decimal

import numpy as np
import pytest
from hypothesis import Phase, given, settings
from hypothesis import strategies as st

from demid.precision import (ZERO, at_place, coordinate_text, counted, factor_print_quantum, p_text, percent_text, place_of,
                             printed_quantum, q2_text, rough_text, round_off_floor, round_off_only, uncertainty_text,
                             value_text)


@pytest.mark.parametrize("uncertainty", [93.0, 9.3, 0.47, 0.012, 930.0, 47_000.0])
@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_a_value_of_exactly_half_its_place_is_indistinguishable_from_zero(uncertainty, sign):
    # half of the place rounds to zero there (round half to even): the data cannot tell the value from zero
    place = place_of(uncertainty)
    value = sign * place / 2
    assert value_text(value, uncertainty) == ZERO
    assert value_text(value * 1.02, uncertainty) == at_place(value * 1.02, place) != ZERO


@given(mantissa=st.floats(1.0, 9.99), exponent=st.integers(-6, 8), digits=st.integers(1, 4))
@settings(max_examples=30, deadline=None, derandomize=True, phases=[Phase.explicit, Phase.generate])
def test_the_place_of_a_number_s_last_kept_digit_against_decimal(mantissa, exponent, digits):
    x = mantissa * 10.0 ** exponent
    rounded = Decimal(f"{x:.{digits}g}")
    want = 10.0 ** (rounded.adjusted() - digits + 1)
    assert place_of(x, digits) == pytest.approx(want, rel=1e-12)
    assert place_of(-x, digits) == place_of(x, digits)


def test_the_place_of_the_documented_examples():
    assert (place_of(0.093), place_of(12), place_of(0.0998)) == pytest.approx((0.001, 1.0, 0.01), rel=1e-12)


def test_a_p_value_at_its_floor_is_printed_and_below_it_is_not():
    assert p_text(1e-4) == "0.0001"
    assert p_text(0.99e-4) == "< 0.0001"
    assert p_text(0.0123) == "0.012"


@pytest.mark.parametrize("n, text", [(0, "0 waves"), (1, "1 wave"), (2, "2 waves"), (11, "11 waves")])
def test_a_count_and_its_noun(n, text):
    assert counted(n, "wave") == text


def test_percentages_on_each_threshold():
    assert percent_text(1e-4) == "0.01 %" and percent_text(-1e-4) == "−0.01 %"
    assert percent_text(0.99e-4) == "< 0.01 %" and percent_text(0.0) == "0 %"
    assert percent_text(10.0 * (1 + 1e-12)) == "more than 10×" and percent_text(-10.5) == "more than 10×"
    assert percent_text(9.0) == "900 %" and percent_text(-0.05) == "−5 %" and percent_text(0.123456, 4) == "12.35 %"


def test_q2_on_one_and_just_below_it():
    assert q2_text(1.0) == "1.00" and q2_text(1.5) == "1.50" and q2_text(-0.5) == "-0.50"
    assert q2_text(0.9966) == "0.997" and q2_text(0.99951) == "0.9995" and q2_text(0.99949) == "0.999" and q2_text(0.9999995) == "> 0.999999"
    assert q2_text(0.994) == "0.99"


def test_uncertainties_and_rough_values_at_the_fixed_form_s_ends():
    assert uncertainty_text(1e4) == "1e+04" and uncertainty_text(9999.0) == "10000"
    assert uncertainty_text(1e-4) == "0.00010" and uncertainty_text(0.99e-4) == "9.9e-05"
    assert uncertainty_text(-0.0123) == "−0.012" and uncertainty_text(0.0) == "0"
    assert rough_text(1e6) == "1e+06" and rough_text(999_999.0) == "1000000"
    assert rough_text(1e-4) == "0.0001" and rough_text(0.99e-4) == "0.0001"
    assert rough_text(-12.34) == "−10" and rough_text(0.0345) == "0.03"


def test_a_residual_spread_exactly_at_the_round_off_floor_is_round_off():
    y = np.array([1.0, 2.0, 3.0, 4.0])  # printed to units: the floor is sqrt(1.5 / 12)
    floor = round_off_floor(y)
    assert floor == np.sqrt(1.5 / 12)
    residuals = np.full(4, floor)
    assert np.sqrt(np.mean(residuals ** 2)) == floor  # the spread lands exactly on the floor
    assert round_off_only(residuals, y)
    assert not round_off_only(residuals * (1 + 1e-12), y)
    assert not round_off_only(np.zeros(0), y)
    assert round_off_only(np.zeros(4), y)
    assert round_off_floor(np.zeros(0)) == 0.0
    # factors' round-off adds its variance; a value carrying every digit leaves working precision
    assert round_off_floor(y, np.full(4, 0.5)) == pytest.approx(np.sqrt(1.5 * (1 / 12 + 0.25)), rel=1e-14)
    assert round_off_floor([1.0123456789012345, -3.0123456789012345]) == pytest.approx(3.0123456789012345e-9)


def test_a_column_tied_between_decimals_and_significant_digits_reads_decimals():
    # decimals 0, 2, 2 (two at the most) and significant digits 4, 4, 3 (two at the most): a tie
    np.testing.assert_allclose(printed_quantum([1228.0, 29.18, 3.12]), [0.01] * 3, rtol=1e-12)
    # one more value at four digits: significant digits win
    np.testing.assert_allclose(printed_quantum([1228.0, 29.18, 3.12, 4.567]), [1.0, 0.01, 0.001, 0.001], rtol=1e-12)


def test_a_factor_column_of_four_significant_digits_is_rounded_one_of_three_is_not():
    # 0.0757 beside 0.5: the column's place is 1e-4, where 0.5000 shows four digits
    np.testing.assert_allclose(factor_print_quantum([0.0757, 0.5]), [1e-4, 0.0], rtol=1e-12)
    # 0.757 beside 0.5: three digits at most, a value a person set
    assert factor_print_quantum([0.757, 0.5]).tolist() == [0.0, 0.0]


@pytest.mark.parametrize("value, lower, upper, text", [
    (0.075736, 0.0757, 0.924, "0.0757"),   # a range under 1: a thousandth of it is 1e-4 to the power of ten below
    (123.456, 0.0, 100.0, "123.5"),        # a range of exactly 100: its thousandth is 0.1 itself
    (123.456, 100.0, 0.0, "123.5"),        # bounds either way round
    (1234.56, 0.0, 1000.0, "1235"),
    (-12.3456, -20.0, -10.0, "−12.35"),
    (0.00012345, 0.0001, 0.0002, "0.0001234"),
    (5.0, 5.0, 5.0, "5.000"),              # no range: a thousandth of the value
    (0.0, 0.0, 0.0, "0"),                  # no range and no value: a thousandth of 1
    (float("nan"), 0.0, 1.0, "–"),
])
def test_a_coordinate_to_a_thousandth_of_its_range(value, lower, upper, text):
    assert coordinate_text(value, lower, upper) == text

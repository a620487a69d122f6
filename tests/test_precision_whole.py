"""The report's number texts at their edges, each against the rule written out here: a value that is not a finite
number (NaN, either infinity, None) prints as a dash whatever uncertainty comes with it; a Q² takes the fewest
decimals from two that do not print a value below one as one; a percentage's thresholds (a trace below 0.01 %, a
ratio past 10x) hold on the threshold itself; a p-value's floor and a count's plural at 0, 1 and 2."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.precision import (SMALLEST_P, ZERO, counted, coordinate_text, p_text, percent_text, pm_text, q2_text,
                             rough_text, uncertainty_text, value_text)

NOT_FINITE = [math.nan, math.inf, -math.inf]
UNCERTAINTIES = [None, math.nan, 0.0, 1e-6, 0.03, 2.5, 1e9]


@pytest.mark.parametrize("value", NOT_FINITE + [None])
@pytest.mark.parametrize("uncertainty", UNCERTAINTIES)
def test_a_value_that_is_no_finite_number_prints_as_a_dash_whatever_its_uncertainty(value, uncertainty):
    assert value_text(value, uncertainty) == "–"
    assert value_text(value, uncertainty, max_digits=2) == "–"


@pytest.mark.parametrize("value", NOT_FINITE)
def test_every_other_text_of_a_number_that_is_not_finite(value):
    assert rough_text(value) == "–"
    assert uncertainty_text(value) == "–"
    assert p_text(value) == "–"
    assert percent_text(value) == "–"
    assert coordinate_text(value, 0.0, 1.0) == "–"
    assert q2_text(value) == "undefined"
    assert pm_text(1.0, value) == "1 ± –"


def test_none_where_a_number_is_missing():
    assert rough_text(None) == p_text(None) == percent_text(None) == "–"
    assert q2_text(None) == "undefined"


def _q2_written_out(q2: float) -> str:
    for places in range(2, 7):
        text = f"{q2:.{places}f}"
        if q2 >= 1 or float(text) < 1:
            return text
    return "> 0.999999"


@given(q2=st.one_of(st.floats(-5.0, 1.5), st.sampled_from([0.994, 0.995, 0.9949999, 0.99995, 0.9999996, 1.0, 1.004,
                                                          0.0, -0.004])))
@settings(max_examples=60, deadline=None, derandomize=True)
def test_q2_takes_the_fewest_decimals_from_two_that_do_not_print_one(q2):
    text = q2_text(q2)
    assert text == _q2_written_out(q2)
    if q2 < 1:
        assert text.startswith(">") or float(text) < 1
    if not text.startswith(">"):
        decimals = len(text.partition(".")[2])
        assert 2 <= decimals <= 6
        assert float(text) == pytest.approx(q2, abs=0.5 * 10 ** -decimals + 1e-12)


@pytest.mark.parametrize("q2, text", [(0.5, "0.50"), (0.996, "0.996"), (0.9996, "0.9996"), (1.0, "1.00"),
                                      (0.99999996, "> 0.999999"), (-1.2345, "-1.23"), (0.994, "0.99")])
def test_q2_known_texts(q2, text):
    assert q2_text(q2) == text


@pytest.mark.parametrize("fraction, text", [(0.0, "0 %"), (-0.0, "0 %"), (1e-4, "0.01 %"), (-1e-4, "−0.01 %"),
                                            (9.99e-5, "< 0.01 %"), (-9.99e-5, "< 0.01 %"), (10.0, "1000 %"),
                                            (9.996, "1000 %"), (9.994, "999 %"),
                                            (-10.0, "−1000 %"), (10.01, "more than 10×"),
                                            (-10.01, "more than 10×"), (0.123456, "12.3 %"),
                                            (-0.5, "−50 %"), (1.0, "100 %")])
def test_a_percentage_on_and_past_each_threshold(fraction, text):
    assert percent_text(fraction) == text


def test_a_percentage_to_other_digits():
    assert percent_text(0.123456, digits=2) == "12 %"
    assert percent_text(0.123456, digits=5) == "12.346 %"


@pytest.mark.parametrize("p, text", [(SMALLEST_P, "0.0001"), (0.99e-4, "< 0.0001"), (0.0, "< 0.0001"),
                                     (0.04567, "0.046"), (1.0, "1"), (0.5, "0.5")])
def test_a_p_value_on_its_floor_and_above(p, text):
    assert p_text(p) == text


@pytest.mark.parametrize("n, text", [(0, "0 runs"), (1, "1 run"), (2, "2 runs"), (11, "11 runs")])
def test_a_count_takes_its_plural_except_at_one(n, text):
    assert counted(n, "run") == text


def test_a_value_below_half_its_place_is_zero_and_a_negative_one_keeps_its_sign():
    # an uncertainty of 0.1 supports two decimals: half of 0.01 is the edge
    assert value_text(0.004, 0.1) == ZERO
    assert value_text(-0.004, 0.1) == ZERO
    assert value_text(-0.006, 0.1) == "−0.01"
    assert value_text(0.0051, 0.1) == "0.01"
    assert value_text(0.0, 0.5) == ZERO
    assert value_text(0.0) == "0" and value_text(0.0, 0.0) == "0"


# ---- the round-off floor: the residual size below which a fit is exact to the table's printed precision
from demid.precision import ROUND_OFF, printed_place, printed_quantum, round_off_floor, round_off_only  # noqa: E402


@given(decimals=st.integers(0, 4), n=st.integers(3, 15), seed=st.integers(0, 10_000),
       with_factors=st.booleans(), scale=st.sampled_from([1.0, 1e4]))
@settings(max_examples=30, deadline=None, derandomize=True)
def test_the_round_off_floor_is_the_larger_of_working_precision_and_the_print(decimals, n, seed, with_factors,
                                                                               scale):
    import numpy as np

    rng = np.random.default_rng(seed)
    y = np.round(rng.uniform(1, 9, n) * scale, decimals)
    y[0] = round(float(y[0]) + 10.0 ** -decimals * 0.3, decimals) + 10.0 ** -decimals  # a value at the last place
    factor_sd = rng.uniform(0, 0.01, n) if with_factors else None
    quantum = printed_quantum(y)
    variance = quantum ** 2 / 12 + (factor_sd ** 2 if with_factors else 0.0)
    want = max(ROUND_OFF * np.max(np.abs(y)), np.sqrt(1.5 * np.mean(variance)))
    floor = round_off_floor(y, factor_sd)
    assert floor == pytest.approx(want, rel=1e-12)
    at = np.full(n, floor)  # residuals of root mean square the floor (to its last bit): round-off; a little more: not
    assert round_off_only(at * (1 - 1e-12), y, factor_sd)
    assert not round_off_only(at * 1.001, y, factor_sd)
    assert not round_off_only([], y, factor_sd)
    assert round_off_floor([]) == 0.0


@pytest.mark.parametrize("cells, place", [(["0.900000", "1.5"], 1e-6), (["83", "12"], 1.0), (["1.5e-3"], 1e-4),
                                          (["1.2E+3"], 100.0), (["1.2E+3", "7"], 1.0), (["x", "", "−2.25"], 0.01),
                                          (["a", "b"], 0.0)])
def test_a_column_s_printed_place_is_its_finest_printed_digit(cells, place):
    assert printed_place(cells) == pytest.approx(place, rel=1e-12) if place else printed_place(cells) == 0.0

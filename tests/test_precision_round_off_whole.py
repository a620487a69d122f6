"""The round-off a printed table carries, against closed forms over generated tables: the response error the
factors' print adds (a factor value printed to 4-6 significant digits at a known place q is off by up to q/2,
variance q²/12, carried by the gradient over the coded unit, in log10 units for log factors; values a person set,
like 2 beside 0.075736, add nothing), the round-off floor of a response printed to a known place, with and without
the factors' share, against the working-precision floor of 1e-9 of the largest value, and the test of residuals
against it on either side.  A wave's shares "before % → after %" against the fewest digits (3-6) that tell them
apart, written out."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.precision import (ROUND_OFF, factor_round_off_sd, round_off_floor, round_off_only, shares_apart,
                             shares_change_text)


def _printed_column(rng, n, decimals, leading):
    """n values of `leading` integer digits printed to `decimals` decimals, the last digit never 0 (each value
    reaches the column's place), of either sign."""
    whole = rng.integers(10 ** (leading - 1), 10 ** leading, size=n)
    frac = rng.integers(0, 10 ** (decimals - 1), size=n) * 10 + rng.integers(1, 10, size=n)
    values = whole + frac / 10.0 ** decimals
    return np.array([float(f"{v:.{decimals}f}") for v in values]), 10.0 ** -decimals


@given(seed=st.integers(0, 10_000), k=st.integers(1, 3), n=st.integers(3, 9), set_by_hand=st.integers(0, 2),
       logs=st.lists(st.booleans(), min_size=3, max_size=3))
@settings(max_examples=25, deadline=None, derandomize=True)
def test_the_factors_print_adds_gradient_times_its_rounding(seed, k, n, set_by_hand, logs):
    rng = np.random.default_rng(seed)
    columns, quanta = [], []
    for j in range(k):
        decimals, leading = int(rng.integers(3, 6)), int(rng.integers(1, 3))  # 4-7 significant digits
        column, q = _printed_column(rng, n, decimals, leading)
        quantum = np.full(n, q)
        hand = rng.choice(n, size=min(set_by_hand, n - 1), replace=False)
        column[hand] = rng.integers(1, 10, size=len(hand)).astype(float)  # "2", "7": a value a person set
        quantum[hand] = 0.0
        columns.append(column)
        quanta.append(quantum)
    x = np.column_stack(columns)
    gradient = rng.normal(size=(n, k)) * 10.0 ** rng.integers(-2, 3, size=k)
    unit = rng.uniform(0.2, 5.0, size=k) * rng.choice([-1.0, 1.0], size=k)
    log_scale = logs[:k]
    expected = np.zeros(n)
    for j in range(k):
        q = quanta[j] / (np.abs(x[:, j]) * math.log(10.0)) if log_scale[j] else quanta[j]
        expected += (gradient[:, j] * q / abs(unit[j])) ** 2 / 12.0
    np.testing.assert_allclose(factor_round_off_sd(gradient, x, unit, log_scale), np.sqrt(expected), rtol=1e-9,
                               atol=0)


@given(seed=st.integers(0, 10_000), n=st.integers(2, 12), decimals=st.integers(1, 4), leading=st.integers(1, 4),
       with_factors=st.booleans())
@settings(max_examples=25, deadline=None, derandomize=True)
def test_the_round_off_floor_of_a_response_printed_to_a_known_place(seed, n, decimals, leading, with_factors):
    rng = np.random.default_rng(seed)
    y, q = _printed_column(rng, n, decimals, leading)
    y = y * rng.choice([-1.0, 1.0], size=n)
    factor_sd = rng.uniform(0, 3 * q, size=n) if with_factors else None
    variance = q ** 2 / 12 + (factor_sd ** 2 if with_factors else 0.0)
    floor = max(ROUND_OFF * np.max(np.abs(y)), math.sqrt(1.5 * np.mean(variance)))
    assert round_off_floor(y, factor_sd) == pytest.approx(floor, rel=1e-9)
    # residuals whose root mean square is the floor are round-off; a hair above, scatter
    residuals = rng.normal(size=n)
    residuals *= floor / math.sqrt(np.mean(residuals ** 2))
    assert round_off_only(residuals * (1 - 1e-9), y, factor_sd)
    assert not round_off_only(residuals * (1 + 1e-9), y, factor_sd)


def test_a_response_of_every_digit_has_the_working_precision_floor():
    y = np.array([1.2345678901234567, -3.3333333333333335, 2.718281828459045]) * 1e3
    assert round_off_floor(y) == ROUND_OFF * np.max(np.abs(y))
    assert round_off_floor(np.array([])) == 0.0
    assert not round_off_only(np.array([]), y)


def _fewest_digits_apart(before, after):
    for digits in range(3, 7):
        if f"{before:.{digits}g}" != f"{after:.{digits}g}":
            return digits
    return 6


@given(before=st.floats(1e-3, 100.0), ratio=st.sampled_from([1.0, 1.2, 1.002, 1.00002, 1.000002, 0.999997]))
@settings(max_examples=30, deadline=None, derandomize=True)
def test_a_change_of_shares_is_written_with_the_digits_that_tell_them_apart(before, ratio):
    after = before * ratio
    digits = 3 if before == after else _fewest_digits_apart(before, after)
    first, second = f"{before:.{digits}g}", f"{after:.{digits}g}"
    assert shares_apart(before, after) == (first, second)
    assert shares_change_text(before, after) == f"{first} % → {second} %"

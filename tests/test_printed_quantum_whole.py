"""The printed precision of a column (printed_quantum), the rounding a factor's print hides (factor_print_quantum)
and the response error it adds (factor_round_off_sd), over generated columns printed as a table would print them:
to fixed decimals (0-6) or to significant digits (3-6), signs mixed, magnitudes 1e-3 to 1e5, a few cells that lost
their trailing zeros.  The expected places are read off the printed strings with Python's Decimal (the digits a
cell shows), not off the floats the code reads."""

from __future__ import annotations

from decimal import Decimal

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.precision import ROUNDED_FACTOR_DIGITS, factor_print_quantum, factor_round_off_sd, printed_quantum


def _printed(rng, n, style, digits, scale):
    """Cells as printed: fixed decimals or significant digits (never so few decimals that a value prints as 0)."""
    low = max(scale, 10.0 ** (1 - digits)) if style == "fixed" else scale
    values = rng.choice([-1.0, 1.0], n) * low * 10.0 ** rng.uniform(0, 1.5, n)
    if style == "fixed":
        return [f"{v:.{digits}f}" for v in values]
    return [f"{float(f'{v:.{digits}g}'):.12g}" for v in values]


def _places(cells):
    """Per cell: the power of ten of its leading digit and of its last non-zero digit, from its digits."""
    lead, last = [], []
    for text in cells:
        d = Decimal(text).normalize()
        sign, digits, exponent = d.as_tuple()
        last.append(exponent)
        lead.append(exponent + len(digits) - 1)
    return np.array(lead), np.array(last)


def _expected_quantum(cells):
    lead, last = _places(cells)
    decimals = -last
    shown = lead + decimals + 1
    by_digits = np.sum(shown == shown.max()) > np.sum(decimals == decimals.max())
    if by_digits:
        return 10.0 ** (lead - shown.max() + 1.0)
    return np.full(len(cells), 10.0 ** -max(decimals.max(), 0))


@given(seed=st.integers(0, 10_000), n=st.integers(3, 12), style=st.sampled_from(["fixed", "significant"]),
       digits=st.integers(0, 6), scale=st.sampled_from([1e-3, 0.1, 1.0, 30.0, 1e4]))
@settings(max_examples=40, deadline=None, derandomize=True)
def test_a_column_s_printed_quantum_is_read_off_its_digits(seed, n, style, digits, scale):
    if style == "significant":
        digits = max(digits, 3)
    rng = np.random.default_rng(seed)
    cells = _printed(rng, n, style, digits, scale)
    values = np.array([float(c) for c in cells])
    want = _expected_quantum(cells)
    got = printed_quantum(values)
    np.testing.assert_allclose(got, want, rtol=1e-9)
    # zeros and cells that are no number carry none and leave the others' alone
    padded = np.concatenate([[0.0, np.nan], values])
    np.testing.assert_allclose(printed_quantum(padded), np.concatenate([[0.0, 0.0], want]), rtol=1e-9)
    # a value of thirteen significant digits: the column was not rounded for print
    assert np.all(printed_quantum(np.append(values, 1.000000000005)) == 0.0)


@given(seed=st.integers(0, 10_000), n=st.integers(3, 10), decimals=st.integers(1, 6),
       scale=st.sampled_from([1e-2, 0.5, 20.0]), log=st.booleans())
@settings(max_examples=30, deadline=None, derandomize=True)
def test_a_factor_s_hidden_rounding_and_the_response_error_it_adds(seed, n, decimals, scale, log):
    rng = np.random.default_rng(seed)
    scale = max(scale, 10.0 ** (1 - decimals))  # no level prints as 0
    # levels a person set (few digits) beside levels derived from alpha (rounded at the column's place)
    set_levels = [f"{scale * k:.{decimals}f}" for k in rng.integers(1, 9, 2)]
    derived = [f"{scale * v:.{decimals}f}" for v in rng.uniform(1, 9, n - 2)]
    cells = set_levels + derived
    x = np.array([float(c) for c in cells])
    quantum = _expected_quantum(cells)
    lead, last = _places(cells)
    shown_at_place = lead - np.log10(quantum) + 1
    reaches = np.isclose(10.0 ** last, quantum, rtol=1e-9)
    want = np.where(reaches & (shown_at_place.max() >= ROUNDED_FACTOR_DIGITS), quantum, 0.0)
    np.testing.assert_allclose(factor_print_quantum(x), want, rtol=1e-9)
    # the response error: the gradient times a rounding uniform over the quantum (variance q^2 / 12), per factor
    other = np.round(rng.uniform(1, 5, n), 1)
    points = np.column_stack([x, other])
    gradient = rng.normal(size=(n, 2))
    unit = rng.uniform(0.2, 3.0, 2)
    q = want / (np.abs(x) * np.log(10.0)) if log else want
    expected = np.sqrt((gradient[:, 0] * q / unit[0]) ** 2 / 12)  # the second factor's print hides nothing
    assert np.all(factor_print_quantum(other) == 0.0)
    np.testing.assert_allclose(factor_round_off_sd(gradient, points, unit, [log, False]), expected, rtol=1e-9,
                               atol=1e-300)


def test_edges_of_the_printed_digits():
    # twelve significant digits are still a print (to 1e-11), thirteen are not
    np.testing.assert_allclose(printed_quantum([1.23456789012, 2.5]), [1e-11, 1e-11], rtol=1e-9)
    assert np.all(printed_quantum([1.234567890123, 2.5]) == 0.0)
    # a level of exactly 1 in a column of whole numbers printed to four digits reaches its place like the others
    np.testing.assert_allclose(factor_print_quantum([1.0, 1234.0, 2345.0]), [1.0, 1.0, 1.0], rtol=1e-12)
    np.testing.assert_allclose(factor_print_quantum([0.0, 1.0, 1234.0]), [0.0, 1.0, 1.0], rtol=1e-12)
    # factors given as nested lists, as a table's rows
    sd = factor_round_off_sd(np.array([[2.0], [1.0]]), [[0.075736], [0.924264]], [0.5], [False])
    np.testing.assert_allclose(sd, [2.0 * 1e-6 / 0.5 / np.sqrt(12), 1e-6 / 0.5 / np.sqrt(12)], rtol=1e-9)

"""The printed precision of table columns and the response error that rounded factor prints add."""

import numpy as np
import pytest

from demid.precision import factor_print_quantum, factor_round_off_sd, printed_quantum


@pytest.mark.parametrize("column, quantum", [
    ([10.1235, 3.2, 7.0], 1e-4),            # fixed decimals: the finest place of the column
    ([79.9, 80.25, 81.0], 1e-2),
    ([1200.0, 1300.0, 1250.0], 1.0),        # never coarser than units when reading decimals
    ([0.5, 1.25, 2.0], 1e-2),
    ([2.0, 3.0, 5.0], 1.0),                  # one significant digit each
    ([0.2, 0.5, 0.7], 0.1),
    ([1.25, 2.75, 13.15, 12.35, 4.0], 1e-2),  # most show two decimals; 4.0 lost its zeros, not a digit
])
def test_a_column_printed_to_decimals_is_read_to_its_finest_place(column, quantum):
    np.testing.assert_allclose(printed_quantum(column), quantum, rtol=1e-12)


def test_a_column_printed_to_significant_digits_is_read_per_value():
    # four significant digits: -1228 to units, 29.18 to hundredths, 0.5012 to 1e-4
    out = printed_quantum([-1228.0, 29.18, 0.5012, 345.6])
    np.testing.assert_allclose(out, [1.0, 1e-2, 1e-4, 1e-1], rtol=1e-12)
    # 12.30 printed to four digits lost its trailing zero: still read to hundredths
    out = printed_quantum([-1228.0, 29.18, 0.5012, 345.6, 12.3])
    np.testing.assert_allclose(out, [1.0, 1e-2, 1e-4, 1e-1, 1e-2], rtol=1e-12)


def test_zeros_nans_and_unrounded_values_carry_no_quantum():
    np.testing.assert_array_equal(printed_quantum([0.0, np.nan, 1.5]), [0.0, 0.0, 0.1])
    assert np.all(printed_quantum([np.nan, 0.0]) == 0.0)


def test_factor_quantum_only_for_values_that_reach_the_printed_place():
    x = np.array([0.075736, 0.5, 2.0, 0.924264])
    np.testing.assert_allclose(factor_print_quantum(x), [1e-6, 0.0, 0.0, 1e-6], rtol=1e-12)
    # a level at zero carries no rounding and leaves the others' alone
    np.testing.assert_allclose(factor_print_quantum([0.0, 0.075736, 0.924264]), [0.0, 1e-6, 1e-6], rtol=1e-12)
    # a column printed to three significant digits is no rounding of a derived level
    assert np.all(factor_print_quantum([0.0757, 0.5, 0.924]) == 0.0)


def test_round_off_sd_is_the_gradient_times_a_uniform_rounding_error():
    x = np.array([[0.075736, 10.5], [0.924264, 20.25], [0.5, 15.0]])
    gradient = np.array([[2.0, -1.0], [4.0, 3.0], [1.0, 1.0]])  # coded units per coded unit
    unit = [0.5, 5.0]
    sd = factor_round_off_sd(gradient, x, unit, [False, False])
    q0 = factor_print_quantum(x[:, 0])
    q1 = factor_print_quantum(x[:, 1])
    expected = np.sqrt((gradient[:, 0] * q0 / 0.5) ** 2 / 12 + (gradient[:, 1] * q1 / 5.0) ** 2 / 12)
    np.testing.assert_allclose(sd, expected, rtol=1e-12)
    assert sd[0] == pytest.approx(np.sqrt((2.0 * 1e-6 / 0.5) ** 2 / 12), rel=1e-9)
    # in log10 units a rounding q at x is q / (x ln 10)
    log_sd = factor_round_off_sd(gradient[:, :1], x[:, :1], [0.5], [True])
    assert log_sd[0] == pytest.approx(2.0 * (1e-6 / (0.075736 * np.log(10))) / 0.5 / np.sqrt(12), rel=1e-9)


@pytest.mark.parametrize("value, text", [(12.34, "10"), (0.0345, "0.03"), (1234.0, "1000"), (-9.8766, "−10"),
                                         (0.96, "1"), (0.0, "0"), (float("nan"), "–"), (2.5e7, "2e+07")])
def test_a_number_off_a_surrogate_that_does_not_predict_keeps_one_significant_digit(value, text):
    from demid.precision import rough_text

    assert rough_text(value) == text

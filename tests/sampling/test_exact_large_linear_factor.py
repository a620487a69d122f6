"""A linear factor in large units (a modulus in Pa) beside a log-scale one: the exact set's points in actual units
are the linear values as they are and 10 ** z of the log ones, without overflow (warnings are errors here)."""

import numpy as np
import pytest

from demid.sampling.exact import ExactSet

LINEAR_PA = [5.0e8, 3.2e9, 7.0e2]  # 10 ** these overflows
LOG10 = [-2.0, 1.5, 0.0]


def _exact(log):
    exact = ExactSet.__new__(ExactSet)  # to_actual reads only the log flags
    object.__setattr__(exact, "log", log)
    return exact


@pytest.mark.parametrize("log, columns", [((False, True), (LINEAR_PA, LOG10)), ((True, False), (LOG10, LINEAR_PA)),
                                          ((False, False), (LINEAR_PA, [400.0, 1.0e6, -3.0]))])
def test_to_actual_takes_ten_to_the_power_only_of_log_factors(log, columns):
    z = np.column_stack(columns)
    want = np.column_stack([10.0 ** np.array(c) if flag else np.array(c) for flag, c in zip(log, columns)])
    np.testing.assert_array_equal(_exact(log).to_actual(z), want)
    np.testing.assert_array_equal(_exact(log).to_actual(z[0]), want[0])  # one point, 1-d
    np.testing.assert_array_equal(z, np.column_stack(columns))  # the caller's array is left as it was

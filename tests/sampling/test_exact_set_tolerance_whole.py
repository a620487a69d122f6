"""A relative tolerance written as a whole number (1, i.e. 100 %) gives the exact set's table of the same
tolerance written as a float: a float tolerance column and every other column alike, against the closed form of a
band |x0 + x1| <= 10 in the box [-20, 20]^2 (its area 700 of 1600, the reference point (15, 15) at (10, 10)
from its nearest point (5, 5))."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from demid.sampling.exact import Polynomial, exact_set


def _frame(tolerance):
    plane = Polynomial(np.array([[0, 0], [1, 0], [0, 1]]), np.array([10.0, 1.0, 1.0]))  # 10 + x0 + x1, target 10
    return exact_set([plane], [10.0], tolerance, [-20.0, -20.0], [20.0, 20.0], reference=[15.0, 15.0]).to_frame()


def test_a_whole_number_tolerance_gives_the_table_of_the_same_float_tolerance():
    whole, real = _frame(1), _frame(1.0)
    pd.testing.assert_frame_equal(whole, real)
    assert whole["tolerance"].dtype == np.float64 and (whole["tolerance"] == 1.0).all()
    assert whole["feasible_fraction"].to_numpy() == pytest.approx(700.0 / 1600.0, abs=1e-9)
    assert whole["reference_distance"].to_numpy() == pytest.approx(np.hypot(10.0, 10.0) / 40.0)
    assert whole["nearest_point"].to_numpy() == pytest.approx([5.0, 5.0], abs=1e-6)

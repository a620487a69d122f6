"""A relative tolerance written as a whole number (1, i.e. 100 %) gives the grid set's table of the same tolerance
written as a float (demid.sampling.grid.admissible_set): a float tolerance column and every other column alike,
against the closed form of the band |x0 + x1| <= 10 (a surface 10 + x0 + x1, target 10) in the box [-20, 20]^2:
its area 700 of 1600, its span the whole box on either axis (a straight band: the plane rule measures its cells
exactly)."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from demid.sampling import Domain
from demid.sampling.grid import admissible_set
from demid.surrogate import Surrogate

_PLANE = Surrogate("y", ["a", "b"], [(0, 0), (1, 0), (0, 1)], np.array([10.0, 1.0, 1.0]), np.eye(3), 0.1, 10)
_BOX = Domain(("a", "b"), (-20.0, -20.0), (20.0, 20.0))


def _frame(tolerance):
    return admissible_set({"y": _PLANE}, _BOX, ["y"], {"y": 10.0}, tolerance, 21).to_frame()


def test_a_whole_number_tolerance_gives_the_grid_table_of_the_same_float_tolerance():
    whole, real = _frame(1), _frame(1.0)
    pd.testing.assert_frame_equal(whole, real)
    assert whole["tolerance"].dtype == np.float64 and (whole["tolerance"] == 1.0).all()
    assert whole["feasible_fraction_pct"].to_numpy() == pytest.approx(100.0 * 700.0 / 1600.0, abs=1e-9)
    assert whole["lower"].to_numpy() == pytest.approx([-20.0, -20.0])
    assert whole["upper"].to_numpy() == pytest.approx([20.0, 20.0])

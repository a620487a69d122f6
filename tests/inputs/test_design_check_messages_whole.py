"""Two refusals of the design check with every number they quote read back: a log-scale factor's cell off its
level names the nearest level in the factor's own units (10 to the coded level's log10 value, when no other run
prints that level), and a CCD with two points run twice beside one empty point is a replicated design, not a
factor value typed as another level (a slip moves one run: it leaves one empty point per repeat)."""

from __future__ import annotations

import re

import numpy as np
import pandas as pd
import pytest

from demid.design import ccd_points
from demid.design_check import check_design
from demid.errors import InputError

ALPHA = 1.41421
DESIGN = {"type": "ccd", "alpha": ALPHA, "center_runs": 3}


@pytest.mark.parametrize("log_centre, log_unit, side", [(np.log10(250.0), 0.5, 1.0), (-2.0, 0.25, -1.0)])
def test_a_log_factors_cell_off_its_axial_level_is_told_the_level_in_its_own_units(log_centre, log_unit, side):
    coded = ccd_points(2, ALPHA, 3)
    x2 = np.array([float(f"{v:.6g}") for v in 10 ** (log_centre + coded[:, 1] * log_unit)])
    row = int(np.flatnonzero(np.isclose(coded[:, 1], side * ALPHA))[0])
    # the axial run's value typed 30 % further out: no other run holds that level
    x2[row] = float(f"{x2[row] * 1.3 ** side:.6g}")
    table = pd.DataFrame({"run": np.arange(1, len(coded) + 1), "x1": 5 + 2 * coded[:, 0], "x2": x2})
    with pytest.raises(InputError) as info:
        check_design(table, ["x1", "x2"], DESIGN, "t.csv", "design", log_factors=("x2",))
    said = re.search(r"value (\S+) is not a level .* nearest valid level: (\S+) \(coded ([+-][\d.]+)\)",
                     str(info.value))
    assert said and info.value.run == row + 1 and info.value.column == "x2", str(info.value)
    assert float(said.group(1)) == pytest.approx(x2[row], rel=1e-5)
    assert float(said.group(2)) == pytest.approx(10 ** (log_centre + side * ALPHA * log_unit), rel=2e-5)
    assert float(said.group(3)) == pytest.approx(side * ALPHA, abs=1e-3)


def test_two_points_run_twice_beside_one_empty_point_are_a_replicated_design_not_a_slip():
    points = [tuple(p) for p in ccd_points(2, ALPHA, 3)]
    points[points.index((1.0, 1.0))] = (-1.0, 1.0)  # one slip would leave (1, 1) empty ...
    points.append((1.0, -1.0))  # ... but (1, -1) is run twice too: more repeats than empty points
    coded = np.array(points)
    table = pd.DataFrame({"run": np.arange(1, len(coded) + 1), "x1": 5 + 2 * coded[:, 0], "x2": 20 + 3 * coded[:, 1]})
    with pytest.raises(InputError) as info:
        check_design(table, ["x1", "x2"], DESIGN, "t.csv", "design")
    assert str(info.value) == ("t.csv, runs 2 and 12: both are the point (x1 7, x2 17), which a CCD runs once; the "
                               "design's point (x1 7, x2 23) has no run")

"""Input checks at their edges: a level whose usual value is held by exactly two runs, and runs on three levels
per factor that form no standard design (the whole inferred design, centre runs included)."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from demid.design_check import odd_level_values
from demid.design_inference import InferredDesign, infer_design


def test_a_value_off_a_level_whose_usual_value_two_runs_hold_is_warned_about():
    """Two runs make a usual value: 0.5003 beside two runs reading 0.5 is named; two runs that disagree
    (a tie) and a level of one run are not."""
    snapped = np.array([[0.0], [0.0], [0.0], [1.0], [1.0], [-1.0]])
    values = [0.5, 0.5003, 0.5, 0.9, 0.9004, 0.1]
    table = pd.DataFrame({"run": [11, 12, 13, 14, 15, 16], "x": values})
    assert odd_level_values(table, ["x"], snapped, "t.csv") == [
        "t.csv, run 12, column 'x': 0.5003, where the other 2 runs at this level read 0.5 (fitted as recorded; "
        "a typo?)"]


@pytest.mark.parametrize("points", [
    [(-1, -1), (1, 1), (0, 1), (0, 0), (1, 0), (0, 0)],
    [(-1, -1), (1, 1), (-1, 1), (0, 1), (0, 0), (0, 0), (1, 0)],
])
def test_three_levels_per_factor_in_no_family_are_a_custom_design_without_centre_runs(points):
    """Runs on three evenly spaced levels of each factor whose points are no family (too many of a 3^2
    factorial's missing): custom, alpha 1 for each factor and no centre runs counted, as for any custom design,
    even where runs sit at the centre."""
    table = pd.DataFrame({"run": range(1, len(points) + 1), "a": [10 + 2 * p[0] for p in points],
                          "b": [3 + 0.5 * p[1] for p in points]})
    inferred = infer_design(table, ["a", "b"], "t.csv")
    assert inferred == InferredDesign("custom", ("a", "b"), (1.0, 1.0), 0)
    assert inferred.design == {"type": "custom", "alpha": (1.0, 1.0), "center_runs": 0, "inferred": True}

"""Level 2's best point (criticism.level2._best_point) on responses no factor moves, where every weighted error is
a known constant: the largest is the best point's error, and the targets are met together ("feasible") when it is
at most the tolerance plus 1e-12 -- tested exactly at the tolerance, inside the 1e-12 slack, exactly at
tolerance + 1e-12 and one step past it, with signed errors, 1-4 observables and unequal weights."""

from __future__ import annotations

import numpy as np
import pytest

from demid.criticism.level2 import _best_point
from tests.criticism.test_bottleneck_slack_whole import _problem, _tolerance

CASES = [([0.1, -0.2, 0.4], [1.0, 1.0, 1.0]), ([-0.05, 0.3, -0.6, 0.15], [1.0, 0.5, 2.0, 1.0]),
         ([0.25, -0.35], [1.0, 1.0]), ([-0.3], [1.0])]


@pytest.mark.parametrize("errors,weights", CASES)
@pytest.mark.parametrize("where", ["at", "inside", "at_slack", "past"])
def test_feasible_up_to_the_tolerance_and_its_slack(errors, weights, where):
    weights = np.asarray(weights)
    problem, grid_s, grid_err = _problem(errors, weights)
    worst = float(np.max(weights * np.abs(grid_err[:, 0])))
    assert worst == pytest.approx(float(np.max(weights * np.abs(errors))), rel=1e-12)
    tol = _tolerance(worst, where)
    assert (tol + 1e-12 < worst) == (where == "past")
    best_val, best_s, feasible, unmoved, movable = _best_point(problem, grid_s, grid_err, tol, None)
    assert best_val == worst
    assert bool(feasible) == (where != "past")  # calibration_check reports bool(feasible)
    assert unmoved == list(range(len(errors))) and movable == []
    assert best_s.shape == (2,) and np.all((0.0 <= best_s) & (best_s <= 1.0))

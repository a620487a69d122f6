"""A straight response beyond a bound: its second difference is round-off, never curvature. Moving away from its
target it "does not approach" the target (no crossing 1e10 ranges out); moving towards it, it reaches the band where
the straight line does -- over responses of sizes 1e-3 to 1e6, ranges away from zero, either side."""

from __future__ import annotations

import math

import numpy as np
import pytest

from demid.criticism.reach import reach_beyond_bound, saturation_finding
from demid.sampling.domain import Domain


class _Straight:
    def __init__(self, a, b):
        self.a, self.b = a, b

    def predict(self, x):
        x = np.atleast_2d(x)
        return self.a + self.b * x[:, 0] + 0.0 * x[:, 1]


@pytest.mark.parametrize("scale", [1e-3, 1.0, 37.0, 1e6])
@pytest.mark.parametrize("side", ["lower", "upper"])
@pytest.mark.parametrize("lower, upper", [(0.1, 0.9), (1003.0, 1011.0), (-7.3, -2.1)])
def test_a_straight_response_moving_away_does_not_approach_its_target(scale, side, lower, upper):
    domain = Domain(("x", "w"), (lower, 0.0), (upper, 1.0))
    slope = 0.37 * scale / (upper - lower)
    surrogate = _Straight(scale * 3.1 - slope * lower, slope)  # rises with x over the range
    bound = upper if side == "upper" else lower
    value = surrogate.predict([[bound, 0.5]])[0]
    # a target the response moves away from beyond this bound: above it at the lower bound, below at the upper
    target = value - 0.8 * scale if side == "upper" else value + 0.8 * scale
    r = reach_beyond_bound(surrogate, domain, "x", side, {"x": bound, "w": 0.5}, "y", target, 0.01)
    assert r.curvature == 0.0
    assert math.isinf(r.quadratic_extension) and math.isinf(r.straight_extension) and not r.widen
    assert "does not approach its target" in saturation_finding(r, "x", "y")


@pytest.mark.parametrize("scale", [1e-3, 1.0, 1e6])
@pytest.mark.parametrize("side", ["lower", "upper"])
def test_a_straight_response_moving_towards_its_target_reaches_it_where_the_line_does(scale, side):
    lower, upper = 1003.0, 1011.0
    domain = Domain(("x", "w"), (lower, 0.0), (upper, 1.0))
    slope = 0.37 * scale / (upper - lower)
    surrogate = _Straight(scale * 3.1 - slope * lower, slope)
    bound = upper if side == "upper" else lower
    value = surrogate.predict([[bound, 0.5]])[0]
    target = value + 0.2 * scale if side == "upper" else value - 0.2 * scale
    edge = target - math.copysign(0.01 * abs(target), target - value)
    r = reach_beyond_bound(surrogate, domain, "x", side, {"x": bound, "w": 0.5}, "y", target, 0.01)
    expected = abs(edge - value) / (slope * (upper - lower))  # fraction of the range beyond the bound
    assert r.curvature == 0.0
    assert r.quadratic_extension == pytest.approx(expected, rel=1e-6)
    assert r.straight_extension == pytest.approx(expected, rel=1e-6)

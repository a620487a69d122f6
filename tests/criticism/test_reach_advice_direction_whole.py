"""What the advice not to widen a bound says the response does there: "gains only" exactly when it moves towards
its target going outwards (the derivative at the bound, written out here, times the outward direction and the sign
of what is missing, strictly positive) -- which is also exactly when a straight line reaches the band -- and
"moves away by" otherwise, a response at its stationary point on the bound (slope exactly 0) included: it gains
nothing there.  Both sides, targets above and below, curvature towards and away, bounds at and away from 0."""
from __future__ import annotations

import itertools
import math
import re

import numpy as np

from demid.criticism.models import short_number
from demid.criticism.reach import reach_beyond_bound, saturation_advice
from demid.sampling.domain import Domain


class _Quadratic:
    """y = a + b x + c x^2 in factor x, plus 0.2 w."""

    def __init__(self, a, b, c):
        self.a, self.b, self.c = a, b, c

    def predict(self, points):
        p = np.atleast_2d(points)
        return self.a + self.b * p[:, 0] + self.c * p[:, 0] ** 2 + 0.2 * p[:, 1]


def test_the_advice_says_gains_only_exactly_when_the_response_moves_towards_its_target():
    seen = set()
    for (lower, upper), side, b, c, shift in itertools.product(
            [(-2.0, 0.0), (0.0, 3.0), (1.5, 4.0)], ["lower", "upper"], [0.0, 0.7, -1.3], [0.0, 0.4, -0.9],
            [6.0, -6.0, 60.0, -60.0]):
        bound = upper if side == "upper" else lower
        outward = 1.0 if side == "upper" else -1.0
        sur = _Quadratic(10.0, b, c)
        domain = Domain(("x", "w"), (lower, 0.0), (upper, 1.0))
        f0 = 10.0 + b * bound + c * bound ** 2 + 0.2 * 0.5
        target = f0 + shift
        r = reach_beyond_bound(sur, domain, "x", side, {"x": bound, "w": 0.5}, "y", target, 0.01)
        if r.flat:
            continue  # level 2 sets a bound along which nothing moves aside before any advice
        derivative = b + 2 * c * bound  # d y / d x at the bound
        toward = outward * derivative * (target - f0) > 0
        advice = saturation_advice(r, "x", "y")
        word, number = re.search(r"at the bound y (gains only|moves away by) (\S+) per unit x", advice).groups()
        assert word == ("gains only" if toward else "moves away by"), (lower, upper, side, b, c, shift)
        assert toward == math.isfinite(r.straight_extension)
        assert number == short_number(abs(derivative))
        seen.add((toward, derivative == 0.0))
    assert seen == {(True, False), (False, False), (False, True)}  # a stationary point on the bound among them

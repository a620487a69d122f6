"""Reach beyond a bound of a fitted polynomial whose prediction near the bound is a small difference of large terms.
The round-off of each prediction is relative to its terms, not to its value: y = 1.1 (x - 1011) on 1003-1011 is 0
at the bound, summed from terms of 1112, and its second difference there is round-off, never curvature.  A real
curvature a few times that round-off is kept, and moving the factor's origin or changing its units changes no
field of the result read in fractions of the range (the verdict, the extensions, the curvature)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from demid.criticism.reach import reach_beyond_bound, saturation_finding, terms_size
from demid.sampling.domain import Domain
from demid.surrogate import Surrogate

_TERMS = [(0, 0), (1, 0), (0, 1), (2, 0), (1, 1), (0, 2)]
_EPS = np.finfo(float).eps


def _quadratic_in_x(intercept, linear, square, w_coefficient=0.0):
    """The polynomial surrogate intercept + linear x + square x^2 + w_coefficient w (factors x, w)."""
    beta = np.array([intercept, linear, w_coefficient, square, 0.0, 0.0])
    return Surrogate("y", ["x", "w"], list(_TERMS), beta, np.eye(6), 1.0, 4)


def _along_t(y0, g, c, bound, width, outward):
    """The surrogate y = y0 + g t + c t^2 / 2 in t = outward (x - bound) / width, written in x's own terms."""
    # t = p x + q with p = outward / width, q = -outward bound / width
    p, q = outward / width, -outward * bound / width
    return _quadratic_in_x(y0 + g * q + c * q * q / 2, g * p + c * p * q, c * p * p / 2)


def test_terms_size_is_the_sum_of_the_terms_absolute_values():
    sur = _quadratic_in_x(-1112.1, 1.1, 0.25, w_coefficient=-3.0)
    points = np.array([[1011.0, 0.5], [-2.0, 4.0]])
    expected = [1112.1 + 1.1 * 1011 + 0.25 * 1011 ** 2 + 1.5, 1112.1 + 2.2 + 1.0 + 12.0]
    assert terms_size(sur, points) == pytest.approx(expected, rel=1e-14)


def test_a_straight_response_zero_at_its_bound_does_not_come_back_to_its_target():
    domain = Domain(("x", "w"), (1003.0, 0.0), (1011.0, 1.0))
    sur = _quadratic_in_x(-1.1 * 1011, 1.1, 0.0)
    r = reach_beyond_bound(sur, domain, "x", "upper", {"x": 1011.0, "w": 0.5}, "y", -4.0, 0.01)
    assert abs(r.value) < 1e-9
    assert r.curvature == 0.0
    assert r.slope == pytest.approx(1.1, rel=1e-9)
    assert math.isinf(r.straight_extension) and math.isinf(r.quadratic_extension)
    assert math.isinf(r.levels_off_extension) and math.isnan(r.quadratic_factor_value) and not r.widen
    assert "does not approach its target" in saturation_finding(r, "x", "y")


def _floor(sur, bound, width, outward):
    """The round-off floor of the curvature at ``bound``: 64 epsilons of the largest terms' size, over step^2."""
    xs = bound + outward * np.array([-0.01, 0.0, 0.01]) * width
    size = max(abs(sur.coefficients[0]) + abs(sur.coefficients[1] * x) + abs(sur.coefficients[3] * x * x)
               for x in xs)
    return 64 * _EPS * size / 0.01 ** 2


@pytest.mark.parametrize("times", [4.0, -4.0])
def test_a_real_curvature_a_few_times_the_round_off_is_kept(times):
    bound, width = 1011.0, 8.0
    domain = Domain(("x", "w"), (1003.0, 0.0), (bound, 1.0))
    straight = _along_t(0.0, 8.8, 0.0, bound, width, 1.0)
    c = times * _floor(straight, bound, width, 1.0)  # about 3e-7 times four: far above the 2e-9 of round-off
    sur = _along_t(0.0, 8.8, c, bound, width, 1.0)
    r = reach_beyond_bound(sur, domain, "x", "upper", {"x": bound, "w": 0.5}, "y", -4.0, 0.01)
    assert r.curvature == pytest.approx(c, rel=0.02)
    # moving away at 8.8 per range: a curvature bending back (c < 0) meets the band edge -3.96 at the root
    expected = (8.8 + math.sqrt(8.8 ** 2 - 2 * c * 3.96)) / -c if c < 0 else math.inf
    assert r.quadratic_extension == pytest.approx(expected, rel=0.02)


@pytest.mark.parametrize("fraction", [0.25, -0.25])
def test_a_curvature_well_inside_the_round_off_is_taken_as_none(fraction):
    """A quarter of the floor: indistinguishable from the round-off of terms of 2224, reported as a straight line."""
    bound, width = 1011.0, 8.0
    domain = Domain(("x", "w"), (1003.0, 0.0), (bound, 1.0))
    straight = _along_t(0.0, 8.8, 0.0, bound, width, 1.0)
    sur = _along_t(0.0, 8.8, fraction * _floor(straight, bound, width, 1.0), bound, width, 1.0)
    r = reach_beyond_bound(sur, domain, "x", "upper", {"x": bound, "w": 0.5}, "y", -4.0, 0.01)
    assert r.curvature == 0.0 and math.isinf(r.quadratic_extension)


_SHAPES = [  # (y0, g, c, target): value, slope and curvature outwards (per fraction of the range), and the target
    (0.0, 8.8, 0.0, -4.0),     # straight, zero at the bound, moving away
    (0.0, -8.8, 0.0, -4.0),    # straight, zero at the bound, moving towards
    (2.0, 3.0, -4.0, 5.0),     # rising, levelling off below the target
    (2.0, 3.0, 2.5, 5.0),      # rising, curving up into the band
    (-1.0, -0.5, -1.5, -2.0),  # falling and curving down: reaches the band of a negative target
]


@pytest.mark.parametrize("shape", _SHAPES)
@pytest.mark.parametrize("side", ["lower", "upper"])
def test_moving_the_origin_or_the_units_of_the_factor_changes_nothing_read(shape, side):
    y0, g, c, target = shape
    outward = 1.0 if side == "upper" else -1.0
    results = []
    for origin_in_ranges in (-126.0, 0.0, 0.5, 126.0):
        for width in (1e-3, 8.0, 1e4):
            lower = origin_in_ranges * width
            domain = Domain(("x", "w"), (lower, 0.0), (lower + width, 1.0))
            bound = lower + width if side == "upper" else lower
            sur = _along_t(y0, g, c, bound, width, outward)
            r = reach_beyond_bound(sur, domain, "x", side, {"x": bound, "w": 0.5}, "y", target, 0.01)
            results.append(((origin_in_ranges, width), r))
    first = results[0][1]
    for where, r in results:
        assert (r.widen, r.levels_off, math.isfinite(r.straight_extension),
                math.isfinite(r.quadratic_extension)) == (first.widen, first.levels_off,
                                                          math.isfinite(first.straight_extension),
                                                          math.isfinite(first.quadratic_extension)), where
        if c == 0.0:
            assert r.curvature == 0.0, where
        else:
            assert r.curvature == pytest.approx(c, rel=1e-6), where
        for field in ("straight_extension", "quadratic_extension", "levels_off_extension"):
            assert getattr(r, field) == pytest.approx(getattr(first, field), rel=1e-6), (where, field)
        assert r.value == pytest.approx(y0, abs=1e-9)
        assert r.slope * outward * where[1] == pytest.approx(g, rel=1e-6), where

"""Reach beyond a bound on a kriging surrogate (not a polynomial: its round-off floor is relative to the size of its
predictions).  Universal kriging's quadratic trend fits a response that is exactly straight or exactly quadratic in
the factor's search units, so along the factor the surrogate is that polynomial to round-off, and every field is
known in closed form: a straight response's second difference is round-off (curvature 0, never back in its band
1e9 ranges out), on predictions of either sign, either side, linear and log factors; a real curvature is kept."""

from __future__ import annotations

import math

import numpy as np
import pytest

from demid.criticism.reach import WIDEN_LIMIT, reach_beyond_bound
from demid.kriging import KrigingSurrogate
from demid.sampling.domain import Domain

_LEVELS = (-1.0, -0.5, 0.0, 0.5, 1.0)


def _kriging(level, slope, square, log):
    """Kriging of y = level + slope s + square s^2 + 0.3 w (s: x in search units) on a 5 x 3 grid over x in
    [2, 8] (linear) or [1, 100] (log) and w in [0, 1]."""
    lo_s, hi_s = (0.0, 2.0) if log else (2.0, 8.0)
    s = np.repeat([(lo_s + hi_s) / 2 + (hi_s - lo_s) / 2 * u for u in _LEVELS], 3)
    w = np.tile([0.0, 0.5, 1.0], len(_LEVELS))
    x = np.column_stack([10 ** s if log else s, w])
    y = level + slope * s + square * s * s + 0.3 * w
    sur = KrigingSurrogate("y", ["x", "w"], x, y, np.array([lo_s, 0.0]), np.array([hi_s, 1.0]),
                           np.array([0.8, 0.9]), 1e-8, ("x",) if log else ())
    domain = Domain(("x", "w"), (1.0 if log else 2.0, 0.0), (100.0 if log else 8.0, 1.0), (log, False))
    return sur, domain, (lo_s, hi_s)


@pytest.mark.parametrize("log", [False, True])
@pytest.mark.parametrize("level", [-5000.0, 5000.0, -20000.0])
def test_a_straight_kriging_response_has_no_curvature_and_reaches_its_band_in_closed_form(level, log):
    slope = 7.0 if level != 5000.0 else -7.0
    sur, domain, (lo_s, hi_s) = _kriging(level, slope, 0.0, log)
    width = hi_s - lo_s
    for side in ("lower", "upper"):
        outward = 1.0 if side == "upper" else -1.0
        bound_s = hi_s if side == "upper" else lo_s
        for w in (0.1, 0.37, 0.5, 0.83, 0.95):
            f0 = level + slope * bound_s + 0.3 * w
            rate = outward * slope * width  # d y / d t outwards, t the fraction of the range
            for shift in (-3.0, 3.0, -0.4 * abs(rate), 0.4 * abs(rate), 0.7 * abs(rate)):
                target = f0 + shift
                tolerance = 0.1 * abs(shift) / abs(target)  # the band's edge 0.9 of the shift away
                point = {"x": 10 ** bound_s if log else bound_s, "w": w}
                r = reach_beyond_bound(sur, domain, "x", side, point, "y", target, tolerance)
                assert r.curvature == 0.0  # round-off of predictions of 5000-20000, not curvature
                assert r.value == pytest.approx(f0, rel=1e-11)
                assert r.slope == pytest.approx(slope, rel=1e-8)  # per actual unit (per decade if log)
                assert r.band_edge == pytest.approx(f0 + 0.9 * shift, rel=1e-12)
                assert math.isinf(r.levels_off_extension) and math.isnan(r.levels_off_value)
                if shift * rate > 0:  # towards the target: a straight line and its quadratic agree
                    need = 0.9 * shift / rate
                    assert r.straight_extension == pytest.approx(need, rel=1e-7)
                    assert r.quadratic_extension == pytest.approx(need, rel=1e-7)
                    assert r.widen == (need <= WIDEN_LIMIT)
                    at = bound_s + outward * need * width
                    assert r.quadratic_factor_value == pytest.approx(10 ** at if log else at, rel=1e-7)
                else:  # moving away: it never comes back
                    assert math.isinf(r.straight_extension) and math.isinf(r.quadratic_extension)
                    assert math.isnan(r.quadratic_factor_value) and not r.widen


@pytest.mark.parametrize("square", [-40.0, 25.0])
def test_a_curved_kriging_response_keeps_its_curvature(square):
    sur, domain, (lo_s, hi_s) = _kriging(-5000.0, 7.0, square, False)
    width = hi_s - lo_s
    for side in ("lower", "upper"):
        r = reach_beyond_bound(sur, domain, "x", side, {"x": hi_s if side == "upper" else lo_s, "w": 0.5}, "y",
                               -4000.0, 0.01)
        assert r.curvature == pytest.approx(2 * square * width ** 2, rel=1e-6)  # d^2 y / d t^2

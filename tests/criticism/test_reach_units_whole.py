"""Reach beyond a bound (criticism.reach) whatever the observable's units: the same response written in units 1e-4
to 1e3 times as large gives the same extensions, the same verdict (levels off, widen) and the same advice words,
with its value, slope, curvature and levelling-off value scaled.  Shapes with slopes, curvatures and misses below 1
(per range, in any units) approaching the band slowly and levelling off, bending towards it or away, moving away
from it, on either side; each field against the closed form of f(t) = f0 + g t + k t^2 / 2 (t: fraction of the
range beyond the bound), and the advice's "gains only" / "moves away by" against the direction the response moves."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

from demid.criticism.models import short_number
from demid.criticism.reach import WIDEN_LIMIT, reach_beyond_bound, saturation_advice
from demid.sampling.domain import Domain
from tests.criticism.test_reach_terms_floor_whole import _along_t
from tests.criticism.test_reach_whole import _closed_form

_SHAPES = [  # f0, g, k (outwards, per fraction of the range), target
    (0.2, 0.5, -0.6, 0.6),     # rising slowly, levelling off at 0.408 below the band
    (0.3, -0.4, 0.5, 0.2),     # falling slowly towards a lower target, bending back after the band
    (0.1, 0.3, 0.4, 0.9),      # rising slowly and bending up into the band
    (0.5, -0.2, 0.0, 0.9),     # straight, moving away from a higher target
    (0.5, 0.2, -0.3, 0.58),    # rising slowly to a near target, reached before it turns
    (-0.2, -0.5, 0.8, -0.9),   # falling towards a negative target, levelling off short of it
]


def _reach(shape, side, scale, tolerance=0.01):
    f0, g, k, target = (scale * v for v in shape)
    lower, upper = 2.0, 5.0
    outward = 1.0 if side == "upper" else -1.0
    bound = upper if side == "upper" else lower
    domain = Domain(("x", "w"), (lower, 0.0), (upper, 1.0))
    sur = _along_t(f0, g, k, bound, upper - lower, outward)
    return reach_beyond_bound(sur, domain, "x", side, {"x": bound, "w": 0.5}, "y", target, tolerance)


@pytest.mark.parametrize("shape", _SHAPES)
@pytest.mark.parametrize("side", ["lower", "upper"])
def test_the_observables_units_change_no_extension_verdict_or_word(shape, side):
    f0, g, k, target = shape
    direction = 1.0 if f0 < target else -1.0
    edge = target - direction * 0.01 * abs(target)
    straight, quadratic, turn = _closed_form((f0, g, k), edge, direction)
    level = f0 + g * turn + k * turn ** 2 / 2 if np.isfinite(turn) else math.nan
    outward = 1.0 if side == "upper" else -1.0
    toward = g * direction > 0  # the response moves towards the target going outwards
    for scale in (1e-4, 1e-2, 1.0, 1e3):
        r = _reach(shape, side, scale)
        assert r.value == pytest.approx(scale * f0, rel=1e-9)
        assert r.slope == pytest.approx(scale * outward * g / 3.0, rel=1e-9)
        assert r.curvature == pytest.approx(scale * k, rel=1e-6, abs=1e-12 * scale)
        assert r.band_edge == pytest.approx(scale * edge, rel=1e-12)
        for got, want in ((r.straight_extension, straight), (r.quadratic_extension, quadratic),
                          (r.levels_off_extension, turn)):
            assert got == pytest.approx(want, rel=1e-6) if math.isfinite(want) else got == math.inf, (scale, got, want)
        if math.isfinite(level):
            assert r.levels_off_value == pytest.approx(scale * level, rel=1e-6)
        else:
            assert math.isnan(r.levels_off_value)
        assert r.levels_off == (math.isfinite(turn) and not math.isfinite(quadratic))
        assert r.widen == (quadratic <= WIDEN_LIMIT)
        advice = saturation_advice(r, "x", "y")
        word = re.search(r"at the bound y (gains only|moves away by) ([-\d.e+]+) per unit x", advice)
        assert word.group(1) == ("gains only" if toward else "moves away by"), (scale, advice)
        assert word.group(2) == short_number(abs(r.slope))
        assert f"The missing {short_number(abs(scale * (target - f0)))} of y" in advice

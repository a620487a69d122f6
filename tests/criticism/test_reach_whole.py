"""Reach beyond a bound (criticism.reach) read whole over generated quadratic responses along one factor: either
side, linear or log factor, ranges away from zero, rising or falling responses, targets of either sign above or
below, curvature that helps, hurts or turns the response back, physical limits near or far.  With the response
a quadratic in t (the fraction of the range beyond the bound), every field is solved here in closed form (numpy's
polynomial roots) and every number the finding and the advice quote is parsed back."""

from __future__ import annotations

import re

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from demid.criticism.models import short_number
from demid.criticism.reach import WIDEN_LIMIT, reach_beyond_bound, saturation_advice, saturation_finding
from demid.sampling.domain import Domain


class _AlongFactor:
    """y = a + b s + c s^2 in the search units s of factor 0 (log10 for a log factor), plus 0.3 times factor 1."""

    def __init__(self, a, b, c, log):
        self.a, self.b, self.c, self.log = a, b, c, log

    def predict(self, x):
        x = np.atleast_2d(x)
        s = np.log10(x[:, 0]) if self.log else x[:, 0]
        return self.a + self.b * s + self.c * s * s + 0.3 * x[:, 1]


def _closed_form(f, edge, direction):
    """(straight, quadratic, turn) extensions of f(t) = f0 + g t + k t^2 / 2 towards ``edge``."""
    f0, g, k = f
    rate, bend = direction * g, direction * k
    gap = direction * (edge - f0)
    straight = gap / rate if rate > 0 else np.inf
    roots = np.roots([k / 2, g, f0 - edge]) if abs(k) > 1e-9 else np.roots([g, f0 - edge])
    positive = [float(r.real) for r in np.atleast_1d(roots) if abs(r.imag) < 1e-12 and r.real > 1e-12]
    quadratic = min(positive) if positive else np.inf
    turn = -rate / bend if rate > 0 and bend < 0 else np.inf
    return max(straight, 0.0), max(quadratic, 0.0), turn


@given(log=st.booleans(), side=st.sampled_from(["lower", "upper"]), start=st.floats(0.5, 20.0),
       span=st.floats(0.5, 3.0), b=st.floats(0.05, 5) | st.floats(-5, -0.05),
       c=st.floats(0.05, 3) | st.floats(-3, -0.05), target_shift=st.floats(2, 40) | st.floats(-40, -2),
       offset=st.sampled_from([-100.0, 0.0, 100.0]), limit_share=st.sampled_from([None, 0.0, 0.1, 0.8]),
       tolerance=st.sampled_from([0.01, 0.1]))
@settings(max_examples=60, deadline=None, derandomize=True)
def test_every_field_and_quoted_number_of_a_quadratic_reach(log, side, start, span, b, c, target_shift, offset,
                                                           limit_share, tolerance):
    lo_s, hi_s = (np.log10(start), np.log10(start) + span) if log else (start, start + 10 * span)
    lower, upper = (10 ** lo_s, 10 ** hi_s) if log else (lo_s, hi_s)
    width = hi_s - lo_s
    outward = 1.0 if side == "upper" else -1.0
    bound_s = hi_s if side == "upper" else lo_s
    limit = None
    if limit_share is not None:
        at = bound_s + outward * limit_share * width
        limit = 10 ** at if log else at
    limits = ((limit, None) if side == "lower" else (None, limit), (None, None))
    domain = Domain(("x", "w"), (lower, 0.0), (upper, 1.0), (log, False), limits)
    mid = (lo_s + hi_s) / 2
    surrogate = _AlongFactor(offset - b * mid / width * 10 - c * mid ** 2 / width ** 2 * 10,
                             b / width * 10, c / width ** 2 * 10, log)
    point = {"x": (lower + upper) / 2, "w": 0.4}
    f0 = float(surrogate.predict([[10 ** bound_s if log else bound_s, 0.4]])[0])
    target = f0 + target_shift
    assume(abs(target - f0) > 1.5 * tolerance * abs(target))  # the best point misses the band, as level 2 asks
    with np.errstate(over="ignore"):  # a log factor's value far beyond the bound is inf
        r = reach_beyond_bound(surrogate, domain, "x", side, point, "y", target, tolerance)

    # along t: s = bound + outward t width, so f(t) = f0 + g t + k t^2 / 2
    ds = outward * width
    g = (surrogate.b + 2 * surrogate.c * bound_s) * ds
    k = 2 * surrogate.c * ds ** 2
    direction = 1.0 if f0 < target else -1.0
    edge = target - direction * tolerance * abs(target)
    straight, quadratic, turn = _closed_form((f0, g, k), edge, direction)
    room = np.inf if limit is None else limit_share

    def factor_at(t):
        if not np.isfinite(t):
            return np.nan
        s = bound_s + outward * t * width
        with np.errstate(over="ignore"):
            return float(np.power(10.0, s)) if log else s

    assert (r.factor, r.side, r.observable, r.log) == ("x", side, "y", log)
    assert r.value == pytest.approx(f0, rel=1e-12, abs=1e-9) and r.target == target
    assert r.band_edge == pytest.approx(edge, rel=1e-12)
    assert r.slope == pytest.approx((surrogate.b + 2 * surrogate.c * bound_s), rel=1e-6, abs=1e-7)
    assert r.curvature == pytest.approx(k, rel=1e-5, abs=1e-6)
    for got, want in ((r.straight_extension, straight), (r.quadratic_extension, quadratic),
                      (r.levels_off_extension, turn), (r.limit_extension, room)):
        # a straight response's second difference is round-off: its root lies beyond any range (or none)
        assert got == pytest.approx(want, rel=1e-5, abs=1e-8) if np.isfinite(want) else got > 1e6, (got, want)
    level = f0 + g * turn + k * turn ** 2 / 2 if np.isfinite(turn) else np.nan
    for got, want in ((r.levels_off_value, level), (r.straight_factor_value, factor_at(straight)),
                      (r.quadratic_factor_value, factor_at(quadratic)), (r.levels_off_factor_value, factor_at(turn)),
                      (r.limit_value, factor_at(room))):
        if np.isfinite(want):
            assert got == pytest.approx(want, rel=1e-5, abs=1e-8), (got, want)
    assert np.isnan(r.limit_value) == (limit is None) and np.isnan(r.levels_off_value) == (not np.isfinite(turn))
    assert r.widen == bool(quadratic <= min(WIDEN_LIMIT, room) and room > 0.0)
    assert r.missing == pytest.approx(target - f0, rel=1e-12, abs=1e-12)
    _check_words(r, quadratic, turn, room, level)


def _check_words(r, quadratic, turn, room, level) -> None:
    """The finding and the advice: which sentence, and every number they quote."""
    finding, advice = saturation_finding(r, "x", "y", "kN"), saturation_advice(r, "x", "y", "kN")
    beyond = room <= 0.0 or room < quadratic < np.inf
    assert short_number(abs(r.target - r.value)) in advice and f"y = {short_number(r.target)} kN" in advice
    if beyond:
        assert f"{short_number(r.limit_value)}" in finding and "physical limit" in advice
        return
    levels_off = np.isfinite(turn) and not np.isfinite(quadratic)
    if levels_off and turn > room:
        assert f"up to the physical limit of x ({short_number(r.limit_value)})" in finding
    elif levels_off:
        assert f"levels off at {short_number(level)} kN (x ≈ {short_number(r.levels_off_factor_value)})" in finding
    elif np.isfinite(quadratic):
        quoted = re.search(r"only at x ≈ (\S+), (\d+) % of the range beyond", finding)
        assert quoted.group(1) == short_number(r.quadratic_factor_value)
        assert int(quoted.group(2)) == round(100 * quadratic)
    else:
        assert "does not approach its target" in finding
    toward = r.slope * (1 if r.side == "upper" else -1) * (1 if r.target > r.value else -1) > 0
    moves = re.search(r"at the bound y (gains only|moves away by) (\S+) kN per (decade of|unit) x", advice)
    assert moves.groups() == ("gains only" if toward else "moves away by", short_number(abs(r.slope)),
                              "decade of" if r.log else "unit")
    straight_said = re.search(r"a straight line would reach the target band at x ≈ (\S+)\.", advice)
    if np.isfinite(r.straight_factor_value) and r.straight_extension <= room:
        assert straight_said.group(1) == short_number(r.straight_factor_value)
    else:
        assert straight_said is None

"""A bound's reach at its physical limit, met exactly (criticism.reach): the surrogate reaching the band exactly at
the limit is not beyond it, a hair further is, a range already ending at the limit (room 0) is; a response that
levels off exactly at the limit levels off (the sentence quoting where), one that levels off beyond it stays short
up to the limit; the advice's straight-line sentence is kept when the line reaches the band exactly at the limit
and dropped beyond it; a range ending exactly at its limit is said to; a response at its peak exactly on the bound
(slope 0) does not approach a target above it and does not level off.  Each number the sentences quote read back."""

from __future__ import annotations

import dataclasses
import re

import numpy as np
import pytest

from demid.criticism.reach import Reach, saturation_advice, saturation_finding


def _reach(**changes) -> Reach:
    base = Reach(factor="a", side="upper", observable="y", value=10.0, target=14.0, band_edge=13.86, slope=2.5,
                 curvature=-1.0, straight_extension=0.3, quadratic_extension=0.4, levels_off_extension=np.inf,
                 levels_off_value=np.nan, straight_factor_value=1.6, quadratic_factor_value=1.8,
                 levels_off_factor_value=np.nan, widen=False, limit_extension=0.4, limit_value=1.8)
    return dataclasses.replace(base, **changes)


@pytest.mark.parametrize("room", [0.4, 0.05, 2.0])
def test_reaching_the_band_exactly_at_the_limit_is_not_beyond_it(room):
    at = _reach(limit_extension=room, quadratic_extension=room)
    assert not at.beyond_limit
    assert _reach(limit_extension=room, quadratic_extension=float(np.nextafter(room, 9.0))).beyond_limit
    assert _reach(limit_extension=0.0, quadratic_extension=0.0).beyond_limit
    assert not _reach(limit_extension=room, quadratic_extension=np.inf).beyond_limit


@pytest.mark.parametrize("room", [0.3, 1.25])
def test_levelling_off_exactly_at_the_limit_is_quoted_and_beyond_it_stays_short(room):
    level = dict(quadratic_extension=np.inf, levels_off_value=12.5, levels_off_factor_value=1.95,
                 limit_extension=room, limit_value=2.2)
    at = _reach(levels_off_extension=room, **level)
    assert at.levels_off and not at.beyond_limit
    text = saturation_finding(at, "a", "y", "kPa")
    assert re.search(r"levels off at ([\d.]+) kPa \(a ≈ ([\d.]+)\)", text).groups() == ("12.5", "1.95")
    beyond = _reach(levels_off_extension=float(np.nextafter(room, 9.0)), **level)
    text = saturation_finding(beyond, "a", "y", "kPa")
    assert "up to the physical limit of a (2.2)" in text and "levels off" not in text


@pytest.mark.parametrize("room", [0.3, 0.75])
def test_the_straight_lines_value_is_quoted_up_to_the_limit(room):
    kept = saturation_advice(_reach(straight_extension=room, quadratic_extension=np.inf, limit_extension=room,
                                    limit_value=3.0), "a", "y")
    assert float(re.search(r"a straight line would reach the target band at a ≈ ([\d.]+)\. ", kept).group(1)) == 1.6
    dropped = saturation_advice(_reach(straight_extension=float(np.nextafter(room, 9.0)), quadratic_extension=np.inf,
                                       limit_extension=room, limit_value=3.0), "a", "y")
    assert "straight line" not in dropped
    for text in (kept, dropped):
        assert re.search(r"gains only ([\d.]+) per unit a", text).group(1) == "2.5"
        assert re.search(r"The missing ([\d.]+) of y", text).group(1) == "4"


def test_a_range_ending_exactly_at_its_limit_says_so_and_a_bit_short_of_it_quotes_where_the_band_is():
    at = _reach(limit_extension=0.0, quadratic_extension=0.0, limit_value=1.0)
    text = saturation_finding(at, "a", "y", "kPa")
    assert text.startswith("The range of a already ends at its physical limit 1, where y still misses its target 14 kPa")
    assert "its range already ends at its physical limit 1." in saturation_advice(at, "a", "y", "kPa")
    short = _reach(limit_extension=0.01, quadratic_extension=0.4, quadratic_factor_value=1.4, limit_value=1.01)
    text = saturation_finding(short, "a", "y")
    assert re.search(r"reaches its target band only at a ≈ ([\d.]+), beyond the physical limit of a \(([\d.]+)\)",
                     text).groups() == ("1.4", "1.01")


class _Peak:
    """y = 10 - 3 (a - 1)²: at its peak on the upper bound a = 1, slope exactly 0 there."""

    def predict(self, x):
        return 10.0 - 3.0 * (np.asarray(x, dtype=float)[:, 0] - 1.0) ** 2


def test_a_response_at_its_peak_on_the_bound_does_not_approach_a_target_above_it():
    from demid.criticism.reach import reach_beyond_bound
    from demid.sampling.domain import Domain

    r = reach_beyond_bound(_Peak(), Domain(("a",), (0.0,), (1.0,), (False,)), "a", "upper", {"a": 1.0}, "y",
                           12.0, 0.05)
    assert r.slope == 0.0 and r.curvature == pytest.approx(-6.0)
    assert (r.straight_extension, r.quadratic_extension, r.levels_off_extension) == (np.inf, np.inf, np.inf)
    assert not r.levels_off and not r.widen
    assert saturation_finding(r, "a", "y").startswith("Beyond the bound of a the surrogate of y does not approach")

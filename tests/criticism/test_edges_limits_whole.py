"""Level 2's extrapolation warnings (criticism.edges) exactly at their tolerance, 0.1 % of the search range: runs
that stop exactly 0.1 % short of a bound cover it (no warning) and the next representable value further in does
not; a reference point exactly 0.1 % beyond the runs' range is within it and the next representable value beyond
is outside it (named with the runs' range); a point within each factor's range but off the runs' convex hull is
said to be outside the hull, one inside it is not.  The positions are checked here to land on the tolerance to the
last bit (a billionth of a unit below 0 stands for the next value below 0, which the division underflows)."""

from __future__ import annotations

import re

import numpy as np
import pytest

from demid.criticism.edges import extrapolation_warnings, in_hull
from demid.criticism.models import short_number
from demid.sampling.domain import Domain

TOL = 1e-3
DOMAIN = Domain(("a", "b"), (0.0, 0.0), (1000.0, 1.0), (False, False))


def _runs(a_lo: float, a_hi: float) -> np.ndarray:
    return np.array([[a_lo, 0.0], [a_hi, 0.0], [a_lo, 1.0], [a_hi, 1.0], [500.0, 0.5]])


def _range_sides(out: list[str]) -> list[str]:
    found = [re.search(r"simulate runs out to the (.*) bound\.$", w) for w in out if "search range of a," in w]
    return found[0].group(1).split(" and ") if found else []


@pytest.mark.parametrize("a_lo,a_hi,sides", [
    (1.0, 999.0, []),
    (float(np.nextafter(1.0, 2.0)), 999.0, ["lower"]),
    (1.0, float(np.nextafter(999.0, 0.0)), ["upper"]),
    (float(np.nextafter(1.0, 2.0)), float(np.nextafter(999.0, 0.0)), ["lower", "upper"]),
    (0.0, 1000.0, [])])
def test_runs_short_of_a_bound_by_exactly_the_tolerance_cover_it(a_lo, a_hi, sides):
    assert 1.0 / 1000.0 == TOL and 999.0 / 1000.0 == 1 - TOL  # on the tolerance to the last bit
    out = extrapolation_warnings(DOMAIN, _runs(a_lo, a_hi), None)
    assert _range_sides(out) == sides
    assert not any("search range of b" in w for w in out)
    if sides:
        assert f"which cover {short_number(a_lo)} to {short_number(a_hi)};" in out[0]


@pytest.mark.parametrize("a,outside", [(0.0, False), (-1e-9, True), (1000.0, False),
                                       (float(np.nextafter(1000.0, 2000.0)), True), (500.0, False)])
def test_a_reference_point_exactly_the_tolerance_beyond_the_runs_is_within_their_range(a, outside):
    assert (0.0 - 0.0) / 1000.0 == 1.0 / 1000.0 - TOL and 1000.0 / 1000.0 == 999.0 / 1000.0 + TOL
    out = extrapolation_warnings(DOMAIN, _runs(1.0, 999.0), {"a": a, "b": 0.5})
    said = [w for w in out if w.startswith("Extrapolation: the reference point lies outside the range of the runs")]
    assert len(said) == int(outside)
    assert not any("outside the search range" in w or "convex hull" in w for w in out)
    if outside:
        assert f"a = {short_number(a)} (runs: 1 to 999)" in said[0]


@pytest.mark.parametrize("point,inside", [((900.0, 0.9), False), ((100.0, 0.1), True), ((450.0, 0.45), True),
                                          ((600.0, 0.6), False)])
def test_a_point_off_the_runs_hull_within_each_factors_range_is_named(point, inside):
    runs = np.array([[0.0, 0.0], [1000.0, 0.0], [0.0, 1.0], [1000.0, 0.001], [0.001, 1.0]])  # a triangle, nearly
    out = extrapolation_warnings(DOMAIN, runs, {"a": point[0], "b": point[1]})
    hull = [w for w in out if "convex hull" in w]
    assert len(hull) == int(not inside) and len(out) == len(hull)
    z = runs / np.array([1000.0, 1.0])
    assert in_hull(z, np.array([point[0] / 1000.0, point[1]]), TOL) == inside

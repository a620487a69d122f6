"""The width a combination is reported with, over generated bands: known answers for straight and wedge-shaped
bands, and invariants a band's thickness and its combination must keep (the factors' order, the sign of a
direction, a = b against a = −b)."""

from __future__ import annotations

import itertools
import re

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.combinations.material import MaterialCombinations, set_combinations
from demid.spec import MaterialSpec

N = 201                                   # grid nodes per axis on the coded box [-1, 1]
STEP = 2.0 / (N - 1)
LO, HI = np.array([-1.0, -1.0]), np.array([1.0, 1.0])


def _grid(n: int = N, d: int = 2) -> np.ndarray:
    axis = np.linspace(-1.0, 1.0, n)
    return np.array(list(itertools.product(axis, repeat=d)))


GRID = _grid()


def _band(centre_line, width) -> np.ndarray:
    """Grid nodes with |y − m(x)| ≤ w(x)/2: a band along x whose vertical width is w(x)."""
    x, y = GRID[:, 0], GRID[:, 1]
    return GRID[np.abs(y - centre_line(x)) <= width(x) / 2]


def _measured(points, swap=False, flip=False):
    pts = points[:, ::-1] if swap else points
    pts = pts * (np.array([1.0, -1.0]) if flip else 1.0)
    names = ("b", "a") if swap else ("a", "b")
    return set_combinations(pts, LO, HI, names, scenario="s", set_name="strict", step=[STEP, STEP])


@given(slope=st.floats(-0.8, 0.8), offset=st.floats(-0.1, 0.1), width=st.floats(0.04, 0.16),
       swap=st.booleans(), flip=st.booleans())
@settings(max_examples=20, deadline=None, derandomize=True)
def test_a_straight_bands_thickness_is_its_width_over_the_box_extent_along_its_normal(slope, offset, width, swap,
                                                                                      flip):
    """A band y = s·x + c of vertical width w: thickness along its normal w/√(1+s²), box extent along the normal
    (2|s| + 2)/√(1+s²), so the reported fraction is w / (2|s| + 2), whichever factor is listed first and
    whichever way either axis points."""
    points = _band(lambda x: slope * x + offset, lambda x: np.full_like(x, width))
    res = _measured(points, swap, flip)
    expected = width / (2 * abs(slope) + 2)
    # the grid measures a column's width to within two nodes (the nodes just inside either edge)
    assert abs(res.band_fraction - expected) <= 2 * STEP / (2 * abs(slope) + 2) + 1e-9
    assert res.identified == (res.band_fraction <= 0.10)


@given(power=st.integers(3, 6), narrow=st.floats(0.02, 0.06), grows=st.floats(0.3, 0.8), swap=st.booleans(),
       reverse=st.booleans())
@settings(max_examples=15, deadline=None, derandomize=True)
def test_a_wedge_bands_thickness_is_the_median_of_its_local_widths(power, narrow, grows, swap, reverse):
    """A band narrow most of its length that flares at one end (w(x) = w0 + g·((x+1)/2)^p, or mirrored): half of
    its columns are narrower than w(0), so the median local width is w(0); the mean is pulled up by the flare."""
    def width(x):
        return narrow + grows * (((-x if reverse else x) + 1) / 2) ** power

    res = _measured(_band(lambda x: 0.1 * x, width), swap)
    # slope 0.1: box extent along the band's normal, per unit of vertical width, is 2·0.1 + 2
    assert abs(res.band_fraction - width(0.0) / 2.2) <= 2 * STEP / 2.2 + 1e-9
    mean = (narrow + grows / (power + 1)) / 2.2
    assert mean - res.band_fraction > STEP  # premise: the mean would read differently


def _spec(d: int) -> MaterialSpec:
    names = "abc"[:d]
    return MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "custom"},
        "factors": {n: {"lower": -1.0, "upper": 1.0} for n in names},
        "responses": {"y": {"target": 1.0}}, "scenarios": {"s": {"observables": ["y"], "tolerance": 0.05}}},
        grid_points=11)


@given(d=st.sampled_from([2, 3]), sign=st.sampled_from([1.0, -1.0]), thickness=st.floats(0.05, 0.15),
       pair=st.sampled_from([(0, 1), (1, 0)]))
@settings(max_examples=12, deadline=None, derandomize=True)
def test_a_band_along_a_equals_plus_or_minus_b_is_identified_in_combination(d, sign, thickness, pair):
    """|a − sign·b| ≤ t (c free in three factors): the set is the combination of a and b whatever the sign, and
    its width is t/2 of the box's extent along the normal (1, ∓1)/√2 ((√2 t) / (2√2))."""
    grid = GRID if d == 2 else _grid(41, 3)
    i, j = pair
    points = grid[np.abs(grid[:, i] - sign * grid[:, j]) <= thickness]
    names = tuple("abc"[:d])
    res = set_combinations(points, -np.ones(d), np.ones(d), names, scenario="s", set_name="strict",
                           step=np.full(d, grid[1, -1] - grid[0, -1]))
    step = grid[1, -1] - grid[0, -1]
    assert abs(res.axes.width_fraction[0] - thickness / 2) <= step
    assert abs(res.band_fraction - thickness / 2) <= step
    res.statement = "a − b = 0 ± 0.1"
    found = MaterialCombinations(_spec(d), None, [res], [], -np.ones(d), np.ones(d))
    assert found.in_combination() == {"s": {"a": ["b"], "b": ["a"]}}
    said = re.search(r"\(([\d.]+) % of the range along it\)", found.sentences(res))
    assert said and abs(float(said.group(1)) - 100 * res.band_fraction) <= 0.05 + 1e-9, found.sentences(res)

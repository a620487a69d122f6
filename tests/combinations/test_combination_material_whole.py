"""The combinations of a material that a user reads, against computations written here: which ends of the box a
set reaches when some of its bounds are physical limits (the box's corners enumerated, 2-4 factors, extents
other than 1), and a band's curve in the JSON in actual units (a coding whose centre is not 0 and whose unit is not
1, slopes and targets of either sign): every stored point of the curve is read back through the coding and lies
in the band the surrogate defines."""

from __future__ import annotations

import itertools

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.combinations.material import _cut_side, material_combinations
from demid.design import Coding, quadratic_terms
from demid.sampling.domain import AT_BOUND, BOUND_TOUCH
from demid.sampling.grid import admissible_set
from demid.spec import MaterialSpec
from demid.surrogate import Surrogate


def _expected_cut(points, normal, lower, upper, at_limit) -> str:
    corners = np.array(list(itertools.product(*zip(lower, upper))))
    along = corners @ normal
    box_min, box_max = along.min(), along.max()
    tol = BOUND_TOUCH * (box_max - box_min) + 1e-12
    proj = points @ normal
    ends = {"low": proj.min() <= box_min + tol, "high": proj.max() >= box_max - tol}
    for end, corner in (("low", corners[np.argmin(along)]), ("high", corners[np.argmax(along)])):
        if not at_limit:
            continue
        limited = []
        for i in range(len(normal)):
            # the end moves with factor i's bound when collapsing factor i's range shrinks the extent by more
            # than the touch tolerance; the bound that makes the end is the corner's coordinate
            collapsed = corners[corners[:, i] == corner[i]] @ normal
            if (box_max - box_min) - (collapsed.max() - collapsed.min()) > tol:
                side = "lower" if corner[i] == lower[i] else "upper"
                limited.append(side in at_limit[i])
        ends[end] = ends[end] and not all(limited)
    return AT_BOUND[int(ends["low"]) + 2 * int(ends["high"])]


@given(seed=st.integers(0, 10_000), d=st.integers(2, 4), gaps=st.sampled_from([(0.5, 3.0), (3.0, 0.5), (0.5, 0.5)]),
       tiny=st.booleans(), limits=st.sampled_from(["none", "main", "all", "random"]))
@settings(max_examples=120, deadline=None, derandomize=True)
def test_the_cut_side_with_physical_limits_is_the_one_the_boxs_corners_give(seed, d, gaps, tiny, limits):
    rng = np.random.default_rng(seed)
    normal = rng.normal(size=d)
    if tiny:  # a factor that hardly moves the end: within the touch tolerance, or just beyond it
        normal[-1] = rng.choice([-1.0, 1.0]) * rng.uniform(1e-4, 2e-2)
    normal /= np.linalg.norm(normal)
    lower = -rng.uniform(0.2, 3.0, d)
    upper = lower + rng.uniform(0.2, 6.0, d)
    corners = np.array(list(itertools.product(*zip(lower, upper))))
    box_min, box_max = (corners @ normal).min(), (corners @ normal).max()
    tol = BOUND_TOUCH * (box_max - box_min)
    centre = corners.mean(axis=0)
    t_lo = box_min + gaps[0] * tol - centre @ normal
    t_hi = box_max - gaps[1] * tol - centre @ normal
    points = np.array([centre + t_lo * normal, centre + t_hi * normal])
    if limits == "none":
        at_limit = []
    elif limits == "all":
        at_limit = [["lower", "upper"]] * d
    elif limits == "main":  # the sides of the factors with the largest loadings only
        at_limit = [["lower", "upper"] if abs(v) > 0.05 else [] for v in normal]
    else:
        options = ([], ["lower"], ["upper"], ["lower", "upper"])
        at_limit = [options[i] for i in rng.integers(0, 4, d)]
    assert _cut_side(points, normal, lower, upper, at_limit) == _expected_cut(points, normal, lower, upper, at_limit)


def _linear(name, slopes, intercept):
    terms = quadratic_terms(2)
    coef = np.zeros(len(terms))
    coef[0] = intercept
    coef[1:3] = slopes
    return Surrogate(name, ["a", "b"], terms, coef, np.zeros((len(terms), len(terms))), 0.0, 1)


@given(seed=st.integers(0, 10_000), sign=st.sampled_from([1.0, -1.0]), target_sign=st.sampled_from([1.0, -1.0]))
@settings(max_examples=8, deadline=None, derandomize=True)
def test_a_bands_curve_in_the_json_is_in_actual_units_and_inside_the_band(seed, sign, target_sign):
    rng = np.random.default_rng(seed)
    lo = rng.uniform(-5.0, 5.0, 2)
    hi = lo + rng.uniform(1.0, 20.0, 2)
    tolerance, n = 0.02, 101
    spec = MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "custom"},
        "factors": {"a": {"lower": float(lo[0]), "upper": float(hi[0])},
                    "b": {"lower": float(lo[1]), "upper": float(hi[1])}},
        "responses": {"y": {"target": target_sign * 3.0}},
        "scenarios": {"band": {"observables": ["y"], "tolerance": tolerance}}}, grid_points=n)
    # y = t + s_a (a - a0) + s_b (b - b0): the band's centre line crosses the box through (a0, b0)
    point = lo + (hi - lo) * rng.uniform(0.35, 0.65, 2)
    slopes = np.array([1.0 / (hi[0] - lo[0]), sign * rng.uniform(0.5, 2.0) / (hi[1] - lo[1])]) * 3.0
    target = target_sign * 3.0
    surrogate = _linear("y", slopes, target - slopes @ point)
    strict = {"band": admissible_set({"y": surrogate}, spec.domain, ["y"], {"y": target}, tolerance, n)}
    coding = Coding(("a", "b"), tuple((lo + hi) / 2 + rng.uniform(-1.0, 1.0, 2)), tuple((hi - lo) / 2.8))
    found = material_combinations({"y": surrogate}, spec, coding, strict, {})
    (res,) = found.results
    (entry,) = found.to_json()["sets"]
    curve = entry["curve"]
    wide, narrow = res.wide, res.narrow
    assert (curve["along"], curve["across"]) == (("a", "b")[wide], ("a", "b")[narrow])
    along = np.array(curve["along_actual"])
    mid, low, high = (np.array(curve[k]) for k in ("mid", "lower", "upper"))
    assert 3 <= len(along) <= 11
    # read back through the coding: the stored rows of the coded curve
    stored = res.curve.iloc[np.unique(np.linspace(0, len(res.curve) - 1, len(along)).round().astype(int))]
    np.testing.assert_allclose((along - coding.center[wide]) / coding.unit[wide], stored["along"], rtol=1e-9,
                               atol=1e-9)
    np.testing.assert_allclose((mid - coding.center[narrow]) / coding.unit[narrow], stored["mid"], rtol=1e-9,
                               atol=1e-9)
    # inside the box and inside the band (to a grid step across it)
    assert np.all((along >= lo[wide] - 1e-9) & (along <= hi[wide] + 1e-9))
    assert np.all((low <= mid + 1e-12) & (mid <= high + 1e-12))
    step = (hi - lo) / (n - 1)
    for across in (low, mid, high):
        x = np.zeros((len(along), 2))
        x[:, wide], x[:, narrow] = along, across
        miss = np.abs(surrogate.predict(x) - target)
        assert np.all(miss <= tolerance * abs(target) + abs(slopes[narrow]) * step[narrow] * 1.01)
    # the width the JSON quotes is the band's own
    assert entry["band_fraction"] == res.band_fraction and entry["identified"] == res.identified


def test_a_scenario_without_an_admissible_point_identifies_nothing():
    spec = MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "custom"},
        "factors": {"a": {"lower": 0.0, "upper": 1.0}, "b": {"lower": 0.0, "upper": 1.0}},
        "responses": {"y": {"target": 5.0}},
        "scenarios": {"far": {"observables": ["y"], "tolerance": 0.02}}}, grid_points=41)
    surrogate = _linear("y", np.array([1.0, 1.0]), 0.0)  # at most 2 on the square: the target 5 is out of reach
    strict = {"far": admissible_set({"y": surrogate}, spec.domain, ["y"], {"y": 5.0}, 0.02, 41)}
    found = material_combinations({"y": surrogate}, spec, Coding(("a", "b"), (0.5, 0.5), (0.5, 0.5)), strict, strict)
    assert [res.axes for res in found.results] == [None, None]
    assert not any(res.identified for res in found.results)
    assert found.in_combination() == {} and found.in_combination("plausible") == {} and found.advice == []
    entries = found.to_json()["sets"]
    assert [(e["identified"], e["text"]) for e in entries] == [(False, "no admissible point.")] * 2
    assert found.to_frame().empty

"""Identified combinations on sets whose geometry is known in closed form."""

import re

import numpy as np
import pytest

from demid.combinations import band_curve, principal_axes, set_combinations
from demid.design import Coding


def grid(n, d=2, lo=0.0, hi=1.0):
    axes = [np.linspace(lo, hi, n)] * d
    return np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, d)


def test_straight_band_direction_and_width():
    # |a + b - 1| <= w on the unit square: normal (1, 1)/sqrt 2, thickness 2w/sqrt 2 along it
    w = 0.05
    pts = grid(801)
    band = pts[np.abs(pts.sum(axis=1) - 1) <= w]
    axes = principal_axes(band, [0, 0], [1, 1])
    assert np.allclose(np.abs(axes.directions[:, 0]), [2 ** -0.5, 2 ** -0.5], atol=1e-3)
    assert axes.widths[0] == pytest.approx(2 * w / np.sqrt(2), rel=0.02)
    # box extent along (1,1)/sqrt2 is sqrt 2: the fraction is w
    assert axes.width_fraction[0] == pytest.approx(w, rel=0.02)
    assert axes.identified[0] and not axes.identified[1]
    assert axes.free[1]  # the band runs corner to corner


def test_straight_band_statement_in_actual_units():
    # the same band on actual axes: a in [0, 2] coded as (a - 1)/1, b in [10, 30] coded as (b - 20)/10
    from demid.combinations import linear_statement

    coding = Coding(("a", "b"), (1.0, 20.0), (1.0, 10.0))
    pts = grid(801, lo=-1, hi=1)
    band = pts[np.abs(pts.sum(axis=1)) <= 0.1]           # x_a + x_b = 0 ± 0.1 (coded)
    axes = principal_axes(band, [-1, -1], [1, 1])
    a, c, w, text = linear_statement(axes.directions[:, 0], axes.centre, axes.widths[0], coding, ["a", "b"],
                                     [False, False])
    # x_a + x_b = 0  <=>  (a - 1) + (b - 20)/10 = 0  <=>  a + 0.1 b = 3; unit-length coefficients
    norm = np.hypot(1, 0.1)
    assert np.allclose(a, [1 / norm, 0.1 / norm], atol=2e-3)
    assert c == pytest.approx(3 / norm, rel=2e-3)
    assert w == pytest.approx(0.1 / norm, rel=0.03)
    # a + 0.1 b = 3 ± 0.1, the equation above: the constant to the digits of the half-width's two
    assert text.startswith("a + 0.1·b = 3.00 ± 0.10")


def test_curved_band_curve_recovered_within_grid_step():
    # y = x^2 ± 0.04 on the unit square: the band's centre line is x^2
    n = 401
    pts = grid(n)
    band = pts[np.abs(pts[:, 1] - pts[:, 0] ** 2) <= 0.04]
    curve = band_curve(band, along=0, across=1)
    step = 1 / (n - 1)
    inner = curve[(curve["lower"] > 0) & (curve["upper"] < 1)]
    assert len(inner) > 300
    assert np.max(np.abs(inner["mid"] - inner["along"] ** 2)) <= step
    assert np.max(np.abs(inner["width"] - 0.08)) <= 2 * step + 1e-9  # each end within a step
    res = set_combinations(band, [0, 0], [1, 1], ["x", "y"], scenario="s", set_name="strict", step=[step, step])
    assert res.wide == 0 and res.narrow == 1
    assert res.bend > 0.25                     # curved: not stated as a straight combination
    assert res.identified                      # thin: identified as a band


def test_disk_has_no_preferred_direction():
    pts = grid(601, lo=-1, hi=1)
    disk = pts[np.hypot(pts[:, 0] - 0.1, pts[:, 1] + 0.2) <= 0.5]
    axes = principal_axes(disk, [-1, -1], [1, 1])
    # uniform disk of radius r: sigma^2 = r^2/4 along every axis
    assert axes.widths == pytest.approx([np.sqrt(12) * 0.25] * 2, rel=0.01)
    assert axes.widths[0] == pytest.approx(axes.widths[1], rel=0.01)
    assert not axes.identified.any()


def test_three_factor_slab_one_identified_two_free():
    pts = grid(61, d=3, lo=-1, hi=1)
    normal = np.array([1.0, -2.0, 0.5]) / np.linalg.norm([1.0, -2.0, 0.5])
    slab = pts[np.abs(pts @ normal - 0.1) <= 0.06]
    axes = principal_axes(slab, [-1] * 3, [1] * 3)
    assert abs(axes.directions[:, 0] @ normal) == pytest.approx(1, abs=2e-3)
    assert axes.widths[0] == pytest.approx(0.12, rel=0.05)
    assert axes.identified.tolist() == [True, False, False]
    assert (axes.width_fraction[1:] > 0.5).all()


def test_empty_set():
    assert principal_axes(np.zeros((0, 2)), [0, 0], [1, 1]) is None


def test_curved_sheet_in_three_factors_is_thin_locally():
    # z = 0.5 (x^2 + y^2) - 0.25 ± 0.05 in [-1, 1]^3: a curved sheet whose principal axes overstate its
    # thickness; along the local normal it is 0.1 / sqrt(1 + x^2 + y^2) thick, between 0.1/sqrt 3 and 0.1
    from demid.combinations.axes import local_thickness

    pts = grid(81, d=3, lo=-1, hi=1)
    sheet = pts[np.abs(pts[:, 2] - 0.5 * (pts[:, 0] ** 2 + pts[:, 1] ** 2) + 0.25) <= 0.05]
    axes = principal_axes(sheet, [-1] * 3, [1] * 3)
    assert axes.widths[0] > 0.2                          # globally the sheet looks thick
    local = local_thickness(sheet, axes, [-1] * 3, [1] * 3)
    step = 2 / 80
    assert 0.1 / np.sqrt(3) - step <= np.median(local.widths) <= 0.1 + step
    assert local.fraction <= 0.10
    res = set_combinations(sheet, [-1] * 3, [1] * 3, ["x", "y", "z"], scenario="s", set_name="strict")
    assert res.identified


def test_three_factor_slab_local_agrees_with_global():
    from demid.combinations.axes import local_thickness

    pts = grid(61, d=3, lo=-1, hi=1)
    normal = np.array([1.0, -2.0, 0.5]) / np.linalg.norm([1.0, -2.0, 0.5])
    slab = pts[np.abs(pts @ normal - 0.1) <= 0.06]
    axes = principal_axes(slab, [-1] * 3, [1] * 3)
    local = local_thickness(slab, axes, [-1] * 3, [1] * 3)
    assert np.median(local.widths) == pytest.approx(axes.widths[0], rel=0.1)
    assert np.median(np.abs(local.normals @ normal)) == pytest.approx(1, abs=0.01)


def test_band_cut_by_the_box_is_flagged():
    # a + b <= 0.1 on the unit square: a thin corner, whose narrow width is set by the box, not the data
    pts = grid(401)
    corner = pts[pts.sum(axis=1) <= 0.1]
    res = set_combinations(corner, [0, 0], [1, 1], ["a", "b"], scenario="s", set_name="strict", step=[0.0025] * 2)
    assert res.cut == "lower"
    straight = pts[np.abs(pts.sum(axis=1) - 1) <= 0.05]
    assert set_combinations(straight, [0, 0], [1, 1], ["a", "b"], scenario="s", set_name="strict").cut == "none"


class _Linear:
    """A response linear in the factors (actual units): enough for the advice's gradients."""

    def __init__(self, weights):
        self.weights = np.asarray(weights, dtype=float)

    def predict(self, points):
        return np.asarray(points, dtype=float) @ self.weights


def _band_spec():
    from demid.spec import MaterialSpec

    return MaterialSpec.from_material("m", {
        "design": {"type": "ccd"},
        "factors": {"a": {"lower": 0, "upper": 1}, "b": {"lower": 0, "upper": 1}},
        "responses": {"y1": {"target": 1.0}, "across": {"target": 0.0}, "parallel": {"target": 2.0},
                      "tilted": {}},
        "scenarios": {"band": {"observables": ["y1"], "tolerance": 0.02}}})


def test_advice_names_the_observable_that_cuts_the_band():
    # y1 = a + b: the band a + b = 1 ± 0.02; 'across' = a - b changes along the band (breaks it), 'parallel'
    # = 2(a + b) does not, 'tilted' = a lies 45 degrees off
    from demid.combinations import break_ridge_advice

    spec = _band_spec()
    coding = Coding(("a", "b"), (0.5, 0.5), (0.5, 0.5))
    pts = grid(401)
    band = pts[np.abs(pts.sum(axis=1) - 1) <= 0.02]
    coded = coding.to_coded(band)
    res = set_combinations(coded, [-1, -1], [1, 1], ["a", "b"], scenario="band", set_name="strict",
                           step=[0.005, 0.005])
    assert res.identified and res.cut == "none"
    surrogates = {"y1": _Linear([1, 1]), "across": _Linear([1, -1]), "parallel": _Linear([2, 2]),
                  "tilted": _Linear([1, 0])}
    text = break_ridge_advice(res, band, surrogates, spec, coding, ["y1"])
    assert "across changes most along the set" in text
    assert "90° off" in text and "tilted 45°" in text and "parallel 0°" in text
    assert "would break the ridge" in text
    # with only the parallel observable left, the advice says it cuts at a shallow angle
    text = break_ridge_advice(res, band, {"y1": surrogates["y1"], "parallel": surrogates["parallel"]}, spec,
                              coding, ["y1"])
    assert "shallow angle" in text
    # a scenario that already measures the observable: its own set answers, no next step is advised
    from demid.spec import MaterialSpec

    both = MaterialSpec.from_material("m", {
        "design": {"type": "ccd"},
        "factors": {"a": {"lower": 0, "upper": 1}, "b": {"lower": 0, "upper": 1}},
        "responses": {"y1": {"target": 1.0}, "across": {"target": 0.0}},
        "scenarios": {"band": {"observables": ["y1"], "tolerance": 0.02},
                      "both": {"observables": ["y1", "across"], "tolerance": 0.02}}})
    assert break_ridge_advice(res, band, {"y1": surrogates["y1"], "across": surrogates["across"]}, both,
                              coding, ["y1"]) == ""


def test_combination_verdicts_and_lines():
    import pandas as pd

    from demid.report.summary import combination_lines
    from demid.story.verdicts import in_combination

    spec = _band_spec()
    verdicts = pd.DataFrame({"scenario": ["band", "band"], "factor": ["a", "b"],
                             "verdict": ["unresolved", "identified"], "reason": ["wide", "narrow"]})
    # identified in combination by the plausible set: the verdict says so
    out = in_combination(verdicts, spec, {"in_combination_plausible": {"band": {"a": ["b"], "b": ["a"]}}})
    assert out["verdict"].tolist() == ["unresolved alone; identified in combination with b", "identified"]
    # by the strict set only: the verdict stays, the reason says it would hold if everything were exact
    strict = in_combination(verdicts, spec, {"in_combination": {"band": {"a": ["b"], "b": ["a"]}}})
    assert strict["verdict"].tolist() == ["unresolved", "identified"]
    assert "if surrogate and measurements were exact" in strict["reason"].iloc[0]
    assert in_combination(verdicts, spec, {})["verdict"].tolist() == ["unresolved", "identified"]
    lines = combination_lines({"sets": [{"scenario": "band", "set": "strict", "identified": True,
                                         "text": "a curved band: b ≈ f(a) along the band.",
                                         "curve": {"along": "a", "across": "b", "along_actual": [0.0, 1.0],
                                                   "lower": [0.1, 0.5], "mid": [0.2, 0.6], "upper": [0.3, 0.7]}}]},
                              spec)
    assert lines == ["*band*, strict set: a curved band: b ≈ f(a) along the band. "
                     "Curve (a → b mid [lowest, highest]): 0 → 0.2 [0.1, 0.3]; 1 → 0.6 [0.5, 0.7]."]


def test_combinations_columns_are_documented():
    from demid.report.columns import columns_table

    table = columns_table({}, None, ["mu_r", "gamma"])
    rows = table[table["table"] == "combinations.csv"]["column"].tolist()
    assert rows == ["material", "scenario", "set", "direction", "mu_r", "gamma", "width_coded",
                    "width_fraction_of_range"]
    assert not table.duplicated(["table", "column"]).any()


def test_weighted_points_equal_repeated_points():
    # a weight is the volume a point stands for: weight 2 is the point twice
    rng = np.random.default_rng(1)
    pts = rng.uniform(-1, 1, size=(200, 2))
    weights = rng.integers(1, 4, size=200)
    repeated = np.repeat(pts, weights, axis=0)
    a = principal_axes(pts, [-1, -1], [1, 1], weights=weights)
    b = principal_axes(repeated, [-1, -1], [1, 1])
    assert a.widths == pytest.approx(b.widths)
    assert np.abs(a.directions) == pytest.approx(np.abs(b.directions))


def test_statement_of_a_log_scaled_factor():
    # coded x_g = (log10 g - 1) / 0.5; the band x_a - x_g = 0 reads a - 2 log10 g = -2 (a coded as is)
    from demid.combinations import linear_statement

    coding = Coding(("a", "g"), (0.0, 1.0), (1.0, 0.5))
    pts = grid(401, lo=-1, hi=1)
    band = pts[np.abs(pts[:, 0] - pts[:, 1]) <= 0.05]
    axes = principal_axes(band, [-1, -1], [1, 1])
    _, _, _, text = linear_statement(axes.directions[:, 0], axes.centre, axes.widths[0], coding, ["a", "g"],
                                     [False, True])
    assert re.match(r"a − 2·log10 g = −2\.0+ ± |log10 g − 0\.5·a = 1\.0+ ± ", text), text


@pytest.mark.parametrize("narrow", [(-0.6, 0.8), (0.8, -0.6), (1 / np.sqrt(2), -1 / np.sqrt(2)),
                                    (1 / np.sqrt(2), 1 / np.sqrt(2))])
def test_directions_are_signed_by_their_largest_loading_the_first_of_equal_ones(narrow):
    # a rectangle of points, 0.1 wide along the unit vector ``narrow`` and 1.6 long across it: the principal
    # axes are the rectangle's axes (by symmetry), each signed so that its largest loading (the first of two
    # equal ones) is positive; widths: a uniform band of width w has sd w / sqrt 12
    n = np.asarray(narrow, dtype=float)
    long = np.array([-n[1], n[0]])
    s, t = np.meshgrid(np.linspace(-0.05, 0.05, 11), np.linspace(-0.8, 0.8, 161), indexing="ij")
    points = s.reshape(-1, 1) * n + t.reshape(-1, 1) * long
    axes = principal_axes(points, [-1, -1], [1, 1])

    def signed(v):
        big = np.flatnonzero(np.isclose(np.abs(v), np.abs(v).max(), rtol=0, atol=1e-9))[0]
        return v if v[big] > 0 else -v

    assert axes.directions[:, 0] == pytest.approx(signed(n), abs=1e-9)
    assert axes.directions[:, 1] == pytest.approx(signed(long), abs=1e-9)
    sd = np.std(np.linspace(-0.05, 0.05, 11))
    assert axes.widths[0] / axes.widths[1] == pytest.approx(sd / np.std(np.linspace(-0.8, 0.8, 161)), rel=1e-9)


def test_local_thickness_of_a_straight_band_is_its_width_over_the_box_extent_along_the_normal():
    # a band 0.1 wide along n = (-0.6, 0.8), 1.6 long, in the box [-1, 1]^2: in every cell the local normal is n
    # and the local width sqrt 12 sd of the 11 levels across; the box's extent along n is 0.6 * 2 + 0.8 * 2 = 2.8
    from demid.combinations.axes import local_thickness

    n = np.array([-0.6, 0.8])
    long = np.array([0.8, 0.6])
    across = np.linspace(-0.05, 0.05, 11)
    # 160 columns: no column on a cell boundary (there round-off would split its points between two cells)
    s, t = np.meshgrid(across, np.linspace(-0.8, 0.8, 160), indexing="ij")
    points = s.reshape(-1, 1) * n + t.reshape(-1, 1) * long
    local = local_thickness(points, principal_axes(points, [-1, -1], [1, 1]), [-1, -1], [1, 1])
    width = np.sqrt(12) * np.std(across)
    assert len(local.widths) == 8 and local.counts.sum() == len(points)
    assert np.abs(local.normals @ n) == pytest.approx(np.ones(8), abs=1e-9)
    assert local.widths == pytest.approx(np.full(8, width), rel=1e-6)
    assert local.fractions == pytest.approx(np.full(8, width / 2.8), rel=1e-6)
    assert local.fraction == pytest.approx(width / 2.8, rel=1e-6)


@pytest.mark.parametrize("x_range, side", [((1.9, 2.1), 0), ((0.0, 0.3), 1), ((3.7, 4.0), 2), ((0.0, 4.0), 3)])
def test_cut_side_in_a_box_that_does_not_end_at_one(x_range, side):
    # the box [0, 4] x [1, 5] along the normal (1, 0): its ends are 0 and 4
    from demid.combinations.material import _cut_side
    from demid.sampling.domain import AT_BOUND

    x, y = np.meshgrid(np.linspace(*x_range, 7), np.linspace(1, 5, 9), indexing="ij")
    points = np.column_stack([x.ravel(), y.ravel()])
    assert _cut_side(points, np.array([1.0, 0.0]), [0.0, 1.0], [4.0, 5.0]) == AT_BOUND[side]


def test_a_flat_sheet_in_three_factors_has_its_normal_at_every_point():
    # a slab 0.02 thick along n = (2, -1, 2) / 3 through the origin of [-1, 1]^3 (thinner than a cell is wide):
    # the normal of every cell, and so at every point, is +-n
    n = np.array([2.0, -1.0, 2.0]) / 3
    u = np.array([1.0, 2.0, 0.0]) / np.sqrt(5)
    v = np.cross(n, u)
    s, a, b = np.meshgrid(np.linspace(-0.01, 0.01, 5), np.linspace(-0.5, 0.5, 41), np.linspace(-0.5, 0.5, 41),
                          indexing="ij")
    points = s.reshape(-1, 1) * n + a.reshape(-1, 1) * u + b.reshape(-1, 1) * v
    res = set_combinations(points, [-1] * 3, [1] * 3, ["a", "b", "c"], scenario="s", set_name="strict")
    assert res.local is not None
    normals = res.normals_at(points[::97])
    assert np.abs(normals @ n) == pytest.approx(np.ones(len(normals)), abs=1e-3)  # cells cut the grid unevenly


def test_direction_text_writes_signed_loadings_in_brackets():
    from demid.combinations.material import _direction_text

    assert _direction_text(np.array([0.6, -0.8]), ["a", "b"]) == "(0.60·a − 0.80·b)"
    assert _direction_text(np.array([-0.6, 0.001, 0.8]), ["a", "b", "c"]) == "(−0.60·a + 0.80·c)"


def test_a_slab_in_three_factors_is_identified_in_combination_of_the_factors_its_normal_loads():
    # a slab 0.05 thick along n = (0.6, 0.8, 0), 1.6 long along (-0.8, 0.6, 0) and 0.6 along c, centred in
    # [-1, 1]^3: a and b are identified in combination (loadings 0.6 and 0.8), c is not (its loading is 0)
    from demid.combinations.axes import linear_statement
    from demid.combinations.material import MaterialCombinations
    from demid.spec import MaterialSpec

    spec = MaterialSpec.from_material("m", {
        "design": {"type": "ccd"},
        "factors": {f: {"lower": 0, "upper": 2} for f in "abc"},
        "responses": {"y": {"target": 1.0}}, "scenarios": {"s": {"observables": ["y"], "tolerance": 0.02}}})
    coding = Coding(("a", "b", "c"), (1.0, 1.0, 1.0), (1.0, 1.0, 1.0))
    n, long, c = np.array([0.6, 0.8, 0.0]), np.array([-0.8, 0.6, 0.0]), np.array([0.0, 0.0, 1.0])
    s, t, u = np.meshgrid(np.linspace(-0.025, 0.025, 6), np.linspace(-0.8, 0.8, 81), np.linspace(-0.3, 0.3, 31),
                          indexing="ij")
    points = s.reshape(-1, 1) * n + t.reshape(-1, 1) * long + u.reshape(-1, 1) * c
    res = set_combinations(points, [-1] * 3, [1] * 3, ["a", "b", "c"], scenario="s", set_name="strict")
    assert res.identified and res.cut == "none" and res.curve is None
    a, const, w, text = linear_statement(res.axes.directions[:, 0], res.axes.centre, res.axes.widths[0], coding,
                                         ["a", "b", "c"], [False] * 3)
    res.statement, res.equation = text, {"coefficients_search_units": [float(v) for v in a], "constant": const,
                                         "half_width": w}
    combos = MaterialCombinations(spec, coding, [res], [], -np.ones(3), np.ones(3))
    assert combos.in_combination() == {"s": {"a": ["b"], "b": ["a"]}}
    assert combos.in_combination("plausible") == {}
    out = combos.to_json()
    assert out["in_combination"] == {"s": {"a": ["b"], "b": ["a"]}}
    assert "curve" not in out["sets"][0]  # a set in three factors has no band curve
    # n . (x - 1) = 0 in actual units: 0.6 a + 0.8 b = 1.4, unit coefficients with the largest positive
    assert out["sets"][0]["coefficients_search_units"] == pytest.approx([0.6, 0.8, 0.0], abs=1e-9)
    assert out["sets"][0]["constant"] == pytest.approx(1.4, abs=1e-9)


class _Function:
    def __init__(self, f):
        self.f = f

    def predict(self, points):
        points = np.asarray(points, dtype=float)
        return self.f(points[:, 0], points[:, 1])


def test_on_a_curved_band_an_observable_constant_along_it_is_0_degrees_off():
    # y1 = b - 1.6 (a - 0.5)^2: the band b = 0.3 + 1.6 (a - 0.5)^2 (± 0.6 %) bends inside the box.  'parallel'
    # = 2 y1 is constant along the band: its gradient is the band's normal at every point, 0 degrees off (a
    # straight free direction would see it change); 'across' = a changes along it and is named
    from demid.combinations import break_ridge_advice

    spec = _band_spec()
    coding = Coding(("a", "b"), (0.5, 0.5), (0.5, 0.5))
    pts = grid(401)
    y1 = pts[:, 1] - 1.6 * (pts[:, 0] - 0.5) ** 2
    band = pts[np.abs(y1 - 0.3) <= 0.006]
    res = set_combinations(coding.to_coded(band), [-1, -1], [1, 1], ["a", "b"], scenario="band", set_name="strict",
                           step=[0.005, 0.005])
    assert res.identified and res.cut == "none"
    surrogates = {"y1": _Function(lambda a, b: b - 1.6 * (a - 0.5) ** 2),
                  "parallel": _Function(lambda a, b: 2 * (b - 1.6 * (a - 0.5) ** 2)),
                  "across": _Function(lambda a, b: a)}
    text = break_ridge_advice(res, band, surrogates, spec, coding, ["y1"])
    assert "across changes most along the set" in text
    # 0 degrees up to the grid: the band's centre line is read from 401 x 401 nodes
    import re

    assert float(re.search(r"parallel (\d+)°", text).group(1)) <= 5


def test_an_end_made_of_physical_limits_does_not_cut_the_set():
    """The box [0, 4] x [1, 5]; a set filling it reaches both ends along every direction.  Along (1, 0) an end
    made of x's bound at its physical limit cuts nothing; along the diagonal the upper end is the corner
    (4, 5), cut unless both bounds there are limits."""
    from demid.combinations.material import _cut_side

    x, y = np.meshgrid(np.linspace(0, 4, 9), np.linspace(1, 5, 9), indexing="ij")
    points = np.column_stack([x.ravel(), y.ravel()])
    box = ([0.0, 1.0], [4.0, 5.0])
    along_x, diagonal = np.array([1.0, 0.0]), np.array([1.0, 1.0]) / np.sqrt(2)
    assert _cut_side(points, along_x, *box) == "both"
    assert _cut_side(points, along_x, *box, (["upper"], [])) == "lower"
    assert _cut_side(points, along_x, *box, (["lower", "upper"], [])) == "none"
    assert _cut_side(points, along_x, *box, ([], ["lower", "upper"])) == "both"  # y's limits make no end here
    assert _cut_side(points, diagonal, *box, (["upper"], [])) == "both"
    assert _cut_side(points, diagonal, *box, (["upper"], ["upper"])) == "lower"
    assert _cut_side(points, -diagonal, *box, (["upper"], ["upper"])) == "upper"  # the same corner, seen reversed

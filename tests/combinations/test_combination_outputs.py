"""The numbers tables/combinations.csv and the combination sentences are made of, each against an independent
computation over generated sets (2-4 factors, weighted and unweighted points, boxes of unequal extents): the
principal axes from numpy's weighted covariance, the band's centre line from a plain loop over bins, the
cut side from the points' projections, the table's columns, and the direction text parsed back."""

from __future__ import annotations

import itertools
import re

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.combinations.axes import UNIFORM_WIDTH_PER_SD, band_curve, principal_axes
from demid.combinations.material import MaterialCombinations, _cut_side, _direction_text, set_combinations
from demid.sampling.domain import BOUND_TOUCH
from demid.spec import MaterialSpec


def _cloud(seed: int, d: int, m: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """m points of an elongated, tilted Gaussian cloud in d factors, volume weights and an unequal coded box."""
    rng = np.random.default_rng(seed)
    scales = np.sort(rng.uniform(0.02, 0.6, d))
    rotation, _ = np.linalg.qr(rng.normal(size=(d, d)))
    points = (rng.normal(size=(m, d)) * scales) @ rotation.T + rng.uniform(-0.3, 0.3, d)
    return points, rng.uniform(0.1, 2.0, m), rng.uniform(0.5, 3.0, d)


@given(seed=st.integers(0, 10_000), d=st.integers(2, 4), m=st.integers(12, 300), weighted=st.booleans())
@settings(max_examples=30, deadline=None, derandomize=True)
def test_principal_axes_are_the_weighted_covariances_eigenvectors_narrowest_first(seed, d, m, weighted):
    points, weights, half = _cloud(seed, d, m)
    lower, upper = -half, 1.5 * half
    axes = principal_axes(points, lower, upper, weights=weights if weighted else None)
    w = weights if weighted else np.ones(m)
    centre = np.average(points, axis=0, weights=w)
    cov = np.cov(points.T, aweights=w, bias=True)
    values, vectors = np.linalg.eigh(cov)
    assert axes.n_points == m and axes.factors == tuple(f"x{i + 1}" for i in range(d))
    assert np.allclose(axes.centre, centre, atol=1e-12)
    assert np.allclose(axes.widths, np.sqrt(12.0 * np.clip(values, 0, None)), rtol=1e-9, atol=1e-12)
    assert UNIFORM_WIDTH_PER_SD == pytest.approx(np.sqrt(12.0))
    for j in range(d):
        v = axes.directions[:, j]
        assert abs(abs(v @ vectors[:, j]) - 1.0) < 1e-8  # the same axis, up to its sign
        assert v[np.argmax(np.abs(v))] > 0  # sign fixed: the largest loading is positive
        assert axes.box_extent[j] == pytest.approx(np.abs(v) @ (upper - lower), rel=1e-12)
    assert np.allclose(axes.width_fraction, axes.widths / axes.box_extent)


def test_a_set_without_points_or_without_volume_has_no_axes():
    points = np.array([[0.1, 0.2], [0.3, -0.1], [0.0, 0.5]])
    assert principal_axes(np.zeros((0, 2)), -np.ones(2), np.ones(2)) is None
    assert principal_axes(points, -np.ones(2), np.ones(2), weights=np.zeros(3)) is None
    assert principal_axes(points, -np.ones(2), np.ones(2), weights=[0.0, 0.0, 1.0]) is not None


@given(seed=st.integers(0, 10_000), per_bin=st.integers(3, 16), bins=st.integers(3, 25))
@settings(max_examples=30, deadline=None, derandomize=True)
def test_a_scattered_bands_centre_line_is_taken_over_equal_bins(seed, per_bin, bins):
    """Points off any grid (more distinct values than columns): equal bins between the smallest and largest
    value along the band, each bin's lowest, highest and mean position."""
    rng = np.random.default_rng(seed)
    # a jittered ladder of at least three values per bin (none left empty), stretched and moved
    m = per_bin * bins
    x = (np.linspace(-1.0, 1.0, m) + rng.uniform(-0.4, 0.4, m) / m) * rng.uniform(0.5, 3.0) + rng.uniform(-1, 1)
    y = 0.4 * x + rng.uniform(-0.1, 0.1, m)
    curve = band_curve(np.column_stack([y, x]), along=1, across=0, max_columns=bins)
    width = (x.max() - x.min()) / bins
    which = np.minimum(((x - x.min()) / width).astype(int), bins - 1)
    rows = []
    for b in range(bins):
        inside = which == b
        if inside.any():
            lo, hi = y[inside].min(), y[inside].max()
            rows.append((x[inside].mean(), lo, (lo + hi) / 2, hi, hi - lo))
    expected = pd.DataFrame(rows, columns=["along", "lower", "mid", "upper", "width"])
    # a point on an inner bin edge may fall either side by round-off; the bins' counts must agree otherwise
    assert len(curve) == len(expected)
    assert np.allclose(curve.to_numpy(), expected.to_numpy(), atol=1e-9)


def test_a_grids_centre_line_has_one_row_per_column():
    axis = np.linspace(-1.0, 1.0, 9)
    grid = np.array(list(itertools.product(axis, axis)))
    band = grid[np.abs(grid[:, 1] - 0.5 * grid[:, 0]) <= 0.3]
    curve = band_curve(band, along=0, across=1)
    assert list(curve["along"]) == pytest.approx(list(axis))
    for row in curve.itertuples():
        column = band[np.isclose(band[:, 0], row.along), 1]
        assert (row.lower, row.upper, row.width) == pytest.approx((column.min(), column.max(), np.ptp(column)))


@pytest.mark.parametrize("normal", [(1.0, 0.0), (0.6, 0.8), (-0.6, 0.8), (0.0, -1.0)])
@pytest.mark.parametrize("extent", [(1.0, 1.0), (10.0, 0.5), (0.2, 4.0)])
def test_the_cut_side_is_where_the_projections_reach_the_box_within_the_touch_tolerance(normal, extent):
    normal = np.array(normal)
    lower, upper = -np.array(extent), 2 * np.array(extent)
    corners = np.array(list(itertools.product(*zip(lower, upper))))
    box_min, box_max = (corners @ normal).min(), (corners @ normal).max()
    tol = BOUND_TOUCH * (box_max - box_min)
    centre = corners.mean(axis=0)
    for low_gap, high_gap, expected in [(0.5 * tol, 3 * tol, "lower"), (3 * tol, 0.5 * tol, "upper"),
                                        (0.5 * tol, 0.5 * tol, "both"), (1.5 * tol, 1.5 * tol, "none")]:
        # two points on the normal's line through the box's centre, at the given gaps from the box's ends
        t_lo = box_min + low_gap - centre @ normal
        t_hi = box_max - high_gap - centre @ normal
        points = np.array([centre + t_lo * normal, centre + t_hi * normal])
        assert _cut_side(points, normal, lower, upper) == expected, (low_gap / tol, high_gap / tol)


@pytest.mark.parametrize("vector, text", [
    ((0.6, -0.8), "(0.60·a − 0.80·b)"),
    ((-0.6, 0.8), "(−0.60·a + 0.80·b)"),
    ((0.004, 1.0, -0.0049), "(1.00·b)"),
    ((0.0, -0.5, 0.5), "(−0.50·b + 0.50·c)"),
    ((0.25, 0.25, 0.25, 0.9), "(0.25·a + 0.25·b + 0.25·c + 0.90·d)"),
])
def test_a_direction_is_written_with_its_signs_and_loadings(vector, text):
    assert _direction_text(np.array(vector), list("abcd")[:len(vector)]) == text


def _spec(d: int) -> MaterialSpec:
    return MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "custom"},
        "factors": {n: {"lower": -1.0, "upper": 1.0} for n in "abcd"[:d]},
        "responses": {"y": {"target": 1.0}}, "scenarios": {"s": {"observables": ["y"], "tolerance": 0.05}}},
        grid_points=11)


@pytest.mark.parametrize("d", [2, 3, 4])
def test_the_combinations_table_has_a_row_per_direction_of_each_set_with_its_loadings(d):
    results = []
    for k, (scenario, name) in enumerate([("s", "strict"), ("s", "plausible"), ("t", "strict")]):
        points, _, _ = _cloud(7 + k, d, 60)
        results.append(set_combinations(points, -np.ones(d), np.ones(d), tuple("abcd"[:d]), scenario=scenario,
                                        set_name=name))
    results.append(set_combinations(np.zeros((0, d)), -np.ones(d), np.ones(d), tuple("abcd"[:d]), scenario="u",
                                    set_name="strict"))
    frame = MaterialCombinations(_spec(d), None, results, [], -np.ones(d), np.ones(d)).to_frame()
    factors = list("abcd"[:d])
    assert list(frame.columns) == ["scenario", "set", "direction", *factors, "width_coded", "width_fraction_of_range"]
    assert len(frame) == 3 * d  # the empty set has no direction
    for k, res in enumerate(results[:3]):
        part = frame.iloc[k * d:(k + 1) * d]
        assert set(part["scenario"]) == {res.scenario} and set(part["set"]) == {res.set}
        assert list(part["direction"]) == list(range(1, d + 1))
        assert np.allclose(part[factors].to_numpy(), res.axes.directions.T)
        assert np.allclose(part["width_coded"], res.axes.widths)
        assert np.allclose(part["width_fraction_of_range"], res.axes.width_fraction)
    empty = MaterialCombinations(_spec(d), None, results[3:], [], -np.ones(d), np.ones(d)).to_frame()
    assert empty.empty and list(empty.columns) == list(frame.columns)


def test_every_width_a_combination_sentence_quotes_is_the_sets_own():
    """A small region (every direction identified) quotes each direction's width; a wide set its narrowest."""
    rng = np.random.default_rng(3)
    spec = _spec(3)
    small = set_combinations(rng.uniform(-0.05, 0.05, (400, 3)), -np.ones(3), np.ones(3), ("a", "b", "c"),
                             scenario="s", set_name="strict")
    small.statement = "a region"
    said = MaterialCombinations(spec, None, [small], [], -np.ones(3), np.ones(3)).sentences(small)
    quoted = [float(v) for v in re.findall(r"([\d.]+) %", said)]
    assert said.startswith("every direction is identified")
    assert quoted == pytest.approx(list(100 * small.axes.width_fraction), abs=0.051)
    wide = set_combinations(rng.uniform(-1, 1, (400, 3)), -np.ones(3), np.ones(3), ("a", "b", "c"), scenario="s",
                            set_name="strict")
    text = MaterialCombinations(spec, None, [wide], [], -np.ones(3), np.ones(3)).sentences(wide)
    number = float(re.search(r"the set is (\d+) % of the range wide", text).group(1))
    width = wide.band_fraction if np.isfinite(wide.band_fraction) else wide.axes.width_fraction[0]
    assert number == pytest.approx(100 * width, abs=0.51)


# ------------------------------------------------------------------------------------------ the statement
@given(seed=st.integers(0, 10_000), d=st.integers(2, 4), log_mask=st.integers(0, 15))
@settings(max_examples=40, deadline=None, derandomize=True)
def test_a_linear_statement_holds_on_the_bands_centre_plane_and_its_edges_in_search_units(seed, d, log_mask):
    """a·s = c on the plane normal·x = normal·centre (x coded, s = centre_s + x·unit in search units), a·s = c ± w
    on its two edges normal·x = normal·centre ± width/2; a has unit length and its largest entry is positive; the
    sentence, read back term by term, is the same equation scaled to the leading factor."""
    from demid.combinations.axes import linear_statement
    from demid.design import Coding

    rng = np.random.default_rng(seed)
    normal = rng.normal(size=d)
    normal /= np.linalg.norm(normal) * (1 if rng.uniform() < 0.5 else -1)
    centre, width = rng.uniform(-0.5, 0.5, d), rng.uniform(0.01, 0.4)
    unit, mid = rng.uniform(0.1, 30.0, d), rng.uniform(-5.0, 50.0, d)
    log = [bool(log_mask >> i & 1) for i in range(d)]
    labels = [f"p{i}" for i in range(d)]
    a, c, w, text = linear_statement(normal, centre, width, Coding(tuple(labels), tuple(mid), tuple(unit)), labels,
                                     log, digits=6)
    assert np.linalg.norm(a) == pytest.approx(1.0) and a[np.argmax(np.abs(a))] > 0 and w > 0
    tangent = np.linalg.svd(normal[None, :])[2][1:]  # directions within the plane
    for offset, side in ((0.0, 0), (width / 2, 1), (-width / 2, -1)):
        for t in rng.normal(size=(3, d - 1)):
            x = centre + offset * normal + t @ tangent
            s = mid + x * unit
            assert abs(a @ s - c) == pytest.approx(abs(side) * w, rel=1e-7, abs=1e-9 * (abs(c) + 1))
    # the sentence: "p2 + 0.5·log10 p0 − 3·p1 = c ± w", the leading factor (largest |normal|) first with coefficient 1
    lhs, rhs = text.split(" = ")
    lead = int(np.argmax(np.abs(normal)))
    terms = re.findall(r"(^−?|[+−] )(?:([\d.e+-]+)·)?(log10 )?(p\d)", lhs)
    assert terms[0][3] == f"p{lead}" and terms[0][1] == ""
    shown = {}
    for sign, coef, lg, name in terms:
        assert bool(lg) == log[int(name[1:])]
        shown[int(name[1:])] = (-1 if "−" in sign else 1) * (float(coef) if coef else 1.0)
    expected = a / a[lead]
    for i in range(d):
        if abs(expected[i]) >= 0.5e-6:
            assert shown[i] == pytest.approx(expected[i], rel=1e-5), text
        else:
            assert i not in shown
    value, half = (float(v.replace("−", "-")) for v in rhs.split(" ± "))
    assert half == pytest.approx(w / abs(a[lead]), rel=0.05)
    assert value == pytest.approx(c / a[lead], abs=half)


# ------------------------------------------------------------------------------------------ a band's bend
def _axes_for(centre, normal, width):
    from demid.combinations.axes import PrincipalAxes

    normal = np.asarray(normal, dtype=float)
    other = np.array([-normal[1], normal[0]])
    return PrincipalAxes(("a", "b"), np.asarray(centre, dtype=float), np.column_stack([normal, other]),
                         np.array([width, 1.0]), np.array([2.0, 2.0]), 100)


@pytest.mark.parametrize("step", [0.01, 0.05])
@pytest.mark.parametrize("gap_steps, clear", [(1.4, False), (1.6, True)])
def test_a_bend_leaves_out_columns_within_one_and_a_half_steps_of_the_box(step, gap_steps, clear):
    """Columns whose band reaches within 1.5 grid steps of the box's across-bounds are cut, and left out (when
    three others remain); the bend is the largest distance of the rest's mid-points from the straight line, over
    the band's width."""
    from demid.combinations.axes import curve_bend

    along = np.linspace(-0.8, 0.8, 9)
    mid = 0.05 * along ** 2
    lower, upper = mid - 0.1, mid + 0.1
    # the last column is pushed to the box's upper end: its upper edge sits gap_steps steps below 1
    upper[-1] = 1.0 - gap_steps * step
    mid_last = (lower[-1] + upper[-1]) / 2
    curve = pd.DataFrame({"along": along, "lower": lower, "mid": np.r_[mid[:-1], mid_last], "upper": upper})
    curve["width"] = curve["upper"] - curve["lower"]
    axes = _axes_for((0.0, 0.02), (0.0, 1.0), 0.2)
    bend = curve_bend(curve, axes, 0, 1, [-1.0, -1.0], [1.0, 1.0], step)
    kept = curve if clear else curve.iloc[:-1]
    assert bend == pytest.approx(np.max(np.abs(kept["mid"] - 0.02)) / 0.2)
    # a straight band's bend: its mid-points' spread about its own line only
    flat = curve.assign(mid=0.02, lower=-0.08, upper=0.12)
    assert curve_bend(flat, axes, 0, 1, [-1.0, -1.0], [1.0, 1.0], step) == pytest.approx(0.0, abs=1e-12)
    assert np.isnan(curve_bend(curve, _axes_for((0.0, 0.02), (0.0, 1.0), 0.0), 0, 1, [-1, -1], [1, 1], step))


@pytest.mark.parametrize("fractions, counts, median", [
    ([0.1, 0.2, 0.3], [1, 1, 5], 0.3), ([0.3, 0.1, 0.2], [1, 5, 1], 0.1), ([0.4, 0.2], [3, 3], 0.2),
    ([0.05, 0.5, 0.07, 0.06], [10, 1, 10, 10], 0.06)])
def test_a_local_thickness_is_the_point_weighted_median_of_its_cells(fractions, counts, median):
    from demid.combinations.axes import LocalThickness

    n = len(fractions)
    local = LocalThickness(np.zeros((n, 3)), np.zeros((n, 3)), np.zeros(n), np.array(fractions), np.array(counts))
    assert local.fraction == pytest.approx(median)


@given(seed=st.integers(0, 10_000), thickness=st.floats(0.08, 0.2))
@settings(max_examples=8, deadline=None, derandomize=True)
def test_a_flat_sheets_local_thickness_is_its_thickness(seed, thickness):
    from demid.combinations.axes import local_thickness

    """A slab |n·x| <= t/2 through the cube: cell by cell along the sheet the local width is t (the cells the
    cube's faces cut are a few), its normal n, its fraction the width over the cube's extent along it."""
    d = 3
    rng = np.random.default_rng(seed)
    normal = rng.normal(size=d)
    normal /= np.linalg.norm(normal)
    points = rng.uniform(-1, 1, (60_000, d))
    points = points[np.abs(points @ normal) <= thickness / 2]
    axes = principal_axes(points, -np.ones(d), np.ones(d))
    local = local_thickness(points, axes, -np.ones(d), np.ones(d))
    assert local.counts.sum() <= len(points) and local.counts.min() >= 30
    assert np.allclose(local.fractions, local.widths / (np.abs(local.normals) @ np.full(d, 2.0)))
    good = (np.abs(local.widths / thickness - 1) < 0.2) & (np.abs(np.abs(local.normals @ normal) - 1) < 0.02)
    assert local.counts[good].sum() >= 0.7 * local.counts.sum()
    assert local.fraction == pytest.approx(thickness / (np.abs(normal) @ np.full(d, 2.0)), rel=0.1)


# ------------------------------------------------------------------------------------------ gradients, curves, points
@given(seed=st.integers(0, 10_000), d=st.integers(2, 4), log_mask=st.integers(0, 15))
@settings(max_examples=20, deadline=None, derandomize=True)
def test_a_surrogates_gradient_in_coded_units_is_the_chain_rule_through_the_coding(seed, d, log_mask):
    """y = Σ c_i s_i + q (s_0 s_1) with s the search units (log10 of a log factor): dy/dx_i = unit_i ∂y/∂s_i."""
    from demid.combinations.material import gradient_coded
    from demid.design import Coding
    from demid.sampling.domain import Domain

    rng = np.random.default_rng(seed)
    log = tuple(bool(log_mask >> i & 1) for i in range(d))
    lower = np.where(log, 10.0 ** rng.uniform(-3, 0, d), rng.uniform(-5, 5, d))
    upper = np.where(log, lower * 10.0 ** rng.uniform(1, 3, d), lower + rng.uniform(0.5, 20, d))
    domain = Domain(tuple(f"f{i}" for i in range(d)), tuple(lower), tuple(upper), log)
    lo, hi = domain.search_bounds()
    coding = Coding(domain.factors, tuple((lo + hi) / 2), tuple((hi - lo) / 2))
    c, q = rng.normal(size=d), rng.normal()

    class Surrogate:
        def predict(self, actual):
            s = domain.to_search(np.asarray(actual, dtype=float))
            return s @ c + q * s[:, 0] * s[:, 1]

    points = lo + rng.uniform(0.1, 0.9, (5, d)) * (hi - lo)
    found = gradient_coded(Surrogate(), domain, coding, points)
    expected = np.tile(c, (5, 1))
    expected[:, 0] += q * points[:, 1]
    expected[:, 1] += q * points[:, 0]
    assert np.allclose(found, expected * (hi - lo) / 2, rtol=1e-6, atol=1e-8)


@pytest.mark.parametrize("length", [1, 5, 11, 12, 40, 401])
def test_a_bands_curve_is_stored_with_at_most_eleven_rows_keeping_both_ends(length):
    from demid.combinations.material import CURVE_ROWS, _curve_rows

    curve = pd.DataFrame({"along": np.arange(length, dtype=float), "mid": np.arange(length) ** 2.0})
    rows = _curve_rows(curve)
    assert CURVE_ROWS == 11 and len(rows) == min(length, 11)
    assert rows["along"].iloc[0] == 0 and rows["along"].iloc[-1] == length - 1
    assert np.all(np.diff(rows["along"]) > 0) and list(rows.index) == list(range(len(rows)))
    if length > 11:  # evenly spread: the gaps differ by at most one row
        gaps = np.diff(rows["along"])
        assert gaps.max() - gaps.min() <= 1


@pytest.mark.parametrize("log", [(False, False), (True, False), (False, True, True)])
def test_a_sets_admitted_grid_nodes_are_its_points_in_search_units_with_the_grid_step(log):
    from demid.combinations.material import admitted_points
    from demid.sampling.domain import Domain

    d = len(log)
    domain = Domain(tuple("abc"[:d]), (0.01, 2.0, 1.0)[:d], (10.0, 8.0, 100.0)[:d], log)
    n = 7
    lo, hi = domain.search_bounds()
    axes = [np.linspace(a, b, n) for a, b in zip(lo, hi)]
    grid = np.array(np.meshgrid(*axes, indexing="ij")).reshape(d, -1).T
    mask = (grid[:, 0] - lo[0]) / (hi[0] - lo[0]) + (grid[:, 1] - lo[1]) / (hi[1] - lo[1]) <= 0.75

    class GridSet:
        points = None

    aset = GridSet()
    aset.mask = mask
    points, step = admitted_points(aset, domain)
    assert np.allclose(points, grid[mask]) and np.allclose(step, (hi - lo) / (n - 1))
    aset.points = domain.to_actual(grid)  # a Sobol-like sample: its admitted points, no grid step
    points, step = admitted_points(aset, domain)
    assert np.allclose(points, grid[mask]) and np.isnan(step).all()
    empty = GridSet()
    empty.mask = np.zeros(0, dtype=bool)
    points, step = admitted_points(empty, domain)
    assert points.shape == (0, d) and np.isnan(step).all()


def test_a_materials_identified_band_gets_the_break_the_ridge_advice_of_the_observable_across_it():
    """End to end on a grid set: y1 = a + b pins the band a + b = 1 (± 2 %); 'across' = a − b changes along it and
    is named, with the angle between its gradient and the identified direction (90°)."""
    from demid.combinations.material import material_combinations
    from demid.design import Coding, quadratic_terms
    from demid.sampling.grid import admissible_set
    from demid.surrogate import Surrogate

    spec = MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "custom"},
        "factors": {"a": {"lower": 0.0, "upper": 1.0}, "b": {"lower": 0.0, "upper": 1.0}},
        "responses": {"y1": {"target": 1.0}, "across": {"target": 0.0}},
        "scenarios": {"band": {"observables": ["y1"], "tolerance": 0.02}}}, grid_points=201)
    terms = quadratic_terms(2)

    def linear(name, slopes):
        coef = np.zeros(len(terms))
        coef[1:3] = slopes
        return Surrogate(name, ["a", "b"], terms, coef, np.zeros((len(terms), len(terms))), 0.0, 1)

    surrogates = {"y1": linear("y1", [1.0, 1.0]), "across": linear("across", [1.0, -1.0])}
    strict = {"band": admissible_set({"y1": surrogates["y1"]}, spec.domain, ["y1"], {"y1": 1.0}, 0.02, 201)}
    found = material_combinations(surrogates, spec, Coding(("a", "b"), (0.5, 0.5), (0.5, 0.5)), strict, {})
    (res,) = found.results
    assert res.identified and res.cut == "none"
    (line,) = found.advice
    assert line.startswith("*band* identifies a combination and leaves its complement free: across changes most "
                           "along the set (its gradient lies 90° off the identified direction)")
    assert found.to_frame()["a"].abs().round(3).tolist() == [0.707, 0.707]


@pytest.mark.parametrize("extent", [1.0, 2.0, 0.5])
def test_a_direction_is_identified_up_to_ten_per_cent_of_its_extent_and_free_from_ninety(extent):
    """The per-factor verdicts' thresholds, boundaries included: a width of exactly 10 % of the box's extent
    along a direction is identified, exactly 90 % free; a hair either side is not."""
    from demid.combinations.axes import PrincipalAxes

    fractions = np.array([0.05, 0.10, np.nextafter(0.10, 1.0), 0.5, np.nextafter(0.90, 0.0), 0.90, 1.2])
    axes = PrincipalAxes(tuple(f"f{i}" for i in range(len(fractions))), np.zeros(len(fractions)),
                         np.eye(len(fractions)), fractions * extent, np.full(len(fractions), extent), 50)
    assert list(axes.width_fraction) == list(fractions)  # a power of two: the division is exact
    assert list(axes.identified) == [True, True, False, False, False, False, False]
    assert list(axes.free) == [False, False, False, False, False, True, True]
    frame = axes.to_frame()
    assert list(frame["width_fraction_of_range"]) == list(fractions)
    assert list(frame["width_coded"]) == list(fractions * extent) and list(frame["direction"]) == list(range(1, 8))

"""The combinations' thresholds, each met exactly by an input a caller can give, and the side a researcher reads:

- a set's narrowest direction is identified at a width of exactly 10 % of the range (band or axes), free along a
  two-factor band that spans exactly 90 % of its wide factor's range;
- a factor takes part in a combination at a loading of exactly 0.2, a combination needs two factors;
- a band is called curved only when its centre line strays by more than a quarter of its width, a 3+ factor set
  only when its straight width is more than twice its local thickness;
- a loading of exactly 0.005 is written in a direction's text, a smaller one is not;
- the JSON's curve keeps a band of exactly 11 columns whole and thins a longer one to 11 rows;
- the band's normals follow its centre line from three columns on; its bend, thickness and span likewise;
- a cell of a curved set counts from exactly 30 points; a band of exactly ``max_columns`` grid columns keeps them;
- the bend leaves out columns cut by the box only while three others remain;
- of two equal largest loadings, the first factor's is the positive one; a set of zero weight has no axes.

Each is compared with a computation written here (numpy's eigenvectors, hand-built curves) or the rule as
documented."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pandas as pd
import pytest

from demid.combinations.axes import (LOCAL_MIN_POINTS, UNIFORM_WIDTH_PER_SD, PrincipalAxes, band_curve, curve_bend,
                                     local_thickness, principal_axes)
from demid.combinations.material import (CURVE_ROWS, LOADING_MIN, STRAIGHT_MAX_BEND, MaterialCombinations,
                                         SetCombination, _curve_rows, _direction_text, set_combinations)
from demid.sampling.domain import IDENTIFIED_MAX_WIDTH, UNRESOLVED_MIN_WIDTH

ABOVE = np.nextafter


def _axes(directions, widths, extents, centre=None, factors=None) -> PrincipalAxes:
    directions = np.asarray(directions, dtype=float)
    d = directions.shape[0]
    return PrincipalAxes(tuple(factors or [f"f{i}" for i in range(d)]),
                         np.zeros(d) if centre is None else np.asarray(centre, dtype=float), directions,
                         np.asarray(widths, dtype=float), np.asarray(extents, dtype=float), 100)


def _material(results, labels=("a", "b", "c")) -> MaterialCombinations:
    d = len(results[0].axes.factors) if results and results[0].axes is not None else len(labels)
    factors = [SimpleNamespace(name=lab, label=lab.upper(), log=False) for lab in labels[:d]]
    spec = SimpleNamespace(factor_names=[f.name for f in factors], factors=factors, scenarios=[])
    coding = SimpleNamespace(unit=np.ones(d), center=np.zeros(d))
    return MaterialCombinations(spec, coding, list(results), [], -np.ones(d), np.ones(d))


# ------------------------------------------------------------------------------------------ identified and free
@pytest.mark.parametrize("band_fraction, identified", [
    (IDENTIFIED_MAX_WIDTH, True), (ABOVE(IDENTIFIED_MAX_WIDTH, 1.0), False), (0.02, True), (0.5, False)])
def test_a_band_is_identified_up_to_exactly_a_tenth_of_the_range(band_fraction, identified):
    axes = _axes(np.eye(2), [0.9, 1.8], [2.0, 2.0])  # its straight width (45 %) is not what is judged
    res = SetCombination("s", "strict", axes, band_fraction=band_fraction)
    assert bool(res.identified) is identified


@pytest.mark.parametrize("width_fraction, identified", [
    (IDENTIFIED_MAX_WIDTH, True), (ABOVE(IDENTIFIED_MAX_WIDTH, 1.0), False)])
def test_without_a_band_the_narrowest_axis_is_identified_up_to_exactly_a_tenth(width_fraction, identified):
    axes = _axes(np.eye(3), [2.0 * width_fraction, 1.5, 1.9], [2.0, 2.0, 2.0])
    assert axes.width_fraction[0] == width_fraction
    assert SetCombination("s", "strict", axes).identified is identified
    assert SetCombination("s", "strict", None).identified is False


@pytest.mark.parametrize("span, free", [(UNRESOLVED_MIN_WIDTH, True), (np.nextafter(UNRESOLVED_MIN_WIDTH, 0.0), False),
                                        (1.0, True), (0.3, False)])
def test_a_band_is_free_along_itself_when_it_spans_at_least_nine_tenths_of_its_factor(span, free):
    directions = np.array([[0.6, -0.8], [0.8, 0.6]])
    curve = pd.DataFrame({"along": [0.0, 0.5, 1.0], "mid": [0.0, 0.0, 0.0]})
    res = SetCombination("s", "strict", _axes(directions, [0.1, 1.5], [2.8, 2.8]), curve=curve, band_span=span,
                         band_fraction=0.05)
    expected = directions[:, 1:] if free else directions[:, :0]
    assert np.array_equal(res.free, expected)
    # without a band (3 factors) the axes' own 90 % rule: a width of exactly 90 % of the extent is free
    axes = _axes(np.eye(3), [0.1, 1.8, np.nextafter(1.8, 0.0)], [2.0, 2.0, 2.0])
    assert np.array_equal(SetCombination("s", "strict", axes).free, np.eye(3)[:, [1]])


# ------------------------------------------------------------------------------------------ in combination
@pytest.mark.parametrize("small, joins", [(LOADING_MIN, True), (np.nextafter(LOADING_MIN, 0.0), False)])
def test_a_factor_joins_a_combination_at_a_loading_of_exactly_the_minimum(small, joins):
    """Three factors: c loads 0.9, b loads ``small``, a the rest; a joins always, b only from 0.2 on."""
    c = 0.9
    a = float(np.sqrt(1.0 - c ** 2 - small ** 2))
    direction = np.array([a, small, c])
    others = np.linalg.qr(np.column_stack([direction, np.eye(3)[:, :2]]))[0][:, 1:]
    axes = _axes(np.column_stack([direction, others]), [0.05, 1.9, 1.9], [2.0, 2.0, 2.0])
    combos = _material([SetCombination("s1", "strict", axes)]).in_combination()
    part = ["a", "b", "c"] if joins else ["a", "c"]
    assert combos == {"s1": {f: [g for g in part if g != f] for f in part}}


def test_one_factor_alone_is_no_combination_and_cut_unidentified_or_other_sets_are_left_out():
    lone = _axes(np.eye(3), [0.05, 1.9, 1.9], [2.0, 2.0, 2.0])  # the narrowest direction is factor a alone
    pair_dir = np.array([0.6, 0.8, 0.0])
    pair = _axes(np.column_stack([pair_dir, [-0.8, 0.6, 0.0], [0, 0, 1.0]]), [0.1, 1.9, 1.9], [2.8, 2.8, 2.0])
    results = [SetCombination("lone", "strict", lone), SetCombination("pair", "strict", pair),
               SetCombination("cut", "strict", pair, cut="lower"),
               SetCombination("wide", "strict", pair, band_fraction=0.2),
               SetCombination("plaus", "plausible", pair)]
    material = _material(results)
    assert material.in_combination() == {"pair": {"a": ["b"], "b": ["a"]}}
    assert material.in_combination("plausible") == {"plaus": {"a": ["b"], "b": ["a"]}}


# ------------------------------------------------------------------------------------------ sentences
def _band(bend: float) -> SetCombination:
    curve = pd.DataFrame({"along": [-1.0, 0.0, 1.0], "lower": [0.0] * 3, "mid": [0.05] * 3, "upper": [0.1] * 3})
    return SetCombination("s", "strict", _axes(np.eye(2)[:, ::-1], [0.1, 1.8], [2.0, 2.0]), curve=curve, wide=0,
                          narrow=1, bend=bend, band_fraction=0.05, band_span=0.5, statement="B = 0.05 ± 0.05")


@pytest.mark.parametrize("bend, curved", [(STRAIGHT_MAX_BEND, False), (ABOVE(STRAIGHT_MAX_BEND, 1.0), True),
                                          (float("nan"), False)])
def test_a_band_is_called_curved_only_beyond_a_quarter_of_its_width(bend, curved):
    text = _material([_band(bend)], labels=("a", "b")).sentences(_band(bend))
    if curved:
        assert text == "a curved band: B ≈ f(A) along the band, 5.0 % of the range thick."
    else:
        assert text == "B = 0.05 ± 0.05 (5.0 % of the range along it)."


@pytest.mark.parametrize("ratio, curved", [(2.0, False), (ABOVE(2.0, 3.0), True)])
def test_a_set_in_three_factors_is_called_curved_when_its_straight_width_exceeds_twice_its_thickness(ratio, curved):
    thickness = 0.03
    widths = np.array([ratio * thickness * 2.0, 1.9, 1.95])  # extents of 2: straight width fraction ratio * 0.03
    axes = _axes(np.eye(3), widths, [2.0, 2.0, 2.0])
    local = SimpleNamespace(fraction=thickness)
    res = SetCombination("s", "strict", axes, band_fraction=thickness, local=local, statement="A = 0 ± 0.06")
    text = _material([res]).sentences(res)
    assert axes.width_fraction[0] == pytest.approx(ratio * thickness, rel=1e-15)
    if curved:
        assert text.startswith("a curved set, 3.0 % of the range thick along its local normal; the best straight "
                               "approximation, A = 0 ± 0.06, is 6 % wide; free along (1.00·B), (1.00·C)."), text
    else:
        assert text == "A = 0 ± 0.06 (3.0 % of the range along it); free along (1.00·B), (1.00·C).", text


def test_the_other_sentences_quote_the_widths_they_judge():
    unidentified = SetCombination("s", "strict", _axes(np.eye(2), [0.5, 1.8], [2.0, 2.0]))
    small = SetCombination("s", "strict", _axes(np.eye(2), [0.1, 0.2], [2.0, 2.0]), statement="A = 0 ± 0.05")
    cut = SetCombination("s", "strict", _axes(np.eye(2), [0.1, 1.8], [2.0, 2.0]), cut="both", statement="A = 0")
    material = _material([unidentified], labels=("a", "b"))
    assert material.sentences(unidentified) == ("no combination is identified: the set is 25 % of the range wide "
                                                "across its narrowest direction.")
    assert material.sentences(small) == ("every direction is identified (a small region; widths 5.0 %, 10.0 % of "
                                         "the range along its axes): A = 0 ± 0.05.")
    assert material.sentences(cut).startswith("A = 0, but the set reaches the search range's both ends along this "
                                              "direction")
    assert material.sentences(SetCombination("s", "strict", None)) == "no admissible point."


@pytest.mark.parametrize("loading, shown", [(0.005, True), (np.nextafter(0.005, 0.0), False), (-0.005, True)])
def test_a_loading_of_exactly_half_a_hundredth_is_written_and_a_smaller_one_is_not(loading, shown):
    text = _direction_text(np.array([0.8, loading, -0.6]), ["A", "B", "C"])
    sign = "−" if loading < 0 else "+"
    assert text == (f"(0.80·A {sign} {abs(loading):.2f}·B − 0.60·C)" if shown else "(0.80·A − 0.60·C)")
    assert _direction_text(np.array([-0.6, 0.8]), ["A", "B"]) == "(−0.60·A + 0.80·B)"


# ------------------------------------------------------------------------------------------ the band's curve
@pytest.mark.parametrize("columns", [CURVE_ROWS - 1, CURVE_ROWS, CURVE_ROWS + 1, 3 * CURVE_ROWS])
def test_the_curve_in_the_json_keeps_up_to_eleven_columns_whole_and_thins_longer_ones_evenly(columns):
    curve = pd.DataFrame({"along": np.arange(columns, dtype=float), "mid": np.arange(columns) * 0.5})
    rows = _curve_rows(curve)
    if columns <= CURVE_ROWS:
        assert rows["along"].tolist() == list(range(columns))
    else:
        expected = sorted({int(round(v)) for v in np.linspace(0, columns - 1, CURVE_ROWS)})
        assert rows["along"].tolist() == expected and len(rows) == CURVE_ROWS
        assert rows.index.tolist() == list(range(len(rows)))


@pytest.mark.parametrize("columns", [2, 3, 4])
def test_a_band_of_three_columns_has_a_curve_bend_thickness_span_and_normals(columns):
    """A straight band b = 0.5 a + c on ``columns`` grid columns: from three on, its bend (the centre line's
    largest distance from the line along numpy's narrowest eigenvector, over √12 σ), its thickness (the
    column width over |slope| range_a + range_b, the median over columns), its span and its normals follow the
    centre line; with two columns none of them."""
    along = np.linspace(-0.9, 0.9, columns)
    across = np.array([-0.04, 0.0, 0.04])
    points = np.array([(a, 0.5 * a + b) for a in along for b in across])
    lower, upper = np.array([-1.0, -1.0]), np.array([1.0, 1.0])
    res = set_combinations(points, lower, upper, ["a", "b"], scenario="s", set_name="strict", step=[0.01, 0.01])
    normal = np.array([-0.5, 1.0]) / np.hypot(0.5, 1.0)
    probe = np.array([[0.1, 0.05], [-0.5, -0.2]])
    if columns >= 3:
        centre = points.mean(axis=0)
        values, vectors = np.linalg.eigh(np.cov(points.T, bias=True))
        mids = np.column_stack([along, 0.5 * along])
        bend = np.max(np.abs((mids - centre) @ vectors[:, 0])) / (UNIFORM_WIDTH_PER_SD * np.sqrt(values[0]))
        assert res.bend == pytest.approx(bend, rel=1e-9)
        assert res.band_fraction == pytest.approx(0.08 / (0.5 * 2.0 + 2.0), rel=1e-9)
        assert res.band_span == pytest.approx(0.9, rel=1e-12)
        assert np.allclose(res.normals_at(probe), normal, atol=1e-9)
    else:
        assert np.isnan(res.bend) and np.isnan(res.band_fraction) and np.isnan(res.band_span)
        assert res.normals_at(probe) is None
    assert (res.wide, res.narrow) == (0, 1)


@pytest.mark.parametrize("extra", [0, 1])
def test_a_band_of_exactly_max_columns_grid_columns_keeps_its_columns(extra):
    columns = 6
    along = np.array([0.0, 0.1, 0.3, 0.5, 0.7, 0.9])  # uneven: five bins would merge the first two
    points = np.array([(a, a ** 2 + b) for a in along for b in (-0.1, 0.0, 0.1)])
    curve = band_curve(points, 0, 1, max_columns=columns - extra)
    if extra == 0:
        assert np.allclose(curve["along"], along, atol=1e-15)
        assert np.allclose(curve["mid"], along ** 2, atol=1e-12)
    else:  # bins of equal width over the range: the along value is the mean of the points in each bin
        edges = np.linspace(0.0, 0.9, columns)
        index = np.clip(np.searchsorted(edges, points[:, 0], side="right") - 1, 0, columns - 2)
        means = [points[index == k, 0].mean() for k in range(columns - 1)]
        assert len(curve) == columns - 1 and np.allclose(curve["along"], means)
        lows = [points[index == k, 1].min() for k in range(columns - 1)]
        assert np.allclose(curve["lower"], lows)


@pytest.mark.parametrize("side", ["upper", "lower"])
@pytest.mark.parametrize("clear_columns", [2, 3])
def test_the_bend_leaves_out_cut_columns_only_while_three_clear_ones_remain(clear_columns, side):
    step = 0.01
    n = 5
    along = np.linspace(-0.8, 0.8, n)
    mid = np.array([0.08, 0.02, -0.01, 0.03, 0.0])  # the first column, cut in both cases, strays most
    lower, upper = mid - 0.1, mid + 0.1
    cut = n - clear_columns
    if side == "upper":
        upper[:cut] = 1.0 - step  # within 1.5 steps of the box's upper across-bound
    else:
        lower[:cut] = -1.0 + step  # within 1.5 steps of its lower one
    curve = pd.DataFrame({"along": along, "lower": lower, "mid": mid, "upper": upper})
    axes = _axes(np.eye(2)[:, ::-1], [0.2, 1.5], [2.0, 2.0])  # normal along the second (across) factor
    bend = curve_bend(curve, axes, 0, 1, [-1.0, -1.0], [1.0, 1.0], step)
    kept = mid[cut:] if clear_columns >= 3 else mid
    assert bend == pytest.approx(np.max(np.abs(kept)) / 0.2, rel=1e-12)


# ------------------------------------------------------------------------------------------ axes
@pytest.mark.parametrize("drop", [0, 1])
def test_a_cell_of_a_curved_set_counts_from_exactly_thirty_points(drop):
    """A straight band in two factors cut into eight cells along it, exactly 30 points each (15 positions, one
    point either side of the centre line): every cell counts, with the width √12 σ of its points across; a point
    taken out of one cell drops that cell."""
    assert LOCAL_MIN_POINTS == 30
    half, delta = 15, 0.05
    t = np.array([k + (j + 0.5) / half for k in range(8) for j in range(half)]) / 8.0 * 1.6 - 0.8
    points = np.array([(x, s * delta) for x in t for s in (-1.0, 1.0)])
    if drop:
        points = np.delete(points, 5, axis=0)  # a point of the first cell
    axes = principal_axes(points, [-1.0, -1.0], [1.0, 1.0])
    local = local_thickness(points, axes, [-1.0, -1.0], [1.0, 1.0])
    counts = [30] * 8 if not drop else [30] * 7
    assert local.counts.tolist() == counts
    cells = [points[30 * k:30 * (k + 1)] for k in range(8)] if not drop else [
        points[29 + 30 * (k - 1):29 + 30 * k] for k in range(1, 8)]
    expected = [UNIFORM_WIDTH_PER_SD * np.sqrt(np.linalg.eigvalsh(np.cov(c.T, bias=True))[0]) for c in cells]
    assert np.allclose(local.widths, expected, rtol=1e-9)
    assert np.allclose(local.widths, UNIFORM_WIDTH_PER_SD * delta, rtol=1e-9)
    assert np.allclose(local.fractions, local.widths / 2.0)
    assert np.allclose(np.abs(local.normals[:, 1]), 1.0)
    none = local_thickness(points[:29], principal_axes(points[:29], [-1, -1], [1, 1]), [-1, -1], [1, 1], cells=1)
    assert none is None
    one = local_thickness(points[:30], principal_axes(points[:30], [-1, -1], [1, 1]), [-1, -1], [1, 1], cells=1)
    assert one.counts.tolist() == [30]


def test_of_two_equal_largest_loadings_the_first_factors_is_positive_and_zero_weight_is_no_set():
    """A band along a = -b (its normal (1, 1)/√2 up to sign) and along a = b (normal (1, -1)/√2): the loadings tie
    in size, and the first factor's is made positive."""
    s = np.linspace(-0.8, 0.8, 41)
    for along, normal in (((1.0, -1.0), (1.0, 1.0)), ((1.0, 1.0), (1.0, -1.0))):
        points = np.array([(u * along[0] + v * normal[0], u * along[1] + v * normal[1])
                           for u in s for v in (-0.02, 0.02)]) / np.sqrt(2.0)
        axes = principal_axes(points, [-1, -1], [1, 1])
        assert np.allclose(axes.directions[:, 0], np.array(normal) / np.sqrt(2.0), atol=1e-9)
        assert axes.directions[0, 0] > 0 and axes.directions[0, 1] > 0
    assert principal_axes(np.ones((3, 2)), [-1, -1], [1, 1], weights=np.zeros(3)) is None
    assert principal_axes(np.zeros((0, 2)), [-1, -1], [1, 1]) is None


def test_a_set_without_axes_leaves_no_direction_free():
    """No axes (an empty set): no free direction at all, in no dimension (not one empty column)."""
    free = SetCombination("s", "strict", None).free
    assert free.shape == (0, 0)

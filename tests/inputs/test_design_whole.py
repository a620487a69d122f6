"""Every public function of demid.design against a brute-force or closed-form construction written in the test,
over one to four factors: the model's terms (every monomial of the degree, in the documented order, named and
parsed back), the model matrix, log units, the coding from a table's levels, the CCD and Box-Behnken points (Yates
order, axial pairs, centres) and their labels, snapping to levels, the replicate groups, and the axial distances a
CCD's table cannot tell apart (each quoted number read back, on both thresholds)."""

from __future__ import annotations

import itertools
import math
import re

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.design import (INTERCEPT, LEVEL_TOLERANCE, Coding, DesignStructure, axial_distances, box_behnken_points,
                          ccd_points, classify_points, cubic_terms, factor_levels, model_matrix, model_units,
                          nominal_levels, parse_term, quadratic_terms, replicate_groups, rotatable_alpha,
                          snap_to_factor_levels, snap_to_levels, term_name, unreadable_alpha)

SETTINGS = settings(max_examples=15, deadline=None, derandomize=True)


def _monomials(k: int, degree: int) -> set[tuple[int, ...]]:
    return {p for p in itertools.product(range(degree + 1), repeat=k) if sum(p) == degree}


@pytest.mark.parametrize("k", [1, 2, 3, 4])
def test_quadratic_terms_are_every_monomial_up_to_two_in_the_documented_order(k):
    terms = quadratic_terms(k)
    assert len(terms) == len(set(terms)) == (k + 1) * (k + 2) // 2
    assert set(terms) == _monomials(k, 0) | _monomials(k, 1) | _monomials(k, 2)
    assert terms[0] == (0,) * k
    assert terms[1:k + 1] == [tuple(int(i == j) for i in range(k)) for j in range(k)]
    pairs = [tuple(int(i in (a, b)) for i in range(k)) for a, b in itertools.combinations(range(k), 2)]
    assert terms[k + 1:k + 1 + len(pairs)] == pairs
    assert terms[k + 1 + len(pairs):] == [tuple(2 * int(i == j) for i in range(k)) for j in range(k)]


@pytest.mark.parametrize("k", [1, 2, 3, 4])
def test_cubic_terms_are_every_third_order_monomial_cubes_first(k):
    terms = cubic_terms(k)
    assert len(terms) == len(set(terms)) == math.comb(k + 2, 3)
    assert set(terms) == _monomials(k, 3)
    assert terms[:k] == [tuple(3 * int(i == j) for i in range(k)) for j in range(k)]
    assert all(max(t) < 3 for t in terms[k:])


def _name_written_out(term, factors):
    parts = [f if p == 1 else f"{f}^{p}" for f, p in zip(factors, term) if p]
    return ":".join(parts) or INTERCEPT


@pytest.mark.parametrize("k", [1, 2, 3])
def test_every_term_is_named_and_parsed_back(k):
    factors = [f"x{i}" for i in range(k)]
    for term in quadratic_terms(k) + cubic_terms(k):
        name = term_name(term, factors)
        assert name == _name_written_out(term, factors)
        assert parse_term(name, factors) == term
    assert parse_term("x0:x0", factors) == (2,) + (0,) * (k - 1)
    with pytest.raises(ValueError, match="unknown factor 'q'"):
        parse_term("q", factors)


@given(k=st.integers(1, 4), n=st.integers(1, 9), seed=st.integers(0, 10_000), cubic=st.booleans())
@SETTINGS
def test_the_model_matrix_is_each_term_s_product_of_powers(k, n, seed, cubic):
    x = np.random.default_rng(seed).uniform(-3, 3, size=(n, k))
    terms = quadratic_terms(k) + (cubic_terms(k) if cubic else [])
    want = np.array([[np.prod([xi ** p for xi, p in zip(row, t)]) for t in terms] for row in x])
    np.testing.assert_allclose(model_matrix(x, terms), want, rtol=1e-12, atol=1e-12)
    logs = [f"x{i}" for i in range(k) if i % 2 == 0]
    positive = np.abs(x) + 0.1
    z = model_units(positive, [f"x{i}" for i in range(k)], logs)
    np.testing.assert_allclose(z, np.where([i % 2 == 0 for i in range(k)], np.log10(positive), positive))
    assert z is not positive and np.array_equal(positive, np.abs(x) + 0.1)  # a copy: the input unchanged


@given(k=st.integers(1, 4), seed=st.integers(0, 10_000), alpha=st.sampled_from([1.0, 1.414, 2.0]))
@SETTINGS
def test_the_coding_from_levels_is_mid_range_and_half_range_over_alpha(k, seed, alpha):
    rng = np.random.default_rng(seed)
    actual = rng.uniform(-50, 50, size=(7, k))
    actual[:, -1] = 4.0  # a column at one level: unit 1
    code = Coding.from_levels([f"x{i}" for i in range(k)], actual, alpha)
    lo, hi = actual.min(axis=0), actual.max(axis=0)
    np.testing.assert_allclose(code.center, (lo + hi) / 2)
    want_unit = np.where(hi > lo, (hi - lo) / (2 * alpha), 1.0)
    np.testing.assert_allclose(code.unit, want_unit)
    coded = code.to_coded(actual)
    np.testing.assert_allclose(coded, (actual - (lo + hi) / 2) / want_unit)
    np.testing.assert_allclose(code.to_actual(coded), actual)
    if k > 1:
        np.testing.assert_allclose(coded[:, :-1].max(axis=0), alpha)
        np.testing.assert_allclose(coded[:, :-1].min(axis=0), -alpha)


@pytest.mark.parametrize("k", [1, 2, 3, 4])
@pytest.mark.parametrize("centres", [0, 1, 4])
def test_ccd_points_are_yates_factorial_then_axial_pairs_then_centres(k, centres):
    alpha = 1.5
    pts = ccd_points(k, alpha, centres)
    fact = np.array([[(-1.0 if (r >> i) & 1 == 0 else 1.0) for i in range(k)] for r in range(2 ** k)])
    axial = np.zeros((2 * k, k))
    for i in range(k):
        axial[2 * i, i], axial[2 * i + 1, i] = -alpha, alpha
    np.testing.assert_array_equal(pts, np.vstack([fact, axial, np.zeros((centres, k))]))
    np.testing.assert_allclose(ccd_points(k, None, 0)[2 ** k + 1, 0], 2 ** (k / 4))
    assert rotatable_alpha(k) == pytest.approx(2 ** (k / 4))
    labels = classify_points(pts, alpha)
    assert list(labels) == ["factorial"] * 2 ** k + ["axial"] * 2 * k + ["center"] * centres
    per_factor = np.linspace(1.2, 1.6, k)
    skewed = ccd_points(k, per_factor, centres)
    np.testing.assert_allclose(np.abs(skewed[2 ** k:2 ** k + 2 * k]).max(axis=0), per_factor)
    assert list(classify_points(skewed, per_factor)) == list(labels)


@pytest.mark.parametrize("k", [1, 2, 3, 4])
def test_ccd_points_by_default_are_the_rotatable_ccd_with_five_centre_runs(k):
    """The default the README's studies use: alpha = (2^k)^(1/4), five centre runs after the 2^k + 2k others."""
    pts = ccd_points(k)
    assert pts.shape == (2 ** k + 2 * k + 5, k)
    np.testing.assert_array_equal(pts, ccd_points(k, 2 ** (k / 4), 5))
    assert not pts[-5:].any() and np.all(np.abs(pts[:-5]).max(axis=1) > 0)


@pytest.mark.parametrize("k", [3, 4])
def test_box_behnken_points_are_a_square_on_every_pair_then_centres(k):
    pts = box_behnken_points(k, 2)
    pairs = list(itertools.combinations(range(k), 2))
    assert len(pts) == 4 * len(pairs) + 2
    for n, (i, j) in enumerate(pairs):
        block = pts[4 * n:4 * n + 4]
        assert {(a, b) for a, b in block[:, [i, j]]} == {(-1, -1), (-1, 1), (1, -1), (1, 1)}
        assert not np.delete(block, [i, j], axis=1).any()
    assert list(classify_points(pts, 1.0)) == ["edge"] * (4 * len(pairs)) + ["center"] * 2
    assert classify_points(np.array([[0.5] * k]), 1.0)[0] == "other"


def test_a_design_structure_describes_its_counts():
    assert DesignStructure(13, 4, 4, 5, 0, 1.41).describe() == "13 runs: 4 factorial, 4 axial, 5 centre"
    assert DesignStructure(14, 4, 4, 5, 1, 1.41).describe() == "14 runs: 4 factorial, 4 axial, 5 centre, 1 other"


@given(k=st.integers(1, 4), seed=st.integers(0, 10_000), design=st.sampled_from(["ccd", "box_behnken", "factorial"]),
       alpha=st.sampled_from([1.0, 1.0 + 1e-10, 1.3, 2.0]))
@SETTINGS
def test_values_snap_to_the_nearest_level_of_their_factor(k, seed, design, alpha):
    levels = nominal_levels(design, alpha)
    want_levels = [-alpha, -1.0, 0.0, 1.0, alpha] if design == "ccd" and abs(alpha - 1) > 1e-9 else [-1.0, 0.0, 1.0]
    np.testing.assert_array_equal(levels, want_levels)
    coded = np.random.default_rng(seed).uniform(-2.5, 2.5, size=(6, k))
    snapped = snap_to_levels(coded, levels)
    np.testing.assert_array_equal(snapped, [[min(levels, key=lambda v: abs(c - v)) for c in row] for row in coded])
    per_factor = np.linspace(1.1, 1.9, k)
    factor_lv = factor_levels("ccd", per_factor, k)
    assert [list(lv) for lv in factor_lv] == [[-a, -1.0, 0.0, 1.0, a] for a in per_factor]
    np.testing.assert_array_equal(axial_distances(1.3, k), [1.3] * k)
    np.testing.assert_array_equal(
        snap_to_factor_levels(coded, factor_lv),
        [[min(lv, key=lambda v: abs(c - v)) for c, lv in zip(row, factor_lv)] for row in coded])


@given(seed=st.integers(0, 10_000), k=st.integers(1, 3), n=st.integers(1, 12))
@SETTINGS
def test_replicate_groups_join_the_runs_equal_to_six_decimals(seed, k, n):
    rng = np.random.default_rng(seed)
    base = rng.integers(-1, 2, size=(n, k)).astype(float)
    coded = base + rng.choice([0.0, 4e-7, 3e-6], size=(n, k))  # below and above the sixth decimal's half
    groups = replicate_groups(coded)
    keys = [tuple(np.round(row, 6)) for row in coded]
    for a in range(n):
        for b in range(n):
            assert (groups[a] == groups[b]) == (keys[a] == keys[b])
    assert sorted(set(groups.tolist())) == list(range(len(set(keys))))


def _numbers(text: str) -> list[float]:
    return [float(v) for v in re.findall(r"\d+(?:\.\d+)?", text)]


def test_axial_distances_the_table_cannot_tell_apart_on_and_past_each_threshold():
    low, high = 1 + 2 * LEVEL_TOLERANCE, 1 / LEVEL_TOLERANCE
    assert (low, high) == (1.04, 50.0)
    for alpha in (1.0, low, 1.2, 2.0, high):
        assert unreadable_alpha(alpha) is None, alpha
    for alpha in (1.001, 1.039, 1.0399):
        text = unreadable_alpha(alpha)
        assert text.startswith("puts the axial levels")
        gap, one, least = _numbers(text)  # "... 0.039 coded units ...; use 1 (face-centred) or at least 1.04"
        assert one == 1.0
        assert gap == pytest.approx(float(f"{alpha - 1:.3g}")) and least == low
    for alpha in (50.01, 80.0):
        text = unreadable_alpha(alpha)
        assert text.startswith("puts the factorial levels")
        shown, most = _numbers(text.replace("1/", ""))[:2]
        assert shown == pytest.approx(float(f"{alpha:g}")) and most == high


def _ccd_table(k: int, alpha: float, centres: int):
    import pandas as pd

    centre, half = np.array([0.5, 6.0, -20.0, 1500.0])[:k], np.array([0.2, 2.5, 4.0, 250.0])[:k]
    names = [f"x{i + 1}" for i in range(k)]
    coded = ccd_points(k, alpha, centres)
    table = pd.DataFrame({"run": np.arange(1, len(coded) + 1),
                          **{n: centre[i] + coded[:, i] * half[i] for i, n in enumerate(names)}})
    return table, names, coded, centre, half


@pytest.mark.parametrize("k", [2, 3, 4])
@pytest.mark.parametrize("kind, which", [("factorial", 0), ("factorial", -1), ("axial", 0), ("axial", -1),
                                         ("centre", 0), ("centre", -1)])
def test_a_run_of_any_kind_typed_onto_no_point_names_the_one_value_that_restores_it(k, kind, which):
    """One cell of a CCD's run typed as another level, making a point of no kind: the design is short of one
    point of that run's kind (factorial 2^k, axial 2k, centres as declared), and the one value restoring it
    is named with that kind, in actual units."""
    from demid.design_check import check_design
    from demid.errors import InputError

    alpha = 1.5
    table, names, coded, centre, half = _ccd_table(k, alpha, 3)
    rows = {"factorial": range(2 ** k), "axial": range(2 ** k, 3 * k + 2 ** k - k),
            "centre": range(2 ** k + 2 * k, len(coded))}[kind]
    i = list(rows)[which]
    if kind == "axial":
        column = 0 if coded[i, 0] == 0 else 1  # a zero coordinate typed as the factorial level +1
        typed = 1.0
    else:  # a factorial run's first level typed as the centre; a centre run's as the factorial +1
        column, typed = 0, (0.0 if kind == "factorial" else 1.0)
    true_value = table.loc[i, names[column]]
    table.loc[i, names[column]] = centre[column] + typed * half[column]
    with pytest.raises(InputError) as err:
        check_design(table, names, {"type": "ccd", "alpha": alpha, "center_runs": 3}, "t.csv", "materials.m")
    text = str(err.value)
    said = re.search(rf"with {names[column]} = ([-\d.e+]+) it would be the {kind} run the design is short of", text)
    assert said, text
    assert float(said.group(1)) == pytest.approx(true_value, rel=1e-6, abs=1e-9)
    assert err.value.run == i + 1


@given(seed=st.integers(0, 10_000), k=st.integers(1, 3), odd=st.integers(0, 3), tie=st.booleans())
@settings(max_examples=25, deadline=None, derandomize=True)
def test_values_off_the_value_their_level_usually_reads_are_each_named_with_both_numbers(seed, k, odd, tie):
    """Per factor and level, the value most runs at it read (strictly most: a tie names nothing) and every run
    that reads another value, with both numbers and the count; a level held by one run has nothing to compare."""
    import pandas as pd

    from demid.design_check import odd_level_values

    rng = np.random.default_rng(seed)
    levels = np.array([-1.0, 0.0, 1.0])
    snapped = rng.choice(levels, size=(12, k))
    snapped[:6, 0] = 0.0  # six runs at the centre of the first factor
    values = 5.0 + 2.0 * snapped
    off = rng.choice(6, size=min(odd, 2), replace=False) if not tie else np.arange(3)
    values[off, 0] += 0.0003 * (1 + np.arange(len(off)) % 2)
    if tie:  # three read 5.0003 or 5.0006, three 5.0: a tie between 5.0 and no single other value
        values[off, 0] = 5.0003
    table = pd.DataFrame({"run": np.arange(101, 113), **{f"x{j}": values[:, j] for j in range(k)}})
    got = odd_level_values(table, [f"x{j}" for j in range(k)], snapped, "t.csv")
    want = []
    for j in range(k):
        for level in np.unique(snapped[:, j]):
            rows = np.flatnonzero(snapped[:, j] == level)
            distinct, counts = np.unique(values[rows, j], return_counts=True)
            if len(distinct) < 2 or counts.max() < 2 or (counts == counts.max()).sum() > 1:
                continue
            usual = distinct[np.argmax(counts)]
            want += [(101 + i, f"x{j}", values[i, j], int(counts.max()), usual) for i in rows
                     if values[i, j] != usual]
    said = [re.match(r"t\.csv, run (\d+), column '(\w+)': (\S+), where the other (\d+) runs at this level read "
                     r"(\S+) \(fitted as recorded; a typo\?\)$", text).groups() for text in got]
    assert [(int(r), c, float(v), int(n), float(u)) for r, c, v, n, u in said] == [
        (r, c, pytest.approx(v, rel=1e-9), n, pytest.approx(u, rel=1e-9)) for r, c, v, n, u in want]
    if tie:
        assert not any("column 'x0'" in text and ", where the other 3 runs" in text for text in got)

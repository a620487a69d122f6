"""The design check's known answers (demid/design_check.py): the coding recovered from a CCD table for 2-4 factors
(the centre and half-range of each factor, also when no run sits at the centre), the axial distance the runs show
when one printed axial level carries more digits than another, the repair named for a run typed onto no point
of the design or onto another run's point, missing points named and counted, each value parsed back."""

from __future__ import annotations

import re

import numpy as np
import pandas as pd
import pytest

from demid.design import ccd_points
from demid.design_check import _ccd_alpha_of_table, check_design, infer_coding
from demid.design_generation import factorial_points
from demid.errors import InputError

_CENTRE = np.array([0.5, 6.0, -20.0, 1500.0])
_HALF = np.array([0.2, 2.5, 4.0, 250.0])


def _ccd_table(k: int, alpha: float, centres: int) -> tuple[pd.DataFrame, list[str]]:
    names = [f"x{i + 1}" for i in range(k)]
    coded = ccd_points(k, alpha, centres)
    actual = _CENTRE[:k] + coded * _HALF[:k]
    table = pd.DataFrame({"run": np.arange(1, len(coded) + 1), **{n: actual[:, i] for i, n in enumerate(names)}})
    return table, names


@pytest.mark.parametrize("k", [2, 3, 4])
@pytest.mark.parametrize("rotatable", [False, True])
@pytest.mark.parametrize("face", [False, True])
def test_the_coding_of_a_ccd_table_is_its_centre_and_factorial_half_range(k, rotatable, face):
    alpha = 1.0 if face else (2 ** k) ** 0.25 if rotatable else 1.5
    table, names = _ccd_table(k, alpha, 3)
    design = {"type": "ccd", "alpha": alpha, "center_runs": 3}
    coding, _ = check_design(table, names, design, "t.csv", "materials.m")
    assert np.allclose(coding.center, _CENTRE[:k]) and np.allclose(coding.unit, _HALF[:k])
    assert coding.factors == tuple(names)


@pytest.mark.parametrize("k", [2, 3])
def test_without_a_centre_run_the_centre_is_the_middle_of_the_factorial_levels(k):
    """A factor with no run at its centre level (here: a two-level factorial's corners and its axial runs): the
    centre is the mean of the -1 and +1 levels, the unit their half-distance."""
    table, names = _ccd_table(k, 1.5, 1)
    table = table[np.any(np.abs(table[names].to_numpy() - _CENTRE[:k]) > 1e-9, axis=1)].reset_index(drop=True)
    coding = infer_coding(table, names, {"type": "ccd", "alpha": 1.5, "center_runs": 1}, "t.csv")
    assert np.allclose(coding.center, _CENTRE[:k]) and np.allclose(coding.unit, _HALF[:k])


def test_the_axial_distance_the_runs_show_merges_printed_forms_of_one_level():
    """One axial level printed with a difference in its tenth digit in two rows is one level: the runs show one
    axial distance (a difference below the ninth digit is round-off, not another level)."""
    table, names = _ccd_table(2, 2 ** 0.5, 2)
    (row,) = np.flatnonzero(np.isclose(table["x1"], 0.5 + 2 ** 0.5 * 0.2))
    table = pd.concat([table, table.iloc[[row]]], ignore_index=True)  # the axial run replicated
    # 0.78284271247 printed as 0.78284271012 in one row and 0.7828427104 in the other
    table.loc[row, "x1"] = 0.78284271012
    table.loc[len(table) - 1, "x1"] = 0.7828427104
    assert _ccd_alpha_of_table(table, names) == pytest.approx(2 ** 0.5, rel=1e-7)
    # five levels but a ratio that is not one: no CCD
    table.loc[[row, len(table) - 1], "x1"] = 0.5 + 1.2 * 0.2
    assert _ccd_alpha_of_table(table, names) is None


@pytest.mark.parametrize("k, run, column", [(2, 3, 1), (3, 5, 2), (3, 0, 0)])
def test_a_factorial_run_typed_onto_no_point_names_the_value_that_restores_it(k, run, column):
    """A factorial run whose value in one factor is typed as the centre level (a point of no kind): the design
    is short of that factorial point, and the one value restoring it is named, in actual units."""
    table, names = _ccd_table(k, 2.0, 3)
    factorial = np.all(np.abs(table[names].to_numpy() - _CENTRE[:k]) > 0.99 * _HALF[:k], axis=1)
    i = np.flatnonzero(factorial)[run]
    true_value = table.loc[i, names[column]]
    table.loc[i, names[column]] = _CENTRE[column]
    with pytest.raises(InputError) as err:
        check_design(table, names, {"type": "ccd", "alpha": 2.0, "center_runs": 3}, "t.csv", "materials.m")
    text = str(err.value)
    said = re.search(rf"with {names[column]} = ([-\d.e+]+) it would be the factorial run the design is short of", text)
    assert said, text
    assert float(said.group(1)) == pytest.approx(true_value, rel=1e-6)


def _points_said(text: str, names: list[str]) -> list[dict]:
    """Every "(x1 0.3, x2 6)" point a message shows, as factor -> value."""
    out = []
    for group in re.findall(r"\((x1 [^()]*)\)", text):
        parts = dict(p.rsplit(" ", 1) for p in group.split(", "))
        if set(parts) == set(names):
            out.append({n: float(v) for n, v in parts.items()})
    return out


@pytest.mark.parametrize("k, removed", [(2, 1), (3, 1), (3, 2)])
def test_a_ccd_missing_axial_runs_names_the_first_missing_point_and_how_many_more(k, removed):
    table, names = _ccd_table(k, 1.5, 3)
    coded = (table[names].to_numpy() - _CENTRE[:k]) / _HALF[:k]
    axial = np.flatnonzero(np.sum(np.abs(coded) > 1e-9, axis=1) == 1)
    table = table.drop(index=axial[:removed]).reset_index(drop=True)
    with pytest.raises(InputError) as err:
        check_design(table, names, {"type": "ccd", "alpha": 1.5, "center_runs": 3}, "t.csv", "materials.m")
    text = str(err.value)
    assert f"has no run ({len(table)} runs in the table)" in text
    assert ("and 1 more" in text) == (removed == 2)
    (point,) = _points_said(text, names)
    missing = {tuple(np.round(c, 6)) for c in coded[axial[:removed]]}
    assert tuple(np.round([(point[n] - _CENTRE[i]) / _HALF[i] for i, n in enumerate(names)], 4)) in \
        {tuple(np.round(m, 4)) for m in missing}


@pytest.mark.parametrize("k", [2, 3])
def test_a_factor_value_typed_as_another_level_names_both_runs_the_empty_point_and_the_value(k):
    """A factorial run whose last factor is typed at the opposite level lands on another run's point: the point
    counts still match; both runs, the empty point and the value that restores it are named."""
    table, names = _ccd_table(k, 1.5, 3)
    coded = (table[names].to_numpy() - _CENTRE[:k]) / _HALF[:k]
    corner = np.all(coded > 0.99, axis=1)
    (i,) = np.flatnonzero(corner)
    other = np.flatnonzero(np.all(np.abs(coded[:, :-1] - 1) < 1e-9, axis=1) & (np.abs(coded[:, -1] + 1) < 1e-9))[0]
    right = table.loc[i, names[-1]]
    table.loc[i, names[-1]] = table.loc[other, names[-1]]
    with pytest.raises(InputError) as err:
        check_design(table, names, {"type": "ccd", "alpha": 1.5, "center_runs": 3}, "t.csv", "materials.m")
    text = str(err.value)
    assert "both are the point" in text and "which a CCD runs once" in text
    said = re.search(rf"in one of them {names[-1]} is likely ([-\d.e+]+), typed as another level", text)
    assert said and float(said.group(1)) == pytest.approx(right, rel=1e-6), text
    repeated, empty = _points_said(text, names)
    assert empty[names[-1]] == pytest.approx(right) and repeated[names[-1]] == pytest.approx(table.loc[other, names[-1]])
    assert sorted(err.value.run) == sorted([int(table.loc[i, "run"]), int(table.loc[other, "run"])])


@pytest.mark.parametrize("k, slips", [(2, 2), (3, 2), (3, 3)])
def test_several_factor_values_typed_as_another_level_are_each_a_slip_the_first_named(k, slips):
    """Several factorial runs whose last factor is typed at the opposite level (each lands on another corner, the
    corner beside it empty): as many repeats as empty points, each a slip; the first is named with its two runs
    and the value that restores it."""
    table, names = _ccd_table(k, 1.5, 3)
    coded = (table[names].to_numpy() - _CENTRE[:k]) / _HALF[:k]
    factorial = np.flatnonzero(np.all(np.abs(np.abs(coded) - 1) < 1e-9, axis=1) & (coded[:, -1] > 0))[:slips]
    restores = {}
    for i in factorial:
        other = np.flatnonzero(np.all(np.abs(coded[:, :-1] - coded[i, :-1]) < 1e-9, axis=1)
                               & (np.abs(coded[:, -1] + 1) < 1e-9))[0]
        restores[frozenset({int(table.loc[i, "run"]), int(table.loc[other, "run"])})] = table.loc[i, names[-1]]
        table.loc[i, names[-1]] = table.loc[other, names[-1]]
    with pytest.raises(InputError) as err:
        check_design(table, names, {"type": "ccd", "alpha": 1.5, "center_runs": 3}, "t.csv", "materials.m")
    text = str(err.value)
    assert "both are the point" in text and "which a CCD runs once" in text
    named = frozenset(err.value.run)
    assert named in restores, text
    said = re.search(rf"in one of them {names[-1]} is likely ([-\d.e+]+), typed as another level", text)
    assert said and float(said.group(1)) == pytest.approx(restores[named], rel=1e-6), text


@pytest.mark.parametrize("k", [2, 3])
def test_a_run_moved_onto_a_corner_far_from_its_point_names_the_repeat_and_the_point_without_a_run(k):
    """An axial run moved onto a factorial corner (two coordinates change: no typed-level slip): both runs on
    the corner are named, and the axial point left without a run is shown and said to have none."""
    table, names = _ccd_table(k, 1.5, 3)
    coded = (table[names].to_numpy() - _CENTRE[:k]) / _HALF[:k]
    axial = int(np.flatnonzero(np.abs(coded[:, 0] - 1.5) < 1e-9)[0])
    corner = int(np.flatnonzero(np.all(np.abs(coded - 1) < 1e-9, axis=1))[0])
    table.loc[axial, names] = table.loc[corner, names].to_numpy()
    with pytest.raises(InputError) as err:
        check_design(table, names, {"type": "ccd", "alpha": 1.5, "center_runs": 3}, "t.csv", "materials.m")
    text = str(err.value)
    assert "both are the point" in text and "which a CCD runs once; the design's point (" in text
    assert text.endswith(") has no run") and "typed as another level" not in text, text
    repeated, empty = _points_said(text, names)
    assert [repeated[n] for n in names] == pytest.approx(list(_CENTRE[:k] + _HALF[:k]))
    assert [empty[n] for n in names] == pytest.approx([_CENTRE[0] + 1.5 * _HALF[0], *_CENTRE[1:k]])
    assert sorted(err.value.run) == sorted([axial + 1, corner + 1])


@pytest.mark.parametrize("k, drop", [(2, 1), (3, 1), (3, 4)])
def test_an_incomplete_three_level_factorial_counts_its_missing_points(k, drop):
    coded = factorial_points(k, 2)
    keep = np.ones(len(coded), dtype=bool)
    non_centre = np.flatnonzero(np.any(coded != 0, axis=1))
    keep[non_centre[-drop:]] = False
    table = pd.DataFrame({"run": np.arange(1, keep.sum() + 1),
                          **{f"x{i + 1}": _CENTRE[i] + coded[keep, i] * _HALF[i] for i in range(k)}})
    names = [f"x{i + 1}" for i in range(k)]
    with pytest.raises(InputError) as err:
        check_design(table, names, {"type": "factorial", "center_runs": 2}, "t.csv", "materials.m")
    text = str(err.value)
    assert (f"a 3^{k} factorial has {3 ** k - 1} non-centre points, the table has {3 ** k - 1 - drop}; missing "
            f"{drop}") in text
    # the example is the first missing point as the factorial lists them (first factor slowest, -1 before +1)
    first = min(tuple(int(v) for v in p) for p in coded[non_centre[-drop:]])
    example = ", ".join(f"x{i + 1}={v:+d}" for i, v in enumerate(first))
    assert f"e.g. the point ({example}) in coded units" in text


@pytest.mark.parametrize("k, centres", [(2, 1), (3, 4)])
def test_a_ccd_declared_for_a_two_level_factorial_says_the_squares_need_axial_runs(k, centres):
    corners = np.array(np.meshgrid(*[[-1.0, 1.0]] * k, indexing="ij")).reshape(k, -1).T
    coded = np.vstack([corners, np.zeros((centres, k))])
    names = [f"x{i + 1}" for i in range(k)]
    table = pd.DataFrame({"run": np.arange(1, len(coded) + 1),
                          **{n: _CENTRE[i] + coded[:, i] * _HALF[i] for i, n in enumerate(names)}})
    with pytest.raises(InputError) as err:
        check_design(table, names, {"type": "ccd", "alpha": 1.5, "center_runs": centres}, "t.csv", "materials.m")
    text = str(err.value)
    assert (f"config key materials.m.design: the table has no axial runs: its runs are a two-level factorial with "
            f"{centres} centre run(s)") in text
    assert f"add the {2 * k} axial runs of a CCD, or run the 3^{k} factorial" in text


@pytest.mark.parametrize("k", [3, 4])
def test_a_box_behnken_design_with_every_edge_run_twice_is_called_replicated(k):
    from demid.design import box_behnken_points

    coded = box_behnken_points(k, 0)
    coded = np.vstack([coded, coded, np.zeros((3, k))])
    names = [f"x{i + 1}" for i in range(k)]
    table = pd.DataFrame({"run": np.arange(1, len(coded) + 1),
                          **{n: _CENTRE[i] + coded[:, i] * _HALF[i] for i, n in enumerate(names)}})
    with pytest.raises(InputError) as err:
        check_design(table, names, {"type": "box_behnken", "center_runs": 3}, "t.csv", "materials.m")
    edges = 2 * k * (k - 1)
    assert (f"the table has {2 * edges} edge-midpoint runs where a {k}-factor Box-Behnken design has {edges}: "
            "replicated points?") in str(err.value)


def test_no_repair_is_offered_toward_a_kind_of_point_the_design_is_not_short_of():
    """Four factorial runs (one corner twice, one missing) and a run on no point: restoring the missing corner
    would make five factorial runs where a 2-factor CCD has four, so the run is named without a repair."""
    coded = np.array([(-1, -1), (-1, -1), (1, -1), (-1, 1), (1.0, 0.0),
                      (-1.5, 0), (1.5, 0), (0, -1.5), (0, 1.5), (0, 0), (0, 0), (0, 0)], dtype=float)
    names = ["x1", "x2"]
    table = pd.DataFrame({"run": np.arange(1, len(coded) + 1),
                          **{n: _CENTRE[i] + coded[:, i] * _HALF[i] for i, n in enumerate(names)}})
    with pytest.raises(InputError) as err:
        check_design(table, names, {"type": "ccd", "alpha": 1.5, "center_runs": 3}, "t.csv", "materials.m")
    text = str(err.value)
    assert "is not a factorial, axial or centre point of the" in text and "would be the" not in text
    assert err.value.run == 5


@pytest.mark.parametrize("half_place, unit, expected", [
    (0.005, 0.1, [0.1, 0.15, 0.175]),     # a coarse print: half a place over the unit, times 2 + |level|
    (0.0005, 0.1, [0.02, 0.02, 0.02]),     # a fine print: the level tolerance
    (0.0, 0.1, [0.02, 0.02, 0.02]),        # not read from text
    (0.005, 0.0, [0.02, 0.02, 0.02]),
    (0.005, -0.1, [0.1, 0.15, 0.175]),
])
def test_the_tolerance_a_printed_level_gets_is_half_its_place_carried_through_the_coding(half_place, unit, expected):
    from demid.design_check import _print_tolerance

    assert np.allclose(_print_tolerance(0.02, half_place, unit, np.array([0.0, -1.0, 1.5])), expected)


@pytest.mark.parametrize("low, high", [(-1.3, 1.5), (-1.5, 1.45)])
def test_axial_levels_unequally_far_from_the_centre_show_no_axial_distance(low, high):
    """Both factors' axial levels moved alike, so that their ratios to the factorial levels still agree: the runs
    are still no CCD, whose axial runs sit equally far on both sides."""
    table, names = _ccd_table(2, 1.5, 2)
    for i, name in enumerate(names):
        coded = (table[name] - _CENTRE[i]) / _HALF[i]
        table.loc[np.isclose(coded, -1.5), name] = _CENTRE[i] + low * _HALF[i]
        table.loc[np.isclose(coded, 1.5), name] = _CENTRE[i] + high * _HALF[i]
    assert _ccd_alpha_of_table(table, names) is None


@pytest.mark.parametrize("k, moved", [(2, 2), (3, 2), (3, 3)])
def test_several_runs_moved_onto_one_corner_count_the_points_left_without_a_run(k, moved):
    """``moved`` axial runs moved onto one factorial corner: the corner is run moved + 1 times, and the message
    names the first empty point and counts the others ("and N more")."""
    table, names = _ccd_table(k, 1.5, 3)
    coded = (table[names].to_numpy() - _CENTRE[:k]) / _HALF[:k]
    axial = np.flatnonzero(np.abs(np.abs(coded).max(axis=1) - 1.5) < 1e-9)[:moved]
    corner = int(np.flatnonzero(np.all(np.abs(coded - 1) < 1e-9, axis=1))[0])
    for row in axial:
        table.loc[int(row), names] = table.loc[corner, names].to_numpy()
    with pytest.raises(InputError) as err:
        check_design(table, names, {"type": "ccd", "alpha": 1.5, "center_runs": 3}, "t.csv", "materials.m")
    text = str(err.value)
    assert f"all {moved + 1} are the point" in text, text
    assert text.endswith(f") and {moved - 1} more has no run"), text


@pytest.mark.parametrize("prints", [(0.751, 0.75), (0.75, 0.751), (0.749, 0.7505)])
def test_the_nearest_level_is_quoted_as_the_first_run_at_it_prints_it(prints):
    """Two runs print the level a = +1 a little apart (both within the check's tolerance): a run typed onto no
    level (0.9, coded +1.6) is told the nearest level as the first run of the table at that level prints it."""
    coded = ccd_points(2, 1.0, 1)
    table = pd.DataFrame({"run": np.arange(1, len(coded) + 1), "a": 0.5 + 0.25 * coded[:, 0],
                          "b": 6.0 + 2.5 * coded[:, 1]})
    at_one = np.flatnonzero(coded[:, 0] == 1.0)  # factorial runs 2 and 4, then the axial run 6
    table.loc[at_one[0], "a"], table.loc[at_one[1], "a"] = prints
    table.loc[at_one[2], "a"] = 0.9
    with pytest.raises(InputError) as err:
        check_design(table, ["a", "b"], {"type": "ccd", "alpha": 1.0, "center_runs": 1}, "t.csv", "materials.m")
    assert err.value.run == at_one[2] + 1 and err.value.column == "a"
    assert "value 0.9 is not a level of the declared ccd design (coded +1.6" in str(err.value)
    assert str(err.value).endswith(f"; nearest valid level: {prints[0]:g} (coded +1)")


def test_where_runs_print_one_level_a_little_apart_the_coding_takes_each_levels_lowest_print():
    """The coding comes from printed values (the centre run, the +-1 pair), not from a fit; where two runs print
    one level differently (here by 4e-4, within the check's tolerance), the one read is the level's lowest print,
    whatever the order of the runs: a two-factor face-centred CCD with two centre runs, and a one-factor CCD
    (alpha 2) without a centre run, whose centre is then the middle of the +-1 pair."""
    coded = ccd_points(2, 1.0, 2)
    a = 0.5 + 0.25 * coded[:, 0]
    shifts = {0.0: (0.0, 4e-4), 1.0: (4e-4, 0.0), -1.0: (-4e-4, 0.0)}  # per level, its runs' offsets in turn
    for level, offsets in shifts.items():
        rows = np.flatnonzero(coded[:, 0] == level)
        a[rows[:2]] += offsets
    table = pd.DataFrame({"run": np.arange(1, len(a) + 1), "a": a, "b": 6.0 + 2.5 * coded[:, 1]})
    coding = infer_coding(table, ["a", "b"], {"type": "ccd", "alpha": 1.0, "center_runs": 2}, "t.csv")
    lowest = {level: a[coded[:, 0] == level].min() for level in shifts}  # 0.5, 0.75 and 0.2496
    assert coding.center[0] == pytest.approx(lowest[0.0], abs=1e-12)
    assert coding.unit[0] == pytest.approx((lowest[1.0] - lowest[-1.0]) / 2, abs=1e-12)
    single = pd.DataFrame({"run": np.arange(1, 7), "x": [1.0, 0.7504, 0.25, 0.75, 0.2504, 0.0]})
    coding = infer_coding(single, ["x"], {"type": "ccd", "alpha": 2.0, "center_runs": 0}, "t.csv")
    assert coding.center[0] == pytest.approx((0.75 + 0.25) / 2, abs=1e-12)
    assert coding.unit[0] == pytest.approx((0.75 - 0.25) / 2, abs=1e-12)

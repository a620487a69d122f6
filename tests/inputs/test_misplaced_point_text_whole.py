"""The line that refuses a run on no point of the declared CCD or Box-Behnken design: the run, its factor values as
the table gives them, the kinds of point the design has (with their article: "a factorial, axial or centre point",
"an edge-midpoint or centre point") and, where changing one factor value to one of its levels gives the only
point the design is short of, that column and value.  The expected repairs are found here by trying every factor
at every level against the design's own points, listed from their definitions."""

from __future__ import annotations

from itertools import combinations, product

import numpy as np
import pandas as pd
import pytest

from demid.design_check import check_design
from demid.errors import InputError

CENTRE, UNIT = 3.0, 0.25


def _design_points(design_type, k, alpha):
    """The design's non-centre points and each one's kind, from the definitions."""
    if design_type == "ccd":
        points = [(p, "factorial") for p in product((-1.0, 1.0), repeat=k)]
        points += [(tuple(s * alpha * (i == j) for j in range(k)), "axial") for i in range(k) for s in (-1, 1)]
    else:
        points = [(tuple(a * (m == i) + b * (m == j) for m in range(k)), "edge-midpoint")
                  for i, j in combinations(range(k), 2) for a, b in product((-1.0, 1.0), repeat=2)]
    return {tuple(np.round(p, 9)): kind for p, kind in points}


def _table(design_type, k, alpha, moves, extra=()):
    """The full design with 3 centre runs; the run at each design point ``moved`` of ``moves`` put at its ``to``,
    runs at ``extra`` added; runs in shuffled order."""
    points = list(_design_points(design_type, k, alpha)) + [(0.0,) * k] * 3
    for moved, to in moves:
        points[points.index(moved)] = to
    coded = np.array(points + list(extra))
    order = np.random.default_rng(k).permutation(len(coded))
    names = [f"x{i + 1}" for i in range(k)]
    table = pd.DataFrame({"run": np.arange(1, len(coded) + 1),
                          **{f: np.round(CENTRE + UNIT * coded[order, i], 6) for i, f in enumerate(names)}})
    return table, names, coded[order]


def _repairs(design_type, k, alpha, coded, row):
    """(column index, coded level, kind) of every one-value change of ``row`` that lands on a design point no
    other run is on."""
    design = _design_points(design_type, k, alpha)
    levels = (-alpha, -1.0, 0.0, 1.0, alpha) if design_type == "ccd" else (-1.0, 0.0, 1.0)
    others = {tuple(np.round(p, 9)) for i, p in enumerate(coded) if i != row}
    found = []
    for j, level in product(range(k), levels):
        point = coded[row].copy()
        point[j] = level
        key = tuple(np.round(point, 9))
        if level != coded[row, j] and key in design and key not in others:
            found.append((j, level, design[key]))
    return found


@pytest.mark.parametrize("design_type, k, moved, to, extra", [
    ("box_behnken", 3, (1.0, 1.0, 0.0), (1.0, 1.0, 1.0), False),
    ("box_behnken", 4, (0.0, -1.0, 0.0, 1.0), (0.0, -1.0, 1.0, 1.0), False),
    ("box_behnken", 3, None, (-1.0, 1.0, 1.0), True),
    ("ccd", 2, (1.4142, 0.0), (1.4142, 1.0), False),
    ("ccd", 3, (-1.0, 1.0, 1.0), (-1.0, 0.0, 1.0), False),
    ("ccd", 2, None, (1.0, 0.0), True)])
def test_a_run_on_no_design_point_is_named_with_the_kinds_of_point_and_the_one_repair(design_type, k, moved, to,
                                                                                      extra):
    alpha = 1.4142 if design_type == "ccd" else 1.0
    moved = moved and tuple(np.round(moved, 9))
    table, names, coded = _table(design_type, k, alpha, [] if extra else [(moved, to)], [to] if extra else [])
    design = {"type": design_type, "center_runs": 3, **({"alpha": alpha} if design_type == "ccd" else {})}
    with pytest.raises(InputError) as info:
        check_design(table, names, design, "t.csv", "materials.m")
    row = next(i for i, p in enumerate(coded) if tuple(p) == tuple(to))
    where = ", ".join(f"{f} {table[f].iloc[row]:g}" for f in names)
    kinds = ("a factorial, axial or centre point" if design_type == "ccd" else "an edge-midpoint or centre point")
    what = f"the point ({where}) is not {kinds} of the declared {design_type} design"
    repairs = _repairs(design_type, k, alpha, coded, row)
    assert len(repairs) == (0 if extra else 1)
    if repairs:
        j, level, kind = repairs[0]
        value = float(table[names[j]].iloc[row]) + UNIT * (level - coded[row, j])
        expected = (f"t.csv, run {row + 1}, column '{names[j]}': {what}; with {names[j]} = {value:.6g} it would be "
                    f"the {kind} run the design is short of (another run's level typed by mistake?)")
    else:
        expected = f"t.csv, run {row + 1}: {what}"
    assert str(info.value) == expected


@pytest.mark.parametrize("design_type, k, moves", [
    ("box_behnken", 3, [((1.0, 1.0, 0.0), (1.0, 1.0, 1.0)), ((0.0, -1.0, -1.0), (-1.0, -1.0, -1.0))]),
    ("ccd", 2, [((-1.0, -1.0), (-1.0, 0.0)), ((0.0, 1.4142), (1.0, 1.4142))])])
def test_of_two_runs_on_no_design_point_the_first_in_the_table_is_named(design_type, k, moves):
    alpha = 1.4142 if design_type == "ccd" else 1.0
    table, names, coded = _table(design_type, k, alpha, moves)
    design = {"type": design_type, "center_runs": 3, **({"alpha": alpha} if design_type == "ccd" else {})}
    with pytest.raises(InputError) as info:
        check_design(table, names, design, "t.csv", "materials.m")
    rows = sorted(next(i for i, p in enumerate(coded) if tuple(p) == to) for _, to in moves)
    where = ", ".join(f"{f} {table[f].iloc[rows[0]]:g}" for f in names)
    assert f"t.csv, run {rows[0] + 1}" in str(info.value) and f"the point ({where}) is not" in str(info.value)

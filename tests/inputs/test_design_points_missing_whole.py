"""A CCD or Box-Behnken table with design points left out, or with one point run twice beside points left out that
no single factor value would restore, refused in one line with every count it quotes read back: the first empty
point in the design's standard order (each level as the runs print it), how many more are empty, the runs in the
table, and the runs on the repeated point; over generated designs of 3-4 factors with 2-3 points left out, ranges
of either sign and scale and any run order."""

from __future__ import annotations

import re

import numpy as np
import pandas as pd
import pytest

from demid.design import box_behnken_points, ccd_points
from demid.design_check import check_design
from demid.errors import InputError


def _design(rng, kind: str, k: int):
    centres = int(rng.integers(2, 5))
    if kind == "ccd":
        alpha = float(rng.choice([1.5, 1.68179, 2.0]))
        return ccd_points(k, alpha, centres), {"type": "ccd", "alpha": alpha, "center_runs": centres}, "CCD"
    return box_behnken_points(k, centres), {"type": "box_behnken", "center_runs": centres}, "Box-Behnken design"


def _shown(point, names, centre, half) -> str:
    return ", ".join(f"{f} {c + v * h:.6g}" for f, v, c, h in zip(names, point, centre, half))


def _table(rng, coded, names, centre, half):
    order = rng.permutation(len(coded))
    table = pd.DataFrame(centre + coded[order] * half, columns=names)
    table.insert(0, "run", np.arange(1, len(coded) + 1))
    return table, order


@pytest.mark.parametrize("seed", range(4))
def test_points_left_out_are_named_first_in_standard_order_and_counted(seed):
    rng = np.random.default_rng(seed)
    kind, k = ("ccd", "box_behnken")[seed % 2], int(rng.integers(3, 5))
    coded, design, name = _design(rng, kind, k)
    names = [f"x{i}" for i in range(k)]
    centre, half = rng.uniform(-30, 30, k), rng.uniform(0.05, 8, k)
    # corners of a CCD (four or more runs per level) or edge midpoints of a Box-Behnken design
    pool = np.flatnonzero(np.sum(np.abs(coded) == 1, axis=1) == (k if kind == "ccd" else 2))
    m = int(rng.integers(2, 4))
    gone = np.sort(rng.choice(pool, m, replace=False))
    kept = np.delete(coded, gone, axis=0)
    table, _ = _table(rng, kept, names, centre, half)
    with pytest.raises(InputError) as info:
        check_design(table, names, design, "t.csv", "m")
    text = str(info.value)
    said = re.search(rf"the {name}'s point \((.*?)\)(?: and (\d+) more)? has no run \((\d+) runs in the table\)", text)
    assert said, text
    assert said.group(1) == _shown(coded[gone[0]], names, centre, half)
    assert int(said.group(2) or 0) == m - 1
    assert int(said.group(3)) == len(table)


@pytest.mark.parametrize("seed", range(3))
def test_a_point_run_twice_beside_points_no_slip_explains_names_both_runs_and_the_empty_points(seed):
    rng = np.random.default_rng(100 + seed)
    k = int(rng.integers(3, 5))
    coded, design, name = _design(rng, "ccd", k)
    names = [f"x{i}" for i in range(k)]
    centre, half = rng.uniform(-30, 30, k), rng.uniform(0.05, 8, k)
    corners = np.flatnonzero(np.all(np.abs(coded) == 1, axis=1))
    twice = int(rng.choice(corners))
    # empty corners two or more factors away from the repeated one: no single factor value moves a run there
    far = [i for i in corners if np.sum(coded[i] != coded[twice]) >= 2]
    m = int(rng.integers(2, 4))
    gone = np.sort(rng.choice(far, m, replace=False))
    points = np.vstack([np.delete(coded, gone, axis=0), coded[twice]])
    table, order = _table(rng, points, names, centre, half)
    with pytest.raises(InputError) as info:
        check_design(table, names, design, "t.csv", "m")
    text = str(info.value)
    runs = sorted(int(r) for r, p in zip(table["run"], points[order]) if np.array_equal(p, coded[twice]))
    said = re.search(r"runs (\d+) and (\d+): both are the point \((.*?)\), which a CCD runs once; the design's point "
                     r"\((.*?)\)(?: and (\d+) more)? has no run", text)
    assert said, text
    assert [int(said.group(1)), int(said.group(2))] == runs
    assert said.group(3) == _shown(coded[twice], names, centre, half)
    assert said.group(4) == _shown(coded[gone[0]], names, centre, half)
    assert int(said.group(5) or 0) == m - 1

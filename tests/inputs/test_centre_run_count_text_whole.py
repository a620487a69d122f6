"""The line that refuses a table with the wrong number of centre runs quotes both counts as whole numbers (one centre
run in the singular), even when the config writes the count as a float (``center_runs: 3.0`` passes the schema's
integer type): CCDs, Box-Behnken designs and three-level factorials of two to four factors, more and fewer centre runs
than declared."""

from __future__ import annotations

from itertools import product

import numpy as np
import pandas as pd
import pytest

from demid.design import box_behnken_points, ccd_points
from demid.design_check import check_design
from demid.errors import InputError


def _points(design_type, k, centres):
    if design_type == "ccd":
        return ccd_points(k, 2 ** (k / 4), centres)
    if design_type == "box_behnken":
        return box_behnken_points(k, centres)
    grid = np.array([p for p in product((-1.0, 0.0, 1.0), repeat=k) if any(p)])
    return np.vstack([grid, np.zeros((centres, k))])


@pytest.mark.parametrize("design_type, k, declared, found", [
    ("ccd", 2, 5.0, 3), ("ccd", 3, 2.0, 4), ("box_behnken", 3, 3.0, 2), ("box_behnken", 4, 1.0, 3),
    ("factorial", 2, 4.0, 1), ("factorial", 3, 2.0, 5)])
def test_a_wrong_centre_run_count_is_quoted_in_whole_runs(design_type, k, declared, found):
    coded = _points(design_type, k, found)
    names = [f"x{i + 1}" for i in range(k)]
    rng = np.random.default_rng(k + found)
    table = pd.DataFrame({"run": rng.permutation(len(coded)) + 1,
                          **{f: 3.0 + 0.25 * coded[:, i] for i, f in enumerate(names)}})
    design = {"type": design_type, "center_runs": declared, **({"alpha": 2 ** (k / 4)} if design_type == "ccd" else {})}
    with pytest.raises(InputError) as info:
        check_design(table, names, design, "t.csv", "materials.m")
    head = f"t.csv: config key materials.m.design.center_runs: expected {int(declared)} centre run"
    tail = (f"(s) for a {k}-factor CCD, found {found} ({len(coded)} runs in the table)" if design_type == "ccd" else
            f"{'' if declared == 1 else 's'}, found {found}")
    assert str(info.value) == head + tail

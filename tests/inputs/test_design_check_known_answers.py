"""The design check's known answers (demid/design_check.py): the coding recovered from a CCD table for 2-4 factors
(the centre and half-range of each factor, also when no run sits at the centre), the axial distance the runs show
when one printed axial level carries more digits than another, and the repair named for a run typed onto no
point of the design, its value parsed back."""

from __future__ import annotations

import re

import numpy as np
import pandas as pd
import pytest

from demid.design import ccd_points
from demid.design_check import _ccd_alpha_of_table, check_design, infer_coding
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

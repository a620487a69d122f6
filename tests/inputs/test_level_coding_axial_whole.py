"""The coding of a declared CCD at alpha = 2 (demid.design_check) over generated tables of 2-4 factors, ranges of
either sign and scale, any run order, with every run or without the low or the high axial run of one factor: four
evenly spaced values (-1, 0, 1, 2 coded) read as a CCD's levels two ways, and the coding is the one whose axial
level a single run holds (the centre runs stay at 0).  The check then names the point left out, its coordinates
parsed back and compared with the generating ones, and codes the complete design as generated."""

from __future__ import annotations

import re

import numpy as np
import pandas as pd
import pytest
from hypothesis import Phase, given, settings
from hypothesis import strategies as st

from demid.design import ccd_points
from demid.design_check import check_design, infer_coding
from demid.errors import InputError

SETTINGS = settings(max_examples=16, deadline=None, derandomize=True, phases=[Phase.explicit, Phase.generate])
ALPHA = 2.0


def _table(coded, centre, half, seed):
    order = np.random.default_rng(seed).permutation(len(coded))
    actual = centre + coded[order] * half
    names = [f"f{i}" for i in range(coded.shape[1])]
    table = pd.DataFrame(actual, columns=names)
    table.insert(0, "run", np.arange(1, len(table) + 1))
    return table, names


def _ranges(k, seed):
    # two decimals: every level, the missing point's too, is printed exactly in the check's six digits
    rng = np.random.default_rng(seed)
    return np.round(rng.choice([-1.0, 1.0], k) * rng.uniform(0.5, 80, k), 2), np.round(rng.uniform(0.05, 20, k), 2)


@given(k=st.integers(2, 4), centres=st.integers(1, 4), side=st.sampled_from([-1.0, 1.0]), which=st.data(),
       seed=st.integers(0, 1000))
@SETTINGS
def test_a_ccd_at_alpha_two_without_one_axial_run_keeps_its_centre_and_names_the_point(k, centres, side, which,
                                                                                      seed):
    coded = ccd_points(k, ALPHA, centres)
    j = which.draw(st.integers(0, k - 1))
    missing = np.flatnonzero(np.isclose(coded[:, j], side * ALPHA))[0]
    point = coded[missing]
    centre, half = _ranges(k, seed)
    table, names = _table(np.delete(coded, missing, axis=0), centre, half, seed)
    design = {"type": "ccd", "alpha": ALPHA, "center_runs": centres}
    coding = infer_coding(table, names, design, "t.csv")
    np.testing.assert_allclose(coding.center, centre, rtol=1e-9, atol=1e-9)
    np.testing.assert_allclose(coding.unit, half, rtol=1e-9)
    with pytest.raises(InputError) as info:
        check_design(table, names, design, "t.csv", "design")
    said = re.match(r"the CCD's point \((.*)\) has no run \((\d+) runs in the table\)", info.value.detail)
    assert said, info.value.detail
    shown = dict(part.rsplit(" ", 1) for part in said.group(1).split(", "))
    assert list(shown) == names
    np.testing.assert_allclose([float(shown[n]) for n in names], centre + point * half, rtol=1e-9, atol=1e-9)
    assert int(said.group(2)) == len(table)


@given(k=st.integers(2, 4), centres=st.integers(1, 4), seed=st.integers(0, 1000))
@SETTINGS
def test_a_complete_ccd_at_alpha_two_is_coded_as_generated(k, centres, seed):
    centre, half = _ranges(k, seed)
    table, names = _table(ccd_points(k, ALPHA, centres), centre, half, seed)
    coding, _ = check_design(table, names, {"type": "ccd", "alpha": ALPHA, "center_runs": centres}, "t.csv",
                             "design")
    np.testing.assert_allclose(coding.center, centre, rtol=1e-9, atol=1e-9)
    np.testing.assert_allclose(coding.unit, half, rtol=1e-9)

"""The axial runs of an inferred CCD (demid.design_inference), over generated CCDs of 2-4 factors, axial distances
from just above the level tolerance to 2.5, ranges of either sign and scale, any run order: a CCD without its low
or its high axial run in one factor (a failed run left out) is still a CCD, that factor's axial distance measured
from the axial run left, every other factor's the design's; axial runs of one factor set at different distances
from the centre are refused in one line quoting both levels, their coded distances (parsed back and compared with
the generating ones) and both runs."""

from __future__ import annotations

import re

import numpy as np
import pandas as pd
import pytest
from hypothesis import Phase, given, settings
from hypothesis import strategies as st

from demid.design import ccd_points
from demid.design_inference import infer_design
from demid.errors import InputError

SETTINGS = settings(max_examples=12, deadline=None, derandomize=True, phases=[Phase.explicit, Phase.generate])


def _table(coded, centre, half, seed):
    order = np.random.default_rng(seed).permutation(len(coded))
    actual = centre + coded[order] * half
    table = pd.DataFrame({f"f{i}": actual[:, i] for i in range(coded.shape[1])})
    table.insert(0, "run", np.arange(1, len(table) + 1))
    return table, [f"f{i}" for i in range(coded.shape[1])], order


@given(k=st.integers(2, 4), alpha=st.sampled_from([1.1, 1.3, 1.5, 2.0, 2.5]), centres=st.integers(1, 4),
       which=st.data(), seed=st.integers(0, 1000))
@SETTINGS
def test_a_ccd_without_one_axial_run_keeps_its_axial_distance(k, alpha, centres, which, seed):
    coded = ccd_points(k, alpha, centres)
    j = which.draw(st.integers(0, k - 1))
    side = which.draw(st.sampled_from([-1.0, 1.0]))
    missing = np.flatnonzero(np.isclose(coded[:, j], side * alpha))[0]
    coded = np.delete(coded, missing, axis=0)
    rng = np.random.default_rng(seed)
    centre, half = rng.uniform(-50, 50, k), rng.uniform(0.01, 20, k)
    table, names, _ = _table(coded, centre, half, seed)
    inferred = infer_design(table, names, "t.csv")
    assert inferred.family == "ccd" and inferred.center_runs == centres
    assert inferred.alpha == pytest.approx((alpha,) * k, rel=1e-9)


@given(k=st.integers(2, 4), alpha=st.sampled_from([1.5, 2.0, 2.5]), shift=st.sampled_from([-0.3, 0.2, 0.45]),
       seed=st.integers(0, 1000))
@SETTINGS
def test_axial_runs_at_different_distances_are_refused_quoting_both(k, alpha, shift, seed):
    coded = ccd_points(k, alpha, 2)
    j = seed % k
    high = np.flatnonzero(np.isclose(coded[:, j], alpha))[0]
    low = np.flatnonzero(np.isclose(coded[:, j], -alpha))[0]
    coded[high, j] = alpha + shift
    rng = np.random.default_rng(seed)
    centre, half = rng.uniform(-50, 50, k), rng.uniform(0.5, 20, k)
    table, names, order = _table(coded, centre, half, seed)
    with pytest.raises(InputError) as info:
        infer_design(table, names, "t.csv")
    error = info.value
    number = r"(-?[\d.]+(?:e[-+]?\d+)?)"
    said = re.fullmatch(rf"the levels of f{j} are a CCD's but its axial levels {number} and {number} lie {number} "
                        rf"and {number} coded units from the centre {number}: one of these axial cells is mistyped "
                        r"\(a CCD's axial runs sit at the same distance on both sides\)", error.detail)
    assert said, error.detail
    low_level, high_level, low_coded, high_coded, shown_centre = map(float, said.groups())
    assert low_level == pytest.approx(centre[j] - alpha * half[j], rel=1e-5, abs=1e-5)
    assert high_level == pytest.approx(centre[j] + (alpha + shift) * half[j], rel=1e-5, abs=1e-5)
    assert low_coded == pytest.approx(alpha, rel=1e-3) and high_coded == pytest.approx(alpha + shift, rel=1e-3)
    assert shown_centre == pytest.approx(centre[j], rel=1e-5, abs=1e-5)
    runs_of = {int(i): r + 1 for r, i in enumerate(order)}  # standard-order point -> run number in the table
    assert sorted(error.run) == sorted([runs_of[low], runs_of[high]])
    assert error.column == f"f{j}"


@pytest.mark.parametrize("side", [-1.0, 1.0])
@pytest.mark.parametrize("factor", [0, 3])
def test_a_rotatable_four_factor_ccd_without_an_axial_run_keeps_its_centre(side, factor):
    """At alpha = 2 the four levels left (-2, -1, 0, 1) are evenly spaced: read with the centre at -1 they made a
    CCD without centre runs; the axial level is the one a single run holds."""
    coded = ccd_points(4, 2.0, 3)
    coded = np.delete(coded, np.flatnonzero(np.isclose(coded[:, factor], side * 2.0))[0], axis=0)
    table, names, _ = _table(coded, np.array([1.0, -4.0, 30.0, 0.5]), np.array([0.1, 2.0, 5.0, 0.25]), 7)
    inferred = infer_design(table, names, "t.csv")
    assert inferred.describe() == ("a 4-factor central composite design (CCD), axial distance alpha = 2, "
                                   "3 centre runs")

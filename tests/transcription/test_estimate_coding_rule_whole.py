"""The coding the transcription check reads off a factor column against its documented rule written out here with
plain loops: every pair of distinct values on every pair of nominal levels (and the mid-range coding) is a
candidate; the most cells within the printing precision (plus the alpha slack) of a level win, then the smallest
sum of squared deviations of those cells, then the mid-range coding, then the first pair.

The columns are CCD columns of two to four factors (rotatable, face-centred and other axial distances, one to three
centre runs) printed to one to three decimals, centres of either sign: the rounded axial and factorial cells pull
the coding two ways, and the sum of squares (not of absolute deviations) decides between them."""

from __future__ import annotations

from itertools import combinations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.design import ccd_points, nominal_levels
from demid.transcription.engine import _ALPHA_SLACK, _estimate_coding


def _coding_by_the_rule(column, nominal, alpha, decimals):
    lo, hi = float(min(column)), float(max(column))
    candidates = [((lo + hi) / 2, (hi - lo) / (2 * alpha) if hi > lo else 1.0)]
    distinct = sorted(set(float(v) for v in column))
    for ua, ub in combinations(distinct, 2):
        for la, lb in combinations([float(v) for v in nominal], 2):
            unit = (ub - ua) / (lb - la)
            candidates.append((ua - la * unit, unit))
    scored = []
    for index, (centre, unit) in enumerate(candidates):
        reach = 0.5 * 10.0 ** -decimals / abs(unit) + _ALPHA_SLACK
        hits, squares = 0, 0.0
        for value in column:
            off = min(abs((value - centre) / unit - level) for level in nominal)
            if off <= reach:
                hits += 1
                squares += off * off
        scored.append((-hits, round(squares, 12), index))
    return candidates[min(scored)[2]]


def _column(k, alpha, centre_runs, centre, unit, decimals):
    coded = ccd_points(k, alpha, centre_runs)[:, 0]
    return np.round(centre + unit * coded, decimals)


@given(k=st.integers(2, 4), alpha=st.sampled_from([1.0, 1.2, 1.41421, 1.5, 1.68179, 2.0]),
       centre_runs=st.integers(1, 3), centre=st.sampled_from([-3.0, 0.0, 5.0, 47.0]),
       unit=st.sampled_from([0.3, 1.0, 2.0, 10.0]), decimals=st.integers(1, 3))
@settings(max_examples=25, deadline=None, derandomize=True)
def test_the_coding_is_the_documented_rule(k, alpha, centre_runs, centre, unit, decimals):
    column = _column(k, alpha, centre_runs, centre, unit, decimals)
    nominal = nominal_levels("ccd", alpha)
    assert _estimate_coding(column, nominal, alpha, decimals) == pytest.approx(
        _coding_by_the_rule(column, nominal, alpha, decimals), rel=1e-12, abs=1e-12)


@pytest.mark.parametrize("alpha, centre, unit, decimals", [(1.68179, 5.0, 2.0, 1), (1.41421, -3.0, 2.0, 2),
                                                           (1.68179, 47.0, 1.0, 1)])
def test_squared_deviations_decide_between_the_axial_and_the_factorial_pairs(alpha, centre, unit, decimals):
    """Two-factor CCDs whose every cell is on a level either way: the coding through the rounded axial cells
    leaves the four factorial cells off by less, squared, than the coding through the factorial cells leaves the
    two axial cells (by absolute deviations it would be the other way round)."""
    column = _column(2, alpha, 1, centre, unit, decimals)
    nominal = nominal_levels("ccd", alpha)
    got_centre, got_unit = _estimate_coding(column, nominal, alpha, decimals)
    axial_unit = (column.max() - column.min()) / (2 * alpha)
    assert got_centre == pytest.approx(centre, abs=1e-12)
    assert got_unit == pytest.approx(axial_unit, rel=1e-12) and got_unit != pytest.approx(unit, rel=1e-9)
    coded = (column - got_centre) / got_unit
    off_axial = np.abs(np.abs(coded[np.abs(coded) > 1.2]) - alpha)
    off_factorial = np.abs(np.abs(coded[(np.abs(coded) > 0.5) & (np.abs(coded) < 1.2)]) - 1)
    by_factorial = np.abs((column[np.abs(column - centre) > 1.2 * unit] - centre) / unit) - alpha
    assert np.sum(off_factorial ** 2) + np.sum(off_axial ** 2) < np.sum(by_factorial ** 2)
    assert np.sum(np.abs(off_factorial)) > np.sum(np.abs(by_factorial))

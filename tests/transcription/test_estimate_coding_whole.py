"""The coding the transcription check reads off a factor column (centre and unit that put the most cells on the
design's nominal levels), over generated columns: every level printed three times to 0-4 decimals, then up to
twelve stray values between the levels (a print that resolves the levels to a hundredth of
the unit) and one mistyped extreme far outside them.  Up to fifteen distinct
values the coding is the one the levels were printed from (the extreme moves the mid-range coding, not this
one); above fifteen it is the mid-range coding (lowest and highest value over twice alpha), written out here.
Designs: a rotatable and a face-centred CCD, a Box-Behnken and a three-level factorial; centres of either sign."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import Phase, assume, given, settings
from hypothesis import strategies as st

from demid.design import nominal_levels
from demid.transcription.engine import _design_levels, _estimate_coding


def _column(rng, nominal, centre, unit, decimals, strays):
    on_levels = np.round(np.repeat(centre + unit * nominal, 3), decimals)
    # strays sit between two levels, a third of the way: off every level by far more than the print's rounding
    gaps = rng.integers(0, len(nominal) - 1, strays)
    stray = centre + unit * (nominal[gaps] + (nominal[gaps + 1] - nominal[gaps]) * rng.uniform(0.3, 0.7, strays))
    extreme = centre + unit * (nominal.max() * 6.0)
    return np.concatenate([on_levels, np.round(stray, decimals), [round(extreme, decimals)]])


@given(seed=st.integers(0, 10_000), design=st.sampled_from([("ccd", 1.41421), ("ccd", 1.0), ("box_behnken", 1.0),
                                                             ("factorial", 1.0)]),
       centre=st.sampled_from([-40.0, 0.0, 0.35, 7.0, 2500.0]), unit=st.sampled_from([0.05, 1.0, 12.5]),
       decimals=st.integers(2, 4), strays=st.integers(0, 12))
@settings(max_examples=30, deadline=None, derandomize=True, phases=[Phase.explicit, Phase.generate])
def test_up_to_fifteen_distinct_values_the_levels_place_the_coding_above_it_the_mid_range(
        seed, design, centre, unit, decimals, strays):
    assume(unit * 10 ** decimals >= 100)  # the print resolves the levels (a coarser one fits half the unit too)
    design_type, alpha = design
    nominal = nominal_levels(design_type, alpha)
    rng = np.random.default_rng(seed)
    column = _column(rng, nominal, centre, unit, decimals, strays)
    distinct = len(np.unique(column))
    got_centre, got_unit = _estimate_coding(column, nominal, alpha, decimals)
    levels, level_unit = _design_levels(column, design_type, alpha, decimals, None)
    assert level_unit == abs(got_unit)
    np.testing.assert_allclose(levels, got_centre + got_unit * nominal, rtol=1e-12)
    if distinct <= 15:
        half_place = 0.5 * 10.0 ** -decimals
        assert got_centre == pytest.approx(centre, abs=2 * half_place)
        assert got_unit == pytest.approx(unit, abs=2 * half_place)
    else:
        lo, hi = column.min(), column.max()
        assert (got_centre, got_unit) == pytest.approx(((lo + hi) / 2, (hi - lo) / (2 * alpha)), rel=1e-12)


@pytest.mark.parametrize("strays, expect_levels", [(9, True), (10, False)])
def test_the_limit_is_fifteen_distinct_values(strays, expect_levels):
    """Five CCD levels, `strays` stray values and the extreme: 15 distinct values are searched, 16 are not."""
    nominal = nominal_levels("ccd", 1.41421)
    rng = np.random.default_rng(3)
    column = _column(rng, nominal, 10.0, 2.0, 3, strays)
    while len(np.unique(column)) != 5 + strays + 1:  # strays that happen to coincide: draw again
        column = _column(rng, nominal, 10.0, 2.0, 3, strays)
    got = _estimate_coding(column, nominal, 1.41421, 3)
    if expect_levels:
        assert got == pytest.approx((10.0, 2.0), abs=1e-3)
    else:
        assert got == pytest.approx(((column.min() + column.max()) / 2, np.ptp(column) / (2 * 1.41421)), rel=1e-12)


def test_a_fixed_coding_gives_its_levels_and_one_value_or_no_nominal_level_the_mid_range():
    levels, unit = _design_levels(np.array([1.0, 2.0, 3.0]), "ccd", 1.5, 2, (4.0, -2.0))
    np.testing.assert_allclose(levels, 4.0 - 2.0 * np.array([-1.5, -1.0, 0.0, 1.0, 1.5]))
    assert unit == 2.0
    assert _estimate_coding(np.array([5.0, 5.0, 5.0]), nominal_levels("ccd", 1.5), 1.5, 2) == (5.0, 1.0)
    assert _estimate_coding(np.array([1.0, 3.0, 9.0]), np.array([]), 2.0, 1) == (5.0, 2.0)

"""The coding of a declared CCD at alpha = 2 without its low or high axial run of one factor (demid.design_check),
for factors far from zero against their unit: centres of 2e4 to 1e6 in either sign, units of a few thirds, sevenths,
ninths or elevenths, so that every level is written at full precision (a sheet laid out from a range, not typed) and
the check reads it to eleven significant digits.

The four values of the factor that lost a run (-1, 0, 1, 2 coded) read as a CCD's levels two ways, equally symmetric
and equally wide by their nominal levels; the coding is the one whose axial level a single run holds.  The values'
round-off (up to 1e-6 coded here) must not decide between the two readings: it used to, for about one table in
eight of these (the centre then sat a unit off)."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from demid.design import ccd_points
from demid.design_check import infer_coding
from demid.errors import InputError


def _tables(count: int, seed: int):
    rng = np.random.default_rng(seed)
    for _ in range(count):
        k, side, centres = int(rng.integers(2, 4)), float(rng.choice([-1.0, 1.0])), int(rng.integers(1, 3))
        coded = ccd_points(k, 2.0, centres)
        j = int(rng.integers(k))
        coded = np.delete(coded, np.flatnonzero(np.isclose(coded[:, j], side * 2.0))[0], axis=0)
        unit = rng.integers(1, 60, k) / rng.choice([3.0, 7.0, 9.0, 11.0], k)
        centre = rng.choice([-1.0, 1.0], k) * rng.choice([2.0e4, 5.0e4, 1.0e5, 2.5e5, 1.0e6], k)
        names = [f"f{i}" for i in range(k)]
        table = pd.DataFrame(centre + coded * unit, columns=names)
        table.insert(0, "run", np.arange(1, len(table) + 1))
        yield table, names, centres, centre, unit


def test_the_axial_level_a_single_run_holds_places_the_coding_whatever_the_round_off():
    for table, names, centres, centre, unit in _tables(40, 5):
        coding = infer_coding(table, names, {"type": "ccd", "alpha": 2.0, "center_runs": centres}, "t.csv")
        # read to eleven significant digits: the centre run and the factorial pair each within half a place
        place = 10.0 ** (np.floor(np.log10(np.abs(table[names].to_numpy()).max(axis=0))) - 11)
        assert np.all(np.abs(np.array(coding.unit) - unit) <= place), (coding, centre, unit)
        assert np.all(np.abs(np.array(coding.center) - centre) <= place), (coding, centre, unit)


def test_a_factor_at_one_value_in_every_run_is_refused_naming_it():
    table, names, centres, centre, unit = next(_tables(1, 5))
    table[names[-1]] = 123456.5
    with pytest.raises(InputError) as info:
        infer_coding(table, names, {"type": "ccd", "alpha": 2.0, "center_runs": centres}, "t.csv")
    assert info.value.column == names[-1] and "takes the single value 123456 in every run" in str(info.value)

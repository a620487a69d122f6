"""The design check's whole output on valid tables (demid.design_check.check_design), over generated designs:
CCDs (face-centred, rotatable, other axial distances), Box-Behnken designs and 3^k factorials of 2-4 factors, 1-4
centre runs, any run order, centres of either sign far from zero and half-ranges from 1e-3 to 1e3, values printed
to 12 significant digits: the coding is each factor's centre and factorial half-range, and every run's point type
is the one its generating point has (centre, factorial, axial, edge; 'other' for a 3^k factorial's mixed points),
counted as the design declares them.  A custom design is coded by each factor's mid-range over its half-range."""

from __future__ import annotations

from collections import Counter

import numpy as np
import pandas as pd
from hypothesis import Phase, given, settings
from hypothesis import strategies as st

from demid.design import box_behnken_points, ccd_points
from demid.design_check import check_design
from demid.design_generation import factorial_points

SETTINGS = settings(max_examples=20, deadline=None, derandomize=True, phases=[Phase.explicit, Phase.generate])


def _point_type(point, alpha):
    nonzero = np.abs(point) > 1e-9
    if not nonzero.any():
        return "center"
    if np.allclose(np.abs(point), 1.0):
        return "factorial"
    if nonzero.sum() == 1 and np.isclose(np.abs(point[nonzero][0]), alpha):
        return "axial"
    if nonzero.sum() == 2 and np.allclose(np.abs(point[nonzero]), 1.0):
        return "edge"
    return "other"


@given(design=st.sampled_from(["ccd-face", "ccd-rotatable", "ccd-1.5", "box_behnken", "factorial"]),
       k=st.integers(2, 4), centres=st.integers(1, 4), seed=st.integers(0, 10_000))
@SETTINGS
def test_a_valid_table_is_coded_by_its_centre_and_half_range_and_its_runs_typed(design, k, centres, seed):
    if design == "box_behnken" and k < 3:
        k = 3
    dtype, _, shape = design.partition("-")
    alpha = {"face": 1.0, "rotatable": (2.0 ** k) ** 0.25, "1.5": 1.5}.get(shape, 1.0)
    coded = (ccd_points(k, alpha, centres) if dtype == "ccd" else box_behnken_points(k, centres)
             if dtype == "box_behnken" else factorial_points(k, centres))
    rng = np.random.default_rng(seed)
    half = 10.0 ** rng.uniform(-3, 3, k)
    centre = rng.choice([-1.0, 1.0], k) * half * rng.uniform(0.0, 50.0, k)
    order = rng.permutation(len(coded))
    outer = alpha if dtype == "ccd" else 1.0
    actual = centre + coded[order] * half
    names = [f"f{i}" for i in range(k)]
    table = pd.DataFrame({n: [float(f"{v:.12g}") for v in actual[:, i]] for i, n in enumerate(names)})
    table.insert(0, "run", np.arange(1, len(table) + 1))
    declared = {"type": dtype, "center_runs": centres, **({"alpha": alpha} if dtype == "ccd" else {})}
    coding, types = check_design(table, names, declared, "t.csv", "materials.m")
    assert coding.factors == tuple(names)
    np.testing.assert_allclose((np.array(coding.center) - centre) / half, 0.0, atol=1e-9)
    np.testing.assert_allclose(coding.unit, half, rtol=1e-9)
    want = [_point_type(p, alpha) for p in coded[order]]
    assert list(types) == want
    counts = Counter(want)
    assert counts["center"] == centres
    if dtype == "ccd":
        assert (counts["factorial"], counts["axial"]) == (2 ** k, 2 * k)
    if dtype == "box_behnken":
        assert counts["edge"] == 2 * k * (k - 1)
    custom, custom_types = check_design(table, names, {"type": "custom"}, "t.csv", "materials.m")
    lo, hi = table[names].min().to_numpy(), table[names].max().to_numpy()
    np.testing.assert_allclose((np.array(custom.center) - (lo + hi) / 2) / half, 0.0, atol=1e-12)
    np.testing.assert_allclose(custom.unit, (hi - lo) / 2, rtol=1e-12)
    assert set(custom_types) == {"other"}
    assert outer >= 1.0

"""The design a table's geometry is inferred as, over generated textbook designs: CCDs (face-centred, rotatable
and other axial distances), Box-Behnken designs, 3^k factorials and two-level factorials with centre runs, for
2-4 factors, 1-5 centre runs, any run order and factor ranges of different scales (some on a log scale); the
family, the axial distance and the centre runs found are the generated ones, and the description says them."""

from __future__ import annotations

import re

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.design import box_behnken_points, ccd_points
from demid.design_generation import factorial_points
from demid.design_inference import infer_design


def _table(coded: np.ndarray, seed: int, log_mask: int) -> tuple[pd.DataFrame, list[str], list[str]]:
    rng = np.random.default_rng(seed)
    k = coded.shape[1]
    names = [f"f{i}" for i in range(k)]
    logs = [n for i, n in enumerate(names) if log_mask >> i & 1]
    columns = {}
    for i, n in enumerate(names):
        centre, half = rng.uniform(-3.0, 3.0), rng.uniform(0.05, 2.0)
        search = centre + coded[:, i] * half
        columns[n] = 10.0 ** search if n in logs else search * 10.0 ** rng.integers(-3, 4)
    order = rng.permutation(len(coded))
    table = pd.DataFrame({n: np.asarray(v)[order] for n, v in columns.items()})
    table.insert(0, "run", np.arange(1, len(table) + 1))
    return table, names, logs


@given(k=st.integers(2, 4), kind=st.sampled_from(["face", "rotatable", "other"]), centres=st.integers(1, 5),
       seed=st.integers(0, 10_000), log_mask=st.integers(0, 15))
@settings(max_examples=30, deadline=None, derandomize=True)
def test_a_ccd_is_inferred_with_its_axial_distance_and_centre_runs(k, kind, centres, seed, log_mask):
    alpha = {"face": 1.0, "rotatable": (2 ** k) ** 0.25, "other": 1.6}[kind]
    table, names, logs = _table(ccd_points(k, alpha, centres), seed, log_mask)
    found = infer_design(table, names, "t.csv", logs)
    if kind == "face" and k == 2:  # the face-centred CCD in two factors is the 3^2 factorial, point for point
        assert (found.family, found.center_runs) == ("factorial", centres)
        return
    if kind == "face":
        assert (found.family, found.alpha, found.center_runs) == ("ccd", (1.0,) * k, centres)
        assert found.describe() == (f"a {k}-factor central composite design (CCD), face-centred, alpha = 1, "
                                    f"{centres} centre run{'s' if centres > 1 else ''}")
        return
    assert found.family == "ccd" and found.center_runs == centres
    assert np.allclose(found.alpha, alpha, rtol=1e-6)
    text = found.describe()
    said = re.search(rf"a {k}-factor central composite design \(CCD\), axial distance alpha = ([\d.]+), "
                     rf"{centres} centre runs?$", text)
    assert said and float(said.group(1)) == pytest.approx(alpha, rel=1e-5), text
    assert found.design == {"type": "ccd", "alpha": found.alpha, "center_runs": centres, "inferred": True}


@given(k=st.integers(3, 4), centres=st.integers(1, 5), seed=st.integers(0, 10_000), log_mask=st.integers(0, 15))
@settings(max_examples=15, deadline=None, derandomize=True)
def test_a_box_behnken_design_is_inferred_with_its_centre_runs(k, centres, seed, log_mask):
    table, names, logs = _table(box_behnken_points(k, centres), seed, log_mask)
    found = infer_design(table, names, "t.csv", logs)
    assert (found.family, found.center_runs, found.alpha) == ("box_behnken", centres, (1.0,) * k)
    assert found.describe() == f"a {k}-factor Box-Behnken design with {centres} centre run{'s' if centres > 1 else ''}"


@given(k=st.integers(2, 3), centres=st.integers(1, 4), seed=st.integers(0, 10_000), log_mask=st.integers(0, 7))
@settings(max_examples=15, deadline=None, derandomize=True)
def test_a_three_level_factorial_is_inferred_with_its_centre_runs(k, centres, seed, log_mask):
    table, names, logs = _table(factorial_points(k, centres), seed, log_mask)
    found = infer_design(table, names, "t.csv", logs)
    assert (found.family, found.center_runs) == ("factorial", centres)
    assert found.describe() == f"a 3^{k} full factorial, {centres} centre run{'s' if centres > 1 else ''}"
    assert found.design["type"] == "factorial" and found.design["inferred"] is True


@pytest.mark.parametrize("k, centres", [(2, 3), (3, 1), (4, 2)])
def test_a_two_level_factorial_with_centre_runs_is_inferred_and_checked_as_custom(k, centres):
    corners = np.array(np.meshgrid(*[[-1.0, 1.0]] * k, indexing="ij")).reshape(k, -1).T
    coded = np.vstack([corners, np.zeros((centres, k))])
    table, names, logs = _table(coded, 7, 0)
    found = infer_design(table, names, "t.csv", logs)
    assert (found.family, found.center_runs) == ("two_level", centres)
    assert found.design["type"] == "custom"
    assert found.describe() == f"a {k}-factor two-level factorial with {centres} centre run{'s' if centres > 1 else ''}"


@pytest.mark.parametrize("outer", [1.02, 1.039])
def test_a_fourth_level_within_the_level_tolerance_of_a_factorial_level_is_no_axial_run(outer):
    """A 3^2 factorial with one more run whose factor a sits 2-4 % of a coded unit beyond its +1 level: a level
    that close to +1 is that level typed off, not the axial run of a CCD missing its other side."""
    coded = np.vstack([factorial_points(2, 3), [(outer, 0.0)]])
    table, names, logs = _table(coded, 11, 0)
    found = infer_design(table, names, "t.csv", logs)
    assert found.family != "ccd"
    beyond = np.vstack([factorial_points(2, 3), [(1.3, 0.0)]])  # 0.3 beyond: an axial level
    table, names, logs = _table(beyond, 11, 0)
    assert infer_design(table, names, "t.csv", logs).alpha[0] == pytest.approx(1.3)


def _two_level_points(k: int, centres: int) -> np.ndarray:
    corners = np.array(np.meshgrid(*[[-1.0, 1.0]] * k, indexing="ij")).reshape(k, -1).T
    return np.vstack([corners, np.zeros((centres, k))])


_FAMILIES = {"two_level": (_two_level_points, (2, 3, 4)), "box_behnken": (box_behnken_points, (3, 4)),
             "factorial": (factorial_points, (2, 3))}


@given(family=st.sampled_from(sorted(_FAMILIES)), which_k=st.integers(0, 2), centres=st.integers(1, 3),
       beyond=st.booleans(), seed=st.integers(0, 10_000))
@settings(max_examples=40, deadline=None, derandomize=True)
def test_a_family_missing_runs_is_kept_up_to_one_point_in_ten_and_no_further(family, which_k, centres, beyond, seed):
    """Failed runs left out of a table: a family is kept while at most one point in ten of it (at least one)
    has no run, and the table is custom one missing point later."""
    make, ks = _FAMILIES[family]
    k = ks[which_k % len(ks)]
    coded = make(k, centres)
    off_centre = np.flatnonzero(np.any(coded != 0, axis=1))
    allowed = max(1, len(off_centre) // 10)
    rng = np.random.default_rng(seed)
    missing = rng.choice(off_centre, allowed + int(beyond), replace=False)
    table, names, logs = _table(np.delete(coded, missing, axis=0), seed, 0)
    found = infer_design(table, names, "t.csv", logs)
    if beyond:
        assert found.family == "custom"
    else:
        assert (found.family, found.center_runs) == (family, centres)

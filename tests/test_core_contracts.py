"""Known answers for the numerical core where a plausible slip would otherwise go unseen.

Each test pins one behaviour against an answer computed independently of the code under
test: a closed-form admissible region, a hand-worked step-down example, statsmodels, or
the writers' byte-level contracts (sorted JSON keys, no software/time metadata), so they
hold across machines and library versions.  ``benchmarks/mutation.py`` measures how many
small bugs of the core the suite catches.
"""

from __future__ import annotations

import json
import os
import struct
import types

import numpy as np
import pandas as pd
import pyarrow.parquet as pq
import pytest

from demid.admissibility import Domain, admissible_set, plane_band_fraction
from demid.data import validate_material
from demid.design import ccd_points, model_matrix, quadratic_terms
from demid.errors import InputError
from demid.io import atomic_path, save_figure, to_json_text, write_csv, write_json, write_parquet
from demid.spec import MaterialSpec
from demid.surrogate import Surrogate
from demid.transcription import parse_printed, single_cell_slips

from .helpers import make_ccd_table

TERMS2 = quadratic_terms(2)  # Intercept, a, b, a:b, a^2, b^2
SQUARE = Domain(("a", "b"), (-1.0, -1.0), (1.0, 1.0))


def _surrogate(coef) -> Surrogate:
    return Surrogate("y", ["a", "b"], TERMS2, np.asarray(coef, float), np.zeros((6, 6)), 0.0, 7)


# --------------------------------------------------------------------------- admissible sets
PARABOLA = _surrogate([0, 0, 0, 0, 1.0, 0])  # y = a^2: admissible where T(1-eps) <= a^2 <= T(1+eps)


def _parabola_fraction(target, eps):
    return np.sqrt(target * (1 + eps)) - np.sqrt(target * (1 - eps))  # of a in [-1, 1], times b's full range


@pytest.mark.parametrize("n", [4, 8])
def test_coarse_grid_with_the_vertex_in_mid_cell(n):
    """y = a^2 on an even grid: the middle cell's corners are equal and inside the band while the set
    dips out of it at the vertex.  The plane through the corners is flat there (0/0 in the plane rule
    before), and counting the cell as inside (no curvature margin) would give a third too much."""
    target, eps = 1 / 9, 0.5
    result = admissible_set({"y": PARABOLA}, SQUARE, ["y"], {"y": target}, eps, n)
    exact = _parabola_fraction(target, eps)
    assert np.isfinite(result.fraction)
    assert result.fraction == pytest.approx(exact, abs=0.05)
    outer = np.sqrt(target * (1 + eps))
    assert result.lower[0] == pytest.approx(-outer, abs=2 / (n - 1) / 16 + 1e-9)
    assert result.upper[0] == pytest.approx(outer, abs=2 / (n - 1) / 16 + 1e-9)


def test_parabola_fraction_on_a_fine_grid():
    target, eps = 0.3, 0.2
    result = admissible_set({"y": PARABOLA}, SQUARE, ["y"], {"y": target}, eps, 400)
    assert result.fraction == pytest.approx(_parabola_fraction(target, eps), rel=1e-3)


def test_flat_cells_in_the_plane_rule_are_all_or_nothing():
    center = np.array([0.0, 0.3, -0.3, 0.31, 0.1, -0.3])
    increments = np.array([[0.0, 0.0, 0.0, 0.0, 0.4, 0.4], [0.0, 0.0, 0.0, 0.0, 0.0, 0.0]])
    # cell 5 rises from -0.1 to 0.3 along one axis (inside throughout); cell 6 from -0.5 to -0.1 (half inside)
    assert plane_band_fraction(center, increments, 0.3) == pytest.approx([1.0, 1.0, 1.0, 0.0, 1.0, 0.5], abs=1e-4)


def test_band_thinner_than_the_grid_spacing_spans_its_whole_cell():
    """y = a, band [a0(1-eps), a0(1+eps)] of width 0.001 between the nodes 0.3 and 0.4 (step 0.1):
    no node or sub-point is admissible, the span is the cell that holds the band."""
    dom = Domain(("a", "b"), (0.0, 0.0), (1.0, 1.0))
    a0 = 0.3504
    eps = 0.0005 / a0
    result = admissible_set({"y": _surrogate([0, 1.0, 0, 0, 0, 0])}, dom, ["y"], {"y": a0}, eps, 11)
    assert result.n_admissible_nodes == 0
    assert result.fraction == pytest.approx(0.001, rel=1e-6)  # the plane rule is exact for a linear field
    assert result.lower[0] <= a0 * (1 - eps) and result.upper[0] >= a0 * (1 + eps)
    assert result.lower[0] == pytest.approx(0.3) and result.upper[0] == pytest.approx(0.4)
    assert result.lower[1] == pytest.approx(0.0, abs=0.1 / 16) and result.upper[1] == pytest.approx(1.0, abs=0.1 / 16)


@pytest.mark.parametrize("center, radius", [((0.05, -0.03), 0.3), ((0.31, 0.17), 0.45)])
def test_span_ends_of_a_disk_on_a_coarse_grid_are_refined_within_the_outer_cells(center, radius):
    """Disk |x - c| <= r on an 11-point grid (step 0.2): the outermost nodes are up to a step inside
    the disk; the span ends are refined on a 16-point sub-grid of the outer cells (error <= 0.2/16)."""
    a0, b0 = center
    sur = _surrogate([a0 ** 2 + b0 ** 2, -2 * a0, -2 * b0, 0, 1.0, 1.0])
    result = admissible_set({"y": sur}, SQUARE, ["y"], {"y": radius ** 2 / 2}, 0.999999, 11)
    exact_lower, exact_upper = np.array(center) - radius, np.array(center) + radius
    assert np.all(result.lower >= exact_lower) and np.all(result.lower <= exact_lower + 0.2 / 16)
    assert np.all(result.upper <= exact_upper) and np.all(result.upper >= exact_upper - 0.2 / 16)


def test_two_point_grid_measures_a_linear_band_exactly():
    """One cell per axis: no curvature information, the plane rule is exact for y = a."""
    dom = Domain(("a", "b"), (0.0, 0.0), (1.0, 1.0))
    result = admissible_set({"y": _surrogate([0, 1.0, 0, 0, 0, 0])}, dom, ["y"], {"y": 0.5}, 0.2, 2)
    assert result.fraction == pytest.approx(0.2, abs=1e-4)  # a in [0.4, 0.6]


def test_lens_of_two_disks_fraction_and_extent():
    """Two disks of radius R whose centres are 2d apart: lens area 2R^2 acos(d/R) - 2d sqrt(R^2 - d^2),
    extent |a| <= R - d, |b| <= sqrt(R^2 - d^2).  Boundary cells where both observables are active
    are sub-sampled."""
    radius, d = 0.5, 0.2

    def disk(a0):
        return Surrogate("y", ["a", "b"], TERMS2, np.array([a0 ** 2, -2 * a0, 0, 0, 1.0, 1.0]), np.zeros((6, 6)),
                         0.0, 7)

    sur = {"p": disk(-d), "q": disk(d)}
    targets = {"p": radius ** 2 / 2, "q": radius ** 2 / 2}
    result = admissible_set(sur, SQUARE, ["p", "q"], targets, 0.999999, 41)
    area = 2 * radius ** 2 * np.arccos(d / radius) - 2 * d * np.sqrt(radius ** 2 - d ** 2)
    assert result.observables == ("p", "q")
    assert result.fraction == pytest.approx(area / 4, rel=0.01)
    half = np.array([radius - d, np.sqrt(radius ** 2 - d ** 2)])
    step = 2 / 40
    # sub-grid accuracy (step/16), coarser at the lens's pointed tips in b
    assert np.all(result.lower >= -half) and np.all(result.lower <= -half + step / 8)
    assert np.all(result.upper <= half) and np.all(result.upper >= half - step / 8)


def test_scenarios_use_the_grid_up_to_three_factors_and_sobol_above():
    """A spherical shell r^2 in [T(1-eps), T(1+eps)] around the cube's centre, volume
    4/3 pi T^1.5 ((1+eps)^1.5 - (1-eps)^1.5)."""
    from demid.admissibility import evaluate_scenarios

    target, eps = 0.09, 0.2
    for factors in (("a", "b", "c"), ("a", "b", "c", "d")):
        k = len(factors)
        terms = quadratic_terms(k)
        coef = np.concatenate([[0.25 * k], -np.ones(k), np.zeros(k * (k - 1) // 2), np.ones(k)])
        sur = {"y": Surrogate("y", list(factors), terms, coef, np.zeros((len(terms),) * 2), 0.0, 7)}
        cfg = {"factors": {f: {"lower": 0, "upper": 1} for f in factors}, "responses": {"y": {"target": target}},
               "scenarios": {"shell": {"observables": ["y"], "tolerance": eps}}}
        if k == 3:
            cfg["scenarios"]["wide"] = {"observables": ["y"], "tolerance": 2 * eps}
        table, sets = evaluate_scenarios(sur, MaterialSpec.from_material("m", {"design": {"type": "ccd"}, **cfg}),
                                         31 if k == 3 else 2 ** 12)
        result = sets["shell"]
        if k == 3:
            exact = 4 / 3 * np.pi * target ** 1.5 * ((1 + eps) ** 1.5 - (1 - eps) ** 1.5)
            assert result.fraction_ci is None and result.n_nodes == 31 ** 3
            assert result.fraction == pytest.approx(exact, rel=0.01)
        else:
            exact = np.pi ** 2 / 2 * target ** 2 * ((1 + eps) ** 2 - (1 - eps) ** 2)
            assert result.fraction_ci[0] <= exact <= result.fraction_ci[1]
            assert result.fraction == pytest.approx(exact, rel=0.1)
        scenarios = list(cfg["scenarios"])
        assert list(table.index) == list(range(len(scenarios) * k))  # one row per scenario and factor
        assert table["scenario"].tolist() == [name for name in scenarios for _ in range(k)]
        assert table["feasible_fraction_pct"].iloc[0] == pytest.approx(100 * result.fraction)


# --------------------------------------------------------------------------- criticism: multiplicity control
def test_stepdown_min_p_is_monotone_on_a_hand_worked_example():
    """Westfall-Young step-down min-P on 3 hypotheses and 4 null draws, worked by hand.

    Raw step p-values (1 + #{min over the remaining nulls <= observed}) / 5: step 1 (all three)
    1 hit -> 0.4; step 2 (hypotheses 2, 3) no hit -> 0.2; step 3 (hypothesis 3) 2 hits -> 0.6.
    Adjusted p-values are the running maximum: 0.4, 0.4, 0.6.
    """
    from demid.criticism.catalogue import stepdown_minp

    obs = np.log([0.01, 0.02, 0.03])
    null = np.array([[-5.0, 0.0, 0.0],
                     [0.0, 0.0, -3.6],
                     [0.0, 0.0, -3.55],
                     [0.0, 0.0, 0.0]])
    assert stepdown_minp(obs, null) == pytest.approx([0.4, 0.4, 0.6])
    perm = [2, 0, 1]  # the hypotheses' input order does not matter
    assert stepdown_minp(obs[perm], null[:, perm]) == pytest.approx([0.6, 0.4, 0.4])


def test_box_cox_bootstrap_draws_sigma_with_n_minus_p_degrees_of_freedom():
    """P(LR* >= LR | y* > 0) with y* = fitted + s N(0, 1), s^2 = SSE / (n - p), against an independent
    simulation.  Near zero the positivity conditioning makes the answer depend on s: with
    s^2 = SSE / n the p-value is ~0.17 instead of ~0.25 here."""
    from demid.criticism.catalogue import Round
    from demid.criticism.models import orthonormal_basis

    x = model_matrix(ccd_points(2, 1.41421, 5), TERMS2)
    n, p = x.shape
    q = orthonormal_basis(x)
    fitted = 2.0 + 0.3 * x[:, 1]
    sd = 1.5
    model = types.SimpleNamespace(ssr=sd ** 2 * (n - p), df_resid=n - p, fitted_z=fitted, y=fitted)
    lr_obs = 3.0
    rng = np.random.default_rng(5)
    y = fitted[:, None] + sd * rng.standard_normal((n, 12_000))
    y = y[:, np.all(y > 0, axis=0)]
    expected = np.mean(Round._boxcox_lr(y, q) >= lr_obs)
    p_boot, used = Round._boxcox_bootstrap(Round.__new__(Round), model, q, lr_obs, 3000,
                                           np.random.default_rng(6))
    assert used == 3000
    assert p_boot == pytest.approx(expected, abs=0.035)


def test_fraction_estimate_relative_error():
    from demid.uncertainty import FractionEstimate

    def estimate(fraction, error):
        return FractionEstimate(fraction=fraction, error=error, coarse_fraction=fraction, n=3, evaluations=1,
                                analytic_cells=0, sampled_cells=0)

    assert estimate(0.2, 0.01).relative_error == pytest.approx(0.05)
    assert estimate(0.0, 0.0).relative_error == 0.0
    assert estimate(0.0, 0.01).relative_error == np.inf


def _ring(center):
    a0, b0 = center
    return _surrogate([a0 ** 2 + b0 ** 2, -2 * a0, -2 * b0, 0, 1.0, 1.0])


def test_polished_spans_in_a_box_that_is_not_the_unit_square():
    """Annulus around (0.9, 1.2) in [0, 2] x [-1, 3]: polishing works in scaled units and must map back."""
    from demid.uncertainty import polish_spans

    dom = Domain(("a", "b"), (0.0, -1.0), (2.0, 3.0))
    center, r0, eps = np.array([0.9, 1.2]), 0.5, 0.05
    sur = {"y": _ring(center)}
    aset = admissible_set(sur, dom, ["y"], {"y": r0 ** 2}, eps, 21)
    lower, upper = polish_spans(sur, dom, ["y"], {"y": r0 ** 2}, eps, aset)
    outer = r0 * np.sqrt(1 + eps)
    assert lower == pytest.approx(center - outer, abs=1e-7)
    assert upper == pytest.approx(center + outer, abs=1e-7)


def test_polishing_starts_from_the_admissible_nodes():
    from demid.sampling.polish import start_points
    from demid.sampling.residuals import residual_evaluator

    dom = Domain(("a", "b"), (0.0, -1.0), (2.0, 3.0))
    sur = {"y": _ring([0.9, 1.2])}
    aset = admissible_set(sur, dom, ["y"], {"y": 0.25}, 0.05, 21)
    starts = start_points(residual_evaluator(sur, ("y",), {"y": 0.25}), dom, aset)
    nodes = dom.grid(21)[aset.mask]
    assert len(starts) == aset.n_admissible_nodes > 0
    # one array, not a list of tuples: pytest.approx compares no nested sequences (an error from pytest 9.2)
    assert np.array(sorted(map(tuple, starts))) == pytest.approx(np.array(sorted(map(tuple, nodes))))


def test_grid_error_bounds_the_error_of_the_reference_fraction():
    """A reference fraction 0.05 off the exact annulus area: grid_error must cover that offset."""
    import dataclasses

    from demid.uncertainty import fraction_with_error

    dom = Domain(("a", "b"), (0.0, 0.0), (1.0, 1.0))
    r0, eps = 0.3, 0.05
    sur = {"y": _ring([0.5, 0.5])}
    exact = 2 * np.pi * r0 ** 2 * eps
    grid = admissible_set(sur, dom, ["y"], {"y": r0 ** 2}, eps, 41)
    off = dataclasses.replace(grid, fraction=exact + 0.05)
    est = fraction_with_error(sur, dom, ["y"], {"y": r0 ** 2}, eps, 41, reference=off)
    assert est.grid_fraction == exact + 0.05
    assert est.grid_error >= 0.05 > est.error
    assert abs(est.fraction - exact) <= est.error


@pytest.mark.parametrize("lam", [None, 0.0, -0.5, 0.5, 2.0])
def test_box_cox_back_transform_inverts_scipy(lam):
    from scipy import special

    from demid.criticism.models import boxcox, inv_boxcox

    y = np.array([0.3, 1.0, 2.5, 40.0])
    z = y if lam is None else special.boxcox(y, lam)
    assert boxcox(y, lam) == pytest.approx(z)
    assert inv_boxcox(z, lam) == pytest.approx(y, rel=1e-12)


# --------------------------------------------------------------------------- transcription
def test_decimal_shift_slips_move_the_point_one_or_two_places():
    slips = {value: kind for kind, _, value in single_cell_slips("1.234")}
    for value in (0.01234, 0.1234, 12.34, 123.4):
        assert slips.get(value) == "decimal_shift", value
    assert 1234.0 not in slips or slips[1234.0] != "decimal_shift"
    assert slips.get(-1.234) == "sign_lost" and slips.get(1.2345) == "digit_dropped"
    assert slips.get(1.243) == "transposition" and slips.get(1.334) == "digit_substitution"
    assert {value: kind for kind, _, value in single_cell_slips("1.224")}.get(1.24) == "digit_doubled"


def test_a_typeset_minus_is_read_as_a_minus_by_the_slip_search():
    # U+2212, as copied from a PDF: the table reader accepts it, so its repairs must be found too
    slips = {value: kind for kind, _, value in single_cell_slips("\u2212120.4")}
    assert slips.get(120.4) == "sign_lost" and slips.get(-12.04) == "decimal_shift"


def test_agreement_rule_is_the_rounding_interval_of_the_printed_digits():
    printed = parse_printed("0.97")
    values = [0.965, 0.975, 0.9651, 0.9749, 0.9751, 0.9649, np.nan, np.inf]
    assert printed.agrees(values).tolist() == [True, True, True, True, False, False, False, False]
    assert printed.misfit([0.98, 0.97, 0.96]) == pytest.approx([2.0, 0.0, 2.0])
    below, above = parse_printed("<0.05"), parse_printed(">= 2")
    assert below.agrees([0.05, 0.0499, 0.0501]).tolist() == [True, True, False]
    assert above.agrees([2.0, 2.5, 1.9]).tolist() == [True, True, False]
    assert below.misfit([0.07, 0.01]) == pytest.approx([4.0, 0.0])  # half-width 0.005
    assert above.misfit([1.0, 3.0]) == pytest.approx([2.0, 0.0])  # half-width 0.5
    assert parse_printed("12.50%").decimals == 4 and parse_printed("12.50%").value == pytest.approx(0.125)
    assert parse_printed({"value": "0.5", "decimals": 3}).decimals == 3
    assert parse_printed(np.float64(0.97)).decimals == 2 and parse_printed(np.float64(0.97)).value == 0.97
    with pytest.raises(InputError):
        parse_printed({"decimals": 3})


# --------------------------------------------------------------------------- data validation
# Runs 2, 5, 7, 8 are centre runs (13 keeps one), 6 and 9 the x2 axial runs, 10 an x1 axial run: the
# usable runs that remain still determine every quadratic term.
@pytest.mark.parametrize("failed, ok", [([2, 5, 7, 8, 6, 9, 10], False), ([2, 5, 7, 8, 6, 9], True)])
def test_a_quadratic_in_two_factors_needs_seven_usable_runs(tmp_path, failed, ok):
    """6 coefficients: exactly 6 usable runs leave no residual degree of freedom and are rejected."""
    table = make_ccd_table(lambda x: {"y": 5 + x[:, 0] + x[:, 1] ** 2}, [0.1, 1.0], [0.9, 11.0], noise=0.1,
                           seed=4)
    table["status"] = "ok"
    table.loc[table["run"].isin(failed), ["y", "status"]] = [np.nan, "failed"]
    path = tmp_path / "t.csv"
    table.to_csv(path, index=False)
    cfg = {"data": str(path), "design": {"type": "ccd", "alpha": 1.41421, "center_runs": 5},
           "factors": {"x1": {"lower": 0.1, "upper": 0.9}, "x2": {"lower": 1.0, "upper": 11.0}},
           "responses": {"y": {"target": 10.0}}}
    if ok:
        assert len(validate_material(MaterialSpec.from_material("m", cfg)).failed["y"]) == len(failed)
    else:
        with pytest.raises(InputError, match="only 6 usable runs for a quadratic model with 6 coefficients"):
            validate_material(MaterialSpec.from_material("m", cfg))


def _ccd_csv(tmp_path, cells=None):
    table = make_ccd_table(lambda x: {"y": 5 + x[:, 0] + x[:, 1] ** 2}, [0.1, 1.0], [0.9, 11.0], noise=0.1, seed=4)
    table = table.astype({"y": object})
    for (run, column), value in (cells or {}).items():
        table.loc[table["run"] == run, column] = value
    path = tmp_path / "t.csv"
    table.to_csv(path, index=False)
    return path


def test_missing_columns_are_named(tmp_path):
    from demid.data import read_table

    path = _ccd_csv(tmp_path)
    for needed in ("run", "x2", "y"):
        text = path.read_text(encoding="utf-8").replace(needed, "other", 1)
        (tmp_path / "m.csv").write_text(text, encoding="utf-8")
        with pytest.raises(InputError, match=f"column '{needed}'.*missing column"):
            read_table(tmp_path / "m.csv", ["x1", "x2"], ["y"])


def test_nan_text_is_a_failed_run_and_an_empty_cell_needs_a_status(tmp_path):
    from demid.data import read_table

    table, warnings = read_table(_ccd_csv(tmp_path, {(3, "y"): "NaN"}), ["x1", "x2"], ["y"])
    assert np.isnan(table.loc[table["run"] == 3, "y"].iloc[0]) and np.isfinite(table["y"]).sum() == 12
    assert warnings == [f"{tmp_path / 't.csv'}, run 3, column 'y': value 'NaN' treated as a failed simulation"]
    with pytest.raises(InputError, match=r"run 5, column 'y': empty cell; if this simulation failed, add a "
                                         r"'status' column"):
        read_table(_ccd_csv(tmp_path, {(5, "y"): ""}), ["x1", "x2"], ["y"])


def test_a_failed_run_with_a_number_left_in_a_cell_is_refused_and_nan_text_is_warned_once(tmp_path):
    from demid.data import read_table

    table = make_ccd_table(lambda x: {"y": 5 + x[:, 0], "z": 1 + x[:, 1]}, [0.1, 1.0], [0.9, 11.0], seed=4)
    table = table.astype({"y": object, "z": object})
    table["status"] = "ok"
    table.loc[table["run"] == 2, ["y", "z", "status"]] = ["nan", 12.5, "failed"]
    table.to_csv(tmp_path / "t.csv", index=False)
    with pytest.raises(InputError, match=r"run 2, column 'z'.*marked 'failed'"):
        read_table(tmp_path / "t.csv", ["x1", "x2"], ["y", "z"])
    table.loc[table["run"] == 2, "z"] = ""
    table.to_csv(tmp_path / "t.csv", index=False)
    read, warnings = read_table(tmp_path / "t.csv", ["x1", "x2"], ["y", "z"])
    row = read[read["run"] == 2].iloc[0]
    assert np.isnan(row["y"]) and np.isnan(row["z"])
    assert len(warnings) == 1 and "run 2: marked 'failed'" in warnings[0]


def test_off_level_value_names_its_run_and_the_nearest_level(tmp_path):
    table = make_ccd_table(lambda x: {"y": 5 + x[:, 0]}, [0.1, 1.0], [0.9, 11.0], noise=0.1, seed=4)
    row = int(np.flatnonzero(np.isclose(table["x1"], 0.5 + 0.4 / 1.41421))[0])  # a +1 level of x1
    run = int(table["run"].iloc[row])
    table.loc[row, "x1"] = 0.5 + 0.4 / 1.41421 * 1.3  # coded +1.3: between the levels +1 and +alpha
    path = tmp_path / "t.csv"
    table.to_csv(path, index=False)
    cfg = {"data": str(path), "design": {"type": "ccd", "alpha": 1.41421, "center_runs": 5},
           "factors": {"x1": {"lower": 0.1, "upper": 0.9}, "x2": {"lower": 1.0, "upper": 11.0}},
           "responses": {"y": {"target": 10.0}}}
    with pytest.raises(InputError, match=rf"run {run}, column 'x1': value 0\.867696 is not a level of the declared "
                                         r"ccd design \(coded \+1\.300\); nearest valid level: 0\.9 "
                                         r"\(coded \+1\.414\)"):
        validate_material(MaterialSpec.from_material("m", cfg))


def test_bounds_tolerance_is_relative_to_the_range():
    from demid.data import check_bounds
    from demid.spec import Factor

    factors = (Factor("x", 1000.0, 1001.0, False, "x", "-"),)
    check_bounds(pd.DataFrame({"run": [1, 2], "x": [1000.0, 1001.0000005]}), factors, "t.csv")  # 5e-7 of range
    with pytest.raises(InputError, match=r"run 2, column 'x': value 1001 lies outside the declared bounds"):
        check_bounds(pd.DataFrame({"run": [1, 2], "x": [1000.0, 1001.00001]}), factors, "t.csv")
    with pytest.raises(InputError, match=r"run 1, column 'x'"):
        check_bounds(pd.DataFrame({"run": [1, 2], "x": [999.99999, 1001.0]}), factors, "t.csv")
    # the tolerance is inclusive: exactly 1e-6 of the range outside is still accepted
    check_bounds(pd.DataFrame({"run": [1, 2], "x": [-1e-6, 1 + 1e-6]}), (Factor("x", 0.0, 1.0, False, "x", "-"),), "t")


def test_design_description_and_cubic_terms():
    from demid.design import DesignStructure, cubic_terms

    assert DesignStructure(13, 4, 4, 5, 0, 1.414).describe() == "13 runs: 4 factorial, 4 axial, 5 centre"
    assert DesignStructure(14, 4, 4, 5, 1, 1.414).describe() == "14 runs: 4 factorial, 4 axial, 5 centre, 1 other"
    # the cubic terms of k factors: k pure cubes and k(k-1) + C(k, 3) mixed ones
    for k in (1, 2, 3, 4):
        terms = cubic_terms(k)
        assert len(terms) == len(set(terms)) == k + k * (k - 1) + k * (k - 1) * (k - 2) // 6
        assert all(sum(t) == 3 and len(t) == k for t in terms)


def test_coding_from_levels_and_point_classes():
    from demid.design import Coding, classify_points, replicate_groups

    coding = Coding.from_levels(("a", "b", "c"), [[0.0, 10.0, 7.0], [2.0, 30.0, 7.0], [1.0, 20.0, 7.0]], alpha=2.0)
    assert coding.center == (1.0, 20.0, 7.0) and coding.unit == (0.5, 5.0, 1.0)  # constant column: unit 1
    alpha = 1.682
    points = [[1, 1, 0], [1, 1, 0.5], [1, 0, 0], [0, 0, 0], [1, -1, 1], [0, -alpha, 0], [0, 1, -1]]
    assert classify_points(np.array(points), alpha).tolist() == ["edge", "other", "other", "center", "factorial",
                                                                 "axial", "edge"]
    # replicates are equal to 6 decimals in coded units
    groups = replicate_groups(np.array([[0.0, 0.0], [0.0, 2e-6], [0.0, 4e-7], [1.0, 1.0]]))
    assert groups[0] == groups[2] and len(set(groups.tolist())) == 3


# --------------------------------------------------------------------------- deterministic writers
def _png_chunks(path):
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, chunks = 8, []
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        chunks.append((kind.decode("ascii"), data[pos + 8:pos + 8 + length]))
        pos += 12 + length
    return chunks


def test_json_text_has_sorted_keys_rounded_floats_and_null_for_nan():
    obj = {"b": np.float64(0.1) + 0.2, "a": {"z": np.int64(3), "y": [np.nan, np.bool_(True)]},
           "c": np.array([1.0, np.inf]), "d\u2085\u2080": "\u00b5m"}
    assert to_json_text(obj) == ('{\n  "a": {\n    "y": [\n      null,\n      true\n    ],\n    "z": 3\n  },\n'
                                 '  "b": 0.3,\n  "c": [\n    1.0,\n    null\n  ],\n  "d\u2085\u2080": "\u00b5m"\n}\n')


def test_write_json_writes_exactly_the_sorted_text(tmp_path):
    obj = {"zeta": 1, "alpha": {"y": 2, "x": 1}}
    write_json(obj, str(tmp_path / "new" / "dir" / "o.json"))  # a str path; missing folders are made
    text = (tmp_path / "new" / "dir" / "o.json").read_text(encoding="utf-8")
    assert text == to_json_text(obj)
    assert list(json.loads(text)) == ["alpha", "zeta"] and list(json.loads(text)["alpha"]) == ["x", "y"]


def test_png_has_no_software_or_time_metadata(tmp_path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots()
    ax.plot([0, 1], [1, 0])
    save_figure(fig, tmp_path / "f.png", dpi=30)
    chunks = _png_chunks(tmp_path / "f.png")
    kinds = [k for k, _ in chunks]
    assert kinds[0] == "IHDR" and kinds[-1] == "IEND"
    assert "tIME" not in kinds
    texts = [body for k, body in chunks if k in ("tEXt", "iTXt", "zTXt")]
    assert not any(b"Software" in t or b"Date" in t or b"Creation" in t for t in texts), texts
    assert struct.unpack(">II", chunks[0][1][:8]) == (int(6.4 * 30), int(4.8 * 30))  # dpi is honoured
    fig = plt.figure(figsize=(1.0, 0.5))
    save_figure(fig, tmp_path / "g.png")
    assert struct.unpack(">II", _png_chunks(tmp_path / "g.png")[0][1][:8]) == (300, 150)  # default 300 dpi


def test_parquet_has_no_key_value_metadata_or_statistics(tmp_path):
    frame = pd.DataFrame({"a": [0.1, 0.2, np.nan], "name": ["x", "y", "x"]}, index=[5, 6, 7])
    write_parquet(frame, tmp_path / "t.parquet")
    meta = pq.ParquetFile(tmp_path / "t.parquet").metadata
    # only Arrow's own schema: no pandas block (index, library versions) and no timestamps
    assert set(meta.metadata or {}) <= {b"ARROW:schema"}
    assert pq.read_schema(tmp_path / "t.parquet").metadata is None
    row_group = meta.row_group(0)
    assert all(not row_group.column(i).is_stats_set for i in range(row_group.num_columns))
    # floats byte-stream-split, everything else dictionary-encoded (the layout the readers are tuned for)
    assert "BYTE_STREAM_SPLIT" in row_group.column(0).encodings
    assert "RLE_DICTIONARY" not in row_group.column(0).encodings
    assert "RLE_DICTIONARY" in row_group.column(1).encodings
    back = pq.read_table(tmp_path / "t.parquet").to_pandas()
    pd.testing.assert_frame_equal(back, frame.reset_index(drop=True))
    no_floats = pd.DataFrame({"run": [3, 1, 2], "name": ["x", "y", "x"]})
    write_parquet(no_floats, tmp_path / "i.parquet")
    group = pq.ParquetFile(tmp_path / "i.parquet").metadata.row_group(0)
    assert all("BYTE_STREAM_SPLIT" not in group.column(i).encodings for i in range(2))
    pd.testing.assert_frame_equal(pq.read_table(tmp_path / "i.parquet").to_pandas(), no_floats)


def test_csv_uses_six_significant_digits_and_unix_newlines(tmp_path):
    write_csv(pd.DataFrame({"x": [1 / 3, 2.0, 0.1 + 0.2, 123456789.0], "s": ["a", "b", "c", "d"]}),
              tmp_path / "t.csv")
    assert (tmp_path / "t.csv").read_bytes() == b"x,s\n0.333333,a\n2,b\n0.3,c\n1.23457e+08,d\n"


def test_atomic_path_leaves_nothing_behind_on_failure(tmp_path):
    target = tmp_path / "sub" / "out.json"
    target.parent.mkdir()
    write_json({"v": 1}, target)
    with pytest.raises(RuntimeError):
        with atomic_path(target) as tmp:
            tmp.write_text("partial", encoding="utf-8")
            raise RuntimeError("boom")
    assert target.read_text(encoding="utf-8") == to_json_text({"v": 1})
    assert sorted(p.name for p in target.parent.iterdir()) == ["out.json"]
    umask = os.umask(0)
    os.umask(umask)
    assert target.stat().st_mode & 0o777 == 0o666 & ~umask


def test_sobol_evaluation_points_are_stratified_in_search_units():
    """Scrambled Sobol points of 2**m: every coordinate has exactly one point in each of the 2**m
    equal slices of its search interval (log10 for log factors)."""
    dom = Domain(("a", "b", "g", "c"), (0.0, 2.0, 1e-3, -1.0), (1.0, 6.0, 1e-1, 3.0), (False, False, True, False))
    points = dom.sample(100)
    assert points.shape == (128, 4)
    lo, hi = np.array([0.0, 2.0, -3.0, -1.0]), np.array([1.0, 6.0, -1.0, 3.0])
    u = dom.to_search(points)
    slot = np.floor((u - lo) / (hi - lo) * 128).astype(int)
    for i in range(4):
        assert sorted(slot[:, i]) == list(range(128))
    assert np.array_equal(dom.sample(100), points)  # deterministic


def test_aicc_is_undefined_without_spare_degrees_of_freedom():
    """AICc = -2 llf + 2k + 2k(k+1)/(n-k-1): a number for n > k + 1, NaN (not +-inf) otherwise."""
    from demid.criticism.models import aicc_of

    assert aicc_of(-10.0, 20, 6) == pytest.approx(20.0 + 12.0 + 2 * 6 * 7 / 13)
    assert np.isnan(aicc_of(-10.0, 7, 6)) and np.isnan(aicc_of(-10.0, 5, 6))


def test_small_and_large_values_are_written_positionally():
    """Slip generation works on the printed digits, so exponents must never reach it."""
    from demid.transcription.printed import positional

    assert positional(1e-05) == "0.00001"
    assert positional(2.5e16) == "25000000000000000"
    assert positional(33.49) == "33.49"


def test_sobol_fraction_of_two_slabs_in_a_scaled_box():
    """y1 = a and y2 = b/2, both within 25 % of 1, in [0,2]x[0,4]x[0,1]^2: a in [0.75, 1.25] and b in
    [1.5, 2.5] at once cover (1/4)(1/4) = 1/16 of the box (either slab alone: 7/16)."""
    from demid.sampling.sobol import sobol_fraction

    factors = ("a", "b", "c", "d")
    terms = quadratic_terms(4)
    domain = Domain(factors, (0.0, 0.0, 0.0, 0.0), (2.0, 4.0, 1.0, 1.0))

    def linear(response, factor, slope):
        coef = np.zeros(len(terms))
        coef[1 + factors.index(factor)] = slope
        return Surrogate(response, list(factors), terms, coef, np.zeros((len(terms),) * 2), 0.0, 7)

    surrogates = {"y1": linear("y1", "a", 1.0), "y2": linear("y2", "b", 0.5)}
    res = sobol_fraction(surrogates, domain, ["y1", "y2"], {"y1": 1.0, "y2": 1.0}, 0.25, 2 ** 14, 3)
    assert res.ci_lower <= 1 / 16 <= res.ci_upper
    assert res.fraction == pytest.approx(1 / 16, rel=0.03)
    np.testing.assert_allclose(res.lower, [0.75, 1.5, 0.0, 0.0], atol=1e-6)
    np.testing.assert_allclose(res.upper, [1.25, 2.5, 1.0, 1.0], atol=1e-6)


def test_relative_residuals_divide_by_the_magnitude_of_the_target():
    """A negative target keeps the sign of y - y*: -9 against -10 lies 10 % above, -11 10 % below."""
    from demid.sampling.residuals import relative_residuals

    res = relative_residuals({"y": np.array([-9.0, -11.0]), "z": np.array([4.0, 6.0])}, {"y": -10.0, "z": 5.0},
                             ["y", "z"])
    np.testing.assert_allclose(res, [[0.1, -0.1], [-0.2, 0.2]])


def test_lack_of_fit_holds_its_share_of_the_family_level():
    """Weighted step-down min-P against the exact answer for independent tests: with lack of fit at nominal
    p and nine other members at p = 0.5, lack of fit's adjusted p-value is P(min_j U_j / s_j <= p / s_lof)
    = 1 - prod_j (1 - min(1, s_j p / s_lof)), shares s_lof = LOF_SHARE and (1 - LOF_SHARE) / 9 each.
    Without replicated runs (no lack-of-fit member) the weights are equal."""
    from demid.criticism.catalogue import LOF_SHARE, family_weights, weighted_stepdown

    causes = ["lack_of_fit"] + ["missing_term"] * 9
    rng = np.random.default_rng(7)
    null = np.log(rng.uniform(size=(200_000, 10)))
    p = 0.02
    obs = np.log(np.r_[p, np.full(9, 0.5)])
    shares = np.r_[LOF_SHARE, np.full(9, (1 - LOF_SHARE) / 9)]
    exact = 1 - np.prod(1 - np.minimum(1, shares * p / LOF_SHARE))
    adjusted = weighted_stepdown(causes, obs, null)[0]
    assert adjusted == pytest.approx(exact, abs=4 * np.sqrt(exact * (1 - exact) / 200_000))
    equal = weighted_stepdown(["missing_term"] * 10, obs, null)[0]  # 1 - (1 - p)^10 = 0.18
    assert equal == pytest.approx(1 - (1 - p) ** 10, abs=0.005)
    assert adjusted < 0.05 < equal
    assert np.all(family_weights(["outlier", "drift", "missing_term"]) == 1.0)
    assert family_weights(causes).mean() == pytest.approx(1.0)


@pytest.mark.parametrize("layout", ["constrained", "tight"])
def test_figure_drawn_once_has_the_pixels_savefig_gives(tmp_path, layout):
    """save_figure lays the figure out and renders it in one draw: the PNG must show what matplotlib's
    own savefig (a hidden layout draw, then the render) shows, labels and titles placed alike."""
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure
    from PIL import Image

    def build():
        fig = Figure(figsize=(4, 2.5), layout=layout)
        axes = fig.subplots(1, 2)
        for ax in axes:
            ax.plot([0, 1e4], [0, 1])
            ax.set_xlabel(r"a long label with mathtext $\mu_{\mathrm{r}}$ [J m$^{-2}$]")
            ax.set_title("title\nsecond line")
        fig.suptitle("suptitle")
        return fig

    save_figure(build(), tmp_path / "ours.png", dpi=60)
    build().savefig(tmp_path / "theirs.png", dpi=60, format="png")
    ours = np.asarray(Image.open(tmp_path / "ours.png").convert("RGBA"))
    theirs = np.asarray(Image.open(tmp_path / "theirs.png").convert("RGBA"))
    assert ours.shape == theirs.shape and np.array_equal(ours, theirs)
    assert (tmp_path / "ours.svg").read_text().count("<svg") == 1

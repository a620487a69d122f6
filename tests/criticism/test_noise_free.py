"""Deterministic simulators: round-off residuals are never a finding; lack of fit without pure error is undefined."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from demid.criticism import criticize
from demid.design import ccd_points, model_matrix, quadratic_terms
from demid.surrogate import fit_response


def _exact_table(k, seed, scale):
    """An exact quadratic on a CCD in actual units; the centre runs are identical (a deterministic code)."""
    rng = np.random.default_rng(seed)
    alpha = (2 ** k) ** 0.25
    coded = ccd_points(k, alpha, 5)
    lower, upper = rng.uniform(0.01, 1, k), rng.uniform(2, 20, k)
    actual = coded * (upper - lower) / (2 * alpha) + (lower + upper) / 2
    beta = rng.normal(0, 1, len(quadratic_terms(k))) * scale
    beta[0] = scale * rng.uniform(5, 50)
    y = model_matrix(actual, quadratic_terms(k)) @ beta  # exact in actual units: round-off only
    order = rng.permutation(len(coded))
    table = pd.DataFrame(actual[order], columns=[f"x{i + 1}" for i in range(k)])
    table.insert(0, "run", np.arange(1, len(coded) + 1))
    table["y"] = y[order]
    return table


@pytest.mark.parametrize("k,seed,scale", [(2, 1, 1.0), (2, 2, 1e6), (3, 3, 1e-4), (3, 4, 250.0)])
def test_exact_quadratic_gives_no_findings_and_undefined_lack_of_fit(k, seed, scale):
    table = _exact_table(k, seed, scale)
    factors = [f"x{i + 1}" for i in range(k)]
    fit = fit_response(table, factors, "y", alpha=(2 ** k) ** 0.25)
    st = fit.statistics()
    assert np.isnan(st.lof_f) and np.isnan(st.lof_p)  # neither infinite nor a huge number
    anova = fit.anova().to_frame().set_index("source")
    assert "pure error is zero" in anova.loc["Lack of fit", "note"]
    infl = fit.influence()
    assert not np.any(np.abs(infl["student_resid"].to_numpy()) > 1e3)  # no 1e136 from 0/0
    diag = fit.diagnostics()
    assert np.isnan(diag.max_abs_student_resid)
    result = criticize(table, factors, "y", n_null=199)
    assert result.to_frame().empty
    assert result.to_json()["baseline"]["lof_f"] is None  # undefined, not infinite
    # the verdict says why nothing was tested, not that there were too few runs
    assert result.verdict == "adequate" and "goes through every run to round-off" in result.verdict_detail["message"]
    assert "too few spare runs" not in result.verdict_detail["message"]


@pytest.mark.parametrize("k,value", [(2, 30.0), (3, 0.125)])
def test_a_response_that_never_changes_is_said_to_identify_nothing(k, value):
    table = _exact_table(k, 7, 1.0)
    table["y"] = value
    result = criticize(table, [f"x{i + 1}" for i in range(k)], "y", n_null=199)
    assert result.to_frame().empty and result.verdict == "adequate"
    message = result.verdict_detail["message"]
    assert f"the same value ({value:g}) in every run" in message and "cannot identify any of them" in message


@pytest.mark.parametrize("seed", [5, 6])
def test_a_real_defect_on_an_otherwise_exact_surface_is_still_found(seed):
    """The floor is scale-aware, not a blanket silence: one run off an exact surface is named."""
    table = _exact_table(2, seed, 10.0)
    spread = float(np.ptp(table["y"]))
    table.loc[table["run"] == 3, "y"] += 0.05 * spread
    result = criticize(table, ["x1", "x2"], "y", n_null=199)
    frame = result.to_frame()
    assert not frame.empty
    assert frame.iloc[0]["cause"] == "outlier" and int(frame.iloc[0]["detail"]) == 3


def test_noisy_replicates_keep_their_lack_of_fit_test():
    table = _exact_table(2, 7, 1.0)
    rng = np.random.default_rng(7)
    table["y"] += 0.01 * np.ptp(table["y"]) * rng.standard_normal(len(table))
    st = fit_response(table, ["x1", "x2"], "y", alpha=2 ** 0.5).statistics()
    assert np.isfinite(st.lof_f) and 0 <= st.lof_p <= 1
    note = fit_response(table, ["x1", "x2"], "y", alpha=2 ** 0.5).anova().lof_note
    assert note == ""


def _printed(values, digits):
    """Each value as a table prints it: to ``digits`` significant digits."""
    return np.array([float(f"{v:.{digits}g}") for v in values])


@pytest.mark.parametrize("digits", [4, 6, 8])
@pytest.mark.parametrize("k,seed,scale", [(2, 11, 1.0), (3, 12, 40.0)])
def test_an_exact_quadratic_printed_to_a_few_digits_gives_no_findings(k, seed, scale, digits):
    """A deterministic simulator's exact quadratic, printed to 4-8 significant digits: the residuals are the
    printing's rounding.  They were read as lack of fit (F 3e291 over zero pure error), 'unexplained' or an
    'outlier' whose observed and predicted values printed alike."""
    table = _exact_table(k, seed, scale)
    table["y"] = _printed(table["y"], digits)
    factors = [f"x{i + 1}" for i in range(k)]
    result = criticize(table, factors, "y", n_null=199)
    assert result.to_frame().empty, result.to_frame()
    assert result.verdict == "adequate" and "the precision the values are printed to" in result.verdict_detail["message"]
    assert np.isnan(fit_response(table, factors, "y", alpha=(2 ** k) ** 0.25).statistics().lof_f)


@pytest.mark.parametrize("digits", [6, 8])
def test_a_defect_far_above_the_printed_precision_is_still_found(digits):
    """The printed-precision floor silences rounding, not a defect: a cubic term 1000 times the last printed
    digit on a noise-free quadratic is found, and lack of fit's undefined F does not hide it."""
    table = _exact_table(2, 13, 1.0)
    x1 = table["x1"].to_numpy()
    quantum = 10.0 ** (np.floor(np.log10(np.abs(table["y"]).max())) - digits + 1)
    bump = ((x1 - x1.mean()) / np.ptp(x1)) ** 3
    table["y"] = _printed(table["y"] + 1000 * quantum * bump / np.abs(bump).max(), digits)
    result = criticize(table, ["x1", "x2"], "y", n_null=199)
    assert result.verdict != "adequate", result.verdict_detail["message"]


def test_printed_precision_does_not_mask_real_misfit():
    """Two tables where the misfit is of the order of the last printed digit: replicates 0.045 apart on values
    printed to 0.1 are real pure error (lack of fit F 354 by statsmodels' cell-means comparison), and a cubic
    term that leaves axial residuals of +-1 on whole numbers is a defect.  A floor at half the last digit
    hid both."""
    import statsmodels.formula.api as smf
    from statsmodels.stats.anova import anova_lm

    p = ccd_points(2, 1.41421, 5)
    y = np.round(10 + 2 * p[:, 0] + 1.5 * p[:, 1] + p[:, 0] ** 3, 1)
    y[-5:] = [10.1, 10.1, 10.1, 10.1, 10.2]
    table = pd.DataFrame({"run": range(1, 14), "A": 10 + 5 * p[:, 0], "B": 10 + 5 * p[:, 1], "y": y})
    fit = fit_response(table, ["A", "B"], "y", alpha=1.41421)
    table["cell"] = table["A"].round(6).astype(str) + "_" + table["B"].round(6).astype(str)
    ref = anova_lm(smf.ols("y ~ A + B + A:B + I(A**2) + I(B**2)", table).fit(), smf.ols("y ~ C(cell)", table).fit())
    assert fit.statistics().lof_f == pytest.approx(ref["F"].iloc[1], rel=1e-6) and fit.anova().lof_note == ""

    p = ccd_points(3, 1.68179, 6)
    y = np.round(100 + 20 * p[:, 0] + 15 * p[:, 1] - 8 * p[:, 2] + 5 * p[:, 0] ** 2 + 0.7 * p[:, 0] ** 3)
    table = pd.DataFrame({"run": range(1, 21), "A": 10 + 5 * p[:, 0], "B": 10 + 5 * p[:, 1], "C": 10 + 5 * p[:, 2],
                          "y": y})
    assert criticize(table, ["A", "B", "C"], "y", n_null=199).verdict != "adequate"


@pytest.mark.parametrize("values, quantum", [
    ([12.3, 10.0, 11.1], [0.1, 0.1, 0.1]),  # fixed decimals: 10.0 lost its zero
    ([-1228.0, 87.4, 29.18], [1, 0.01, 0.01]),  # four significant digits: 87.40 lost its zero
    ([5141.0, 22440.0, -789.4, 531.6], [1, 10, 0.1, 0.1]),
    ([1200.0, 1187.0, 1213.0], [1, 1, 1]),  # whole numbers: units, whatever their trailing zeros
    ([0.123, 5.5, 12.0], [0.001] * 3),
    ([1 / 3, 2.0], None),  # a value with every digit: nothing was rounded for print
])
def test_the_printed_place_of_each_value(values, quantum):
    from demid.precision import printed_quantum

    found = printed_quantum(values)
    if quantum is None:
        assert np.all(found <= 1e-11)
    else:
        assert found == pytest.approx(quantum)

"""Known answers for the fit statistics, the linear algebra of criticism and the agreement rule of
printed values: statsmodels itself, textbook leverages, and exact decimal arithmetic."""

from __future__ import annotations

import warnings

import numpy as np
import pandas as pd
import pytest
import statsmodels.api as sm
import statsmodels.formula.api as smf
from statsmodels.stats.anova import anova_lm
from statsmodels.stats.outliers_influence import OLSInfluence

from demid.criticism.models import leverages, orthonormal_basis
from demid.surrogate import fit_response
from demid.transcription import parse_printed

# Montgomery, Design and Analysis of Experiments, Example 11.2 (13-run CCD, 5 centre runs: rows 4-8)
MONTGOMERY = pd.DataFrame({
    "run": range(1, 14),
    "x1": [-1, -1, 1, 1, 0, 0, 0, 0, 0, 1.414, -1.414, 0, 0],
    "x2": [-1, 1, -1, 1, 0, 0, 0, 0, 0, 0, 0, 1.414, -1.414],
    "y": [76.5, 77.0, 78.0, 79.5, 79.9, 80.3, 80.0, 79.7, 79.8, 78.4, 75.6, 78.5, 77.0],
})
CENTRE = slice(4, 9)


def _with_centre(deviations) -> pd.DataFrame:
    table = MONTGOMERY.copy()
    table.loc[table.index[CENTRE], "y"] = 79.9 + np.asarray(deviations, dtype=float)
    return table


# --------------------------------------------------------------------------- lack of fit
def test_lack_of_fit_is_tested_against_a_tiny_but_real_pure_error():
    """Centre replicates 1e-4 apart (a millionth of the response) are real scatter, not round-off:
    the lack-of-fit F and p are statsmodels' (quadratic vs cell-means model)."""
    table = _with_centre([0.0, 1e-4, -1e-4, 2e-4, -2e-4])
    fit = fit_response(table, ["x1", "x2"], "y", alpha=1.414)
    df = table.copy()
    df["cell"] = df["x1"].astype(str) + "_" + df["x2"].astype(str)
    quad = smf.ols("y ~ x1 + x2 + x1:x2 + I(x1**2) + I(x2**2)", df).fit()
    ref = anova_lm(quad, smf.ols("y ~ C(cell)", df).fit())
    st = fit.statistics()
    assert st.lof_f == pytest.approx(ref["F"].iloc[1], rel=1e-6)
    assert st.lof_p == pytest.approx(ref["Pr(>F)"].iloc[1], rel=1e-6, abs=1e-300)
    assert fit.anova().lof_note == ""


def test_replicates_equal_to_working_precision_have_no_pure_error():
    """Centre replicates that differ in the 11th significant digit are identical to working precision
    (below 1e-9 of the response): lack of fit has no F-ratio, and the note says why."""
    fit = fit_response(_with_centre([0.0, 1e-9, -1e-9, 0.0, 0.0]), ["x1", "x2"], "y", alpha=1.414)
    anova = fit.anova()
    assert np.isnan(fit.statistics().lof_f)
    assert "pure error is zero" in anova.lof_note


# --------------------------------------------------------------------------- influence
def _fit_with_exactly_fitted_runs():
    """Without three of the axial runs, the four factorial runs and the remaining axial run have
    leverage 1.  Returns demid's fit and statsmodels' influence statistics of the same model (read
    inside the warning guard: 0/0 at those runs)."""
    table = MONTGOMERY.drop(index=[9, 10, 11])
    fit = fit_response(table, ["x1", "x2"], "y", alpha=1.414)
    x1, x2 = table["x1"].to_numpy(float), table["x2"].to_numpy(float)
    exog = np.column_stack([np.ones(len(table)), x1, x2, x1 * x2, x1 ** 2, x2 ** 2])
    with warnings.catch_warnings(), np.errstate(all="ignore"):
        warnings.simplefilter("ignore")
        influence = OLSInfluence(sm.OLS(table["y"].to_numpy(float), exog).fit())
        reference = {"leverage": influence.hat_matrix_diag, "student": influence.resid_studentized_external,
                     "cooks": influence.cooks_distance[0], "resid": influence.resid}
    return fit, reference


def test_largest_studentised_residual_skips_runs_the_model_fits_exactly():
    """Leverage-1 runs have a studentised residual of 0/0; the largest of the others is statsmodels'."""
    fit, reference = _fit_with_exactly_fitted_runs()
    leverage, student = reference["leverage"], reference["student"]
    assert np.sum(leverage > 1 - 1e-9) == 5
    expected = np.max(np.abs(student[leverage < 1 - 1e-9]))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        got = fit.diagnostics().max_abs_student_resid
    assert got == pytest.approx(expected, rel=1e-9)


def test_runs_fitted_exactly_have_no_influence_statistics():
    """A run of leverage 1 is reproduced whatever its value: its leave-one-out residual and Cook's
    distance are undefined (NaN), not round-off divided by round-off; other runs keep statsmodels'."""
    fit, reference = _fit_with_exactly_fitted_runs()
    leverage, cooks, resid = reference["leverage"], reference["cooks"], reference["resid"]
    with warnings.catch_warnings(), np.errstate(all="ignore"):
        warnings.simplefilter("ignore")
        influence = fit.influence()
        max_cooks = fit.diagnostics().max_cooks_d
    exact = leverage > 1 - 1e-9
    assert exact.sum() == 5
    assert influence.loc[exact, ["loo_residual", "cooks_d", "student_resid"]].isna().all().all()
    np.testing.assert_allclose(influence.loc[~exact, "cooks_d"], cooks[~exact], rtol=1e-9)
    np.testing.assert_allclose(influence.loc[~exact, "loo_residual"], resid[~exact] / (1 - leverage[~exact]),
                               rtol=1e-9)
    assert max_cooks == pytest.approx(np.max(cooks[~exact]), rel=1e-9)


# --------------------------------------------------------------------------- linear algebra of criticism
def test_leverage_of_a_single_regressor():
    """One column x: h_i = x_i^2 / sum x^2 (textbook); a rank-1 matrix spans one direction."""
    x = np.array([[1.0], [2.0], [2.0], [4.0]])
    np.testing.assert_allclose(leverages(x), np.array([1.0, 4.0, 4.0, 16.0]) / 25.0, rtol=1e-12)
    rank_one = np.column_stack([x[:, 0], 3.0 * x[:, 0]])
    q = orthonormal_basis(rank_one)
    assert q.shape == (4, 1)
    np.testing.assert_allclose(np.abs(q[:, 0]), x[:, 0] / 5.0, rtol=1e-12)


# --------------------------------------------------------------------------- printed bounds
def test_printed_bounds_admit_their_own_value_up_to_round_off():
    """0.1 + 0.2 and 0.7 - 0.4 are 0.3 in exact arithmetic (floating point: 0.30000000000000004 and
    0.29999999999999993), so they satisfy '<= 0.3' and '>= 0.3'; a real excess of 1e-6 does not."""
    at_most, at_least = parse_printed("<=0.3"), parse_printed(">=0.3")
    assert at_most.agrees(0.1 + 0.2) and at_least.agrees(0.7 - 0.4)
    assert not at_most.agrees(0.300001) and not at_least.agrees(0.299999)

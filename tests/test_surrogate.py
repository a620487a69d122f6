"""Surrogate fits against known values: exact recovery, Montgomery Example 11.2, statsmodels itself."""

import numpy as np
import pandas as pd
import pytest
import statsmodels.api as sm
import statsmodels.formula.api as smf
from statsmodels.stats.anova import anova_lm

from demid.design import quadratic_terms
from demid.surrogate import coding_from_frame, fit_response, surrogates_from_frame, surrogates_to_frame

from .helpers import make_ccd_table

# Montgomery, Design and Analysis of Experiments, Example 11.2 (chemical process yield, 13-run CCD)
MONTGOMERY = pd.DataFrame({
    "run": range(1, 14),
    "x1": [-1, -1, 1, 1, 0, 0, 0, 0, 0, 1.414, -1.414, 0, 0],
    "x2": [-1, 1, -1, 1, 0, 0, 0, 0, 0, 0, 0, 1.414, -1.414],
    "y": [76.5, 77.0, 78.0, 79.5, 79.9, 80.3, 80.0, 79.7, 79.8, 78.4, 75.6, 78.5, 77.0],
})


def test_noise_free_quadratic_recovered_exactly():
    beta = {"Intercept": 3.0, "x1": -2.0, "x2": 0.5, "x1:x2": 1.25, "x1^2": 4.0, "x2^2": -0.75}

    def resp(x):
        a, b = x[:, 0], x[:, 1]
        return {"y": beta["Intercept"] + beta["x1"] * a + beta["x2"] * b + beta["x1:x2"] * a * b
                + beta["x1^2"] * a**2 + beta["x2^2"] * b**2}

    table = make_ccd_table(resp, [0.1, 2.0], [0.9, 12.0])
    fit = fit_response(table, ["x1", "x2"], "y", alpha=1.41421)
    coef = fit.coefficients().set_index("term")["coefficient_actual"]
    for term, value in beta.items():
        assert coef[term] == pytest.approx(value, abs=1e-8)
    st = fit.statistics()
    assert st.r2 == pytest.approx(1.0) and st.rmse == pytest.approx(0.0, abs=1e-9)


def test_montgomery_example_11_2_anova():
    fit = fit_response(MONTGOMERY, ["x1", "x2"], "y", alpha=1.414)
    an = fit.anova()
    # Printed values (Design-Expert output in the textbook), to the printed decimals.
    assert round(an.ss_model, 2) == 28.25
    assert round(an.ss_residual, 2) == 0.50
    assert round(an.ss_lof, 2) == 0.28 and an.df_lof == 3
    assert round(an.ss_pure_error, 2) == 0.21 and an.df_pure_error == 4
    assert round(an.ss_total, 2) == 28.74 or round(an.ss_total, 2) == 28.75
    st = fit.statistics()
    assert round(st.r2, 4) == 0.9827 and round(st.adj_r2, 4) == 0.9704
    coef = fit.coefficients().set_index("term")["coefficient_coded"]
    assert coef["Intercept"] == pytest.approx(79.94, abs=0.005)
    assert coef["x1"] == pytest.approx(0.995, abs=0.0005)
    assert coef["x1^2"] == pytest.approx(-1.376, abs=0.0005)
    assert coef["x2^2"] == pytest.approx(-1.001, abs=0.0005)


def test_lack_of_fit_matches_statsmodels_anova_lm():
    """Lack of fit = quadratic model vs the saturated cell-means model, as statsmodels computes it."""
    df = MONTGOMERY.copy()
    df["cell"] = df["x1"].astype(str) + "_" + df["x2"].astype(str)
    quad = smf.ols("y ~ x1 + x2 + x1:x2 + I(x1**2) + I(x2**2)", df).fit()
    full = smf.ols("y ~ C(cell)", df).fit()
    ref = anova_lm(quad, full)
    fit = fit_response(MONTGOMERY, ["x1", "x2"], "y", alpha=1.414)
    st = fit.statistics()
    assert st.lof_f == pytest.approx(ref["F"].iloc[1], rel=1e-10)
    assert st.lof_p == pytest.approx(ref["Pr(>F)"].iloc[1], rel=1e-10)


def test_statistics_definitions_against_statsmodels():
    rng = np.random.default_rng(7)
    table = make_ccd_table(lambda x: {"y": 5 + x[:, 0] ** 2 + 3 * x[:, 1]}, [0, 0, 0], [1, 1, 1],
                           alpha=1.68179, center_runs=6, noise=0.2, seed=int(rng.integers(1000)))
    fit = fit_response(table, ["x1", "x2", "x3"], "y", alpha=1.68179)
    res = fit.results
    n, p = len(table), len(quadratic_terms(3))
    st = fit.statistics()
    assert st.r2 == pytest.approx(res.rsquared) and st.adj_r2 == pytest.approx(res.rsquared_adj)
    assert st.rmse == pytest.approx(np.sqrt(res.ssr / n))
    assert st.resid_std == pytest.approx(np.sqrt(res.scale))
    infl = res.get_influence()
    loo = infl.resid_press
    assert st.press == pytest.approx(np.sum(loo**2))
    assert st.q2 == pytest.approx(1 - np.sum(loo**2) / res.centered_tss)
    assert fit.influence()["cooks_d"].to_numpy() == pytest.approx(infl.cooks_distance[0])
    assert p == 10


def test_surrogate_round_trip_predicts_and_matches_statsmodels_se():
    table = make_ccd_table(lambda x: {"y": 1 + x[:, 0] - x[:, 1] ** 2}, [0.1, 1.0], [0.9, 5.0], noise=0.1, seed=2)
    fit = fit_response(table, ["x1", "x2"], "y", alpha=1.41421)
    frame = surrogates_to_frame([fit])
    sur = surrogates_from_frame(frame, ["x1", "x2"])["y"]
    assert coding_from_frame(frame, ["x1", "x2"]) == fit.coding  # stored exactly, read back, never re-inferred
    pts = np.array([[0.3, 2.0], [0.7, 4.5], [0.5, 3.0]])
    coded = fit.coding.to_coded(pts)
    from demid.design import model_matrix
    frame = fit.results.get_prediction(model_matrix(coded, fit.terms)).summary_frame(alpha=0.05)
    assert sur.predict(pts) == pytest.approx(frame["mean"].to_numpy(), rel=1e-9)
    assert sur.se_mean(pts) == pytest.approx(frame["mean_se"].to_numpy(), rel=1e-6)
    obs_se = np.sqrt(frame["mean_se"].to_numpy() ** 2 + fit.results.scale)  # statsmodels' se_obs
    assert sur.se_prediction(pts) == pytest.approx(obs_se, rel=1e-6)
    assert sur.resid_df == 13 - 6 and sur.resid_var == pytest.approx(fit.results.scale, rel=1e-12)


def test_runs_are_numbered_from_one_without_a_run_column():
    table = make_ccd_table(lambda x: {"y": 1 + x[:, 0]}, [0, 0], [1, 1], noise=0.1).drop(columns="run")
    table.loc[2, "y"] = np.nan
    fit = fit_response(table, ["x1", "x2"], "y", alpha=1.41421)
    assert fit.runs.tolist() == list(range(1, 13))


def test_failed_runs_are_dropped_from_that_response_only():
    table = make_ccd_table(lambda x: {"y": x[:, 0] + x[:, 1] ** 2, "z": x[:, 0]}, [0, 0], [1, 1], noise=0.05)
    table.loc[table["run"] == 4, "y"] = np.nan
    fit_y = fit_response(table, ["x1", "x2"], "y", alpha=1.41421)
    fit_z = fit_response(table, ["x1", "x2"], "z", alpha=1.41421)
    assert fit_y.n_runs == 12 and fit_z.n_runs == 13
    assert 4 not in fit_y.runs.tolist() and 4 in fit_z.runs.tolist()
    # the same coefficients as statsmodels on the other runs (quadratic in the actual factors: the
    # coding is affine, so the fitted values agree whatever coding is used)
    x = table[["x1", "x2"]].to_numpy()
    exog = np.column_stack([np.ones(len(x)), x[:, 0], x[:, 1], x[:, 0] * x[:, 1], x[:, 0] ** 2, x[:, 1] ** 2])
    ok = table["run"].to_numpy() != 4
    ref_y = sm.OLS(table["y"].to_numpy()[ok], exog[ok]).fit()
    ref_z = sm.OLS(table["z"].to_numpy(), exog).fit()
    assert fit_y.results.fittedvalues.to_numpy() == pytest.approx(ref_y.fittedvalues, rel=1e-9)
    assert fit_y.statistics().resid_std == pytest.approx(np.sqrt(ref_y.scale), rel=1e-9)
    assert fit_z.results.fittedvalues.to_numpy() == pytest.approx(ref_z.fittedvalues, rel=1e-9)
    assert fit_y.surrogate().coefficients == pytest.approx(ref_y.params, rel=1e-6, abs=1e-9)


@pytest.mark.parametrize("n_runs", [150, 450])
def test_influence_of_a_large_table_matches_statsmodels(n_runs):
    """Above LOO_REFIT_MAX_RUNS runs the studentised residuals come from the leave-one-out identity instead of
    statsmodels' refit without each run: the same numbers, to round-off (below it, statsmodels' own)."""
    from demid.surrogate import LOO_REFIT_MAX_RUNS

    rng = np.random.default_rng(n_runs)
    x = rng.uniform(-1, 1, (n_runs, 2))
    y = 5 + x[:, 0] - 2 * x[:, 1] + 0.5 * x[:, 0] ** 3 + 0.1 * rng.standard_normal(n_runs)
    y[7] += 1.5  # one run far off: a large studentised residual
    table = pd.DataFrame({"run": np.arange(1, n_runs + 1), "a": x[:, 0], "b": x[:, 1], "y": y})
    fit = fit_response(table, ["a", "b"], "y")
    reference = fit.results.get_influence().summary_frame()
    frame = fit.influence()
    assert (n_runs > LOO_REFIT_MAX_RUNS) == (n_runs == 450)
    np.testing.assert_allclose(frame["student_resid"], reference["student_resid"], rtol=1e-10)
    np.testing.assert_allclose(frame["leverage"], reference["hat_diag"], rtol=1e-12)
    np.testing.assert_allclose(frame["cooks_d"], reference["cooks_d"], rtol=1e-10)
    assert frame["student_resid"].abs().idxmax() == 7

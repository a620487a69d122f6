"""The catalogue's reported statistics and nominal p-values (``criticize(...).catalogue``) against the textbook
tests written here with numpy, scipy and statsmodels: the added-variable F of a missing cubic term, of the run
number (drift) and of a step in run order (largest over the change-points, Bonferroni over them), the
externally studentised residual of the worst run (Bonferroni over 2n tails), and the F scale of the
unequal-scatter likelihood ratio."""

from __future__ import annotations

import numpy as np
import pytest
import statsmodels.api as sm
from scipy import stats

from demid.criticism import criticize

from ..generators import FACTORS, ccd_table


def _quadratic(table):
    a, b = (table[f].to_numpy(dtype=float) for f in FACTORS[2])
    return np.column_stack([np.ones(len(a)), a, b, a * a, a * b, b * b])  # the quadratic in actual units


def _sse(design, y) -> float:
    return float(np.sum((y - design @ np.linalg.lstsq(design, y, rcond=None)[0]) ** 2))


def _added_f(base, column, y) -> float:
    """F of adding one column to the model: (SSE0 - SSE1) / (SSE1 / (n - p - 1))."""
    sse0, sse1 = _sse(base, y), _sse(np.column_stack([base, column]), y)
    return (sse0 - sse1) / (sse1 / (len(y) - base.shape[1] - 1))


@pytest.fixture(scope="module", params=[0, 3])
def case(request):
    table, _ = ccd_table(request.param, 2, "term", 6.0)
    result = criticize(table, FACTORS[2], "y", n_null=199)
    entries = {}
    for e in result.catalogue:
        entries.setdefault(e["cause"], []).append(e)
    return table, entries


def test_missing_cubic_terms_are_the_added_variable_f_tests(case):
    table, entries = case
    y, base = table["y"].to_numpy(dtype=float), _quadratic(table)
    df = len(y) - base.shape[1]
    a, b = (table[f].to_numpy(dtype=float) for f in FACTORS[2])
    cubes = {"mu_r^3": a ** 3, "gamma^3": b ** 3}
    seen = set()
    for e in entries["missing_term"]:
        f = _added_f(base, cubes[e["detail"]], y)
        assert e["statistic"] == pytest.approx(f, rel=1e-7)
        assert e["p_nominal"] == pytest.approx(stats.f.sf(f, 1, df - 1), rel=1e-6)
        seen.add(e["detail"])
    assert seen == set(cubes)


def test_drift_and_step_are_added_variable_f_tests_in_run_order(case):
    table, entries = case
    y, base = table["y"].to_numpy(dtype=float), _quadratic(table)
    df = len(y) - base.shape[1]
    runs = table["run"].to_numpy(dtype=float)
    (drift,) = entries["drift"]
    f = _added_f(base, runs, y)
    assert drift["statistic"] == pytest.approx(f, rel=1e-7)
    assert drift["p_nominal"] == pytest.approx(stats.f.sf(f, 1, df - 1), rel=1e-6)
    # a step: 1 from the c-th run in run order on, at least two runs on each side
    order = np.argsort(runs, kind="stable")
    points = range(2, len(y) - 1)
    fs = {int(order[c]): _added_f(base, (runs >= runs[order[c]]).astype(float), y) for c in points}
    (step,) = entries["step"]
    best = max(fs, key=fs.get)
    assert step["detail"] == int(runs[best])  # named by its run number
    assert step["statistic"] == pytest.approx(fs[best], rel=1e-7)
    assert step["p_nominal"] == pytest.approx(min(1.0, len(fs) * stats.f.sf(fs[best], 1, df - 1)), rel=1e-6)


def test_the_outlier_is_the_largest_externally_studentised_residual(case):
    table, entries = case
    y = table["y"].to_numpy(dtype=float)
    fit = sm.OLS(y, _quadratic(table)).fit()
    t = fit.get_influence().resid_studentized_external
    worst = int(np.argmax(np.abs(t)))
    (outlier,) = entries["outlier"]
    assert outlier["detail"] == int(table["run"].iloc[worst])
    assert abs(outlier["statistic"]) == pytest.approx(abs(t[worst]), rel=1e-7)
    p = 2 * len(y) * stats.t.sf(abs(t[worst]), fit.df_resid - 1)
    assert outlier["p_nominal"] == pytest.approx(min(1.0, p), rel=1e-6)


def test_unequal_scatter_p_is_the_f_scale_of_its_likelihood_ratio(case):
    """(df - 1)(exp(LR / n) - 1) ~ F(1, df - 1), with df the quadratic's residual degrees of freedom."""
    table, entries = case
    n = len(table)
    df = n - 6
    assert {e["detail"] for e in entries["heteroscedasticity"]} == {*FACTORS[2], "fitted"}
    for e in entries["heteroscedasticity"]:
        assert e["statistic"] > 0
        assert e["p_nominal"] == pytest.approx(stats.f.sf((df - 1) * np.expm1(e["statistic"] / n), 1, df - 1),
                                               rel=1e-9)


def test_a_step_on_a_weighted_model_is_the_weighted_least_squares_f_test():
    """Once unequal scatter is modelled (weights exp(-gamma v)), the step in run order is tested on the weighted
    fit: its statistic is the largest weighted-least-squares F (statsmodels' WLS, refitted with the step column)
    over the change-points."""
    from demid.criticism.catalogue import Round
    from demid.criticism.level1 import prepare_data
    from demid.criticism.models import Model, ModelForm

    table, _ = ccd_table(1, 2, "term", 6.0)
    table = table.assign(y=table["y"] + np.where(table["run"] >= 8, 4.0, 0.0))
    data, _ = prepare_data(table, FACTORS[2], "y", None, ())
    v = data.coded[:, 0]
    spec = ModelForm(weight_on=FACTORS[2][0], weight_gamma=1.5, weight_values=tuple(v))
    model = Model(data, spec)
    (step,) = [h for h in Round(data, model, 99, np.random.default_rng(0)).hypotheses if h.cause == "step"]
    w = np.exp(-1.5 * v)
    y, base = table["y"].to_numpy(dtype=float), _quadratic(table)
    df = len(y) - base.shape[1]
    sse0 = float(sm.WLS(y, base, weights=w).fit().ssr)
    runs = table["run"].to_numpy(dtype=float)
    fs = {}
    for c in range(2, len(y) - 1):
        after = (runs >= np.sort(runs)[c]).astype(float)
        sse1 = float(sm.WLS(y, np.column_stack([base, after]), weights=w).fit().ssr)
        fs[int(np.flatnonzero(runs == np.sort(runs)[c])[0])] = (sse0 - sse1) / (sse1 / (df - 1))
    best = max(fs, key=fs.get)
    assert step.detail == best
    assert step.statistic == pytest.approx(fs[best], rel=1e-7)
    assert step.logp == pytest.approx(min(0.0, np.log(len(fs)) + stats.f.logsf(fs[best], 1, df - 1)), rel=1e-7)
    # its joint null: the same F for whitened standard normal errors (the round's first 99 draws), largest over
    # the change-points, on the same Bonferroni scale
    eps = np.random.default_rng(0).standard_normal((len(y), 99))
    sw = np.sqrt(w)[:, None]

    def whitened_sse(design):
        xw = design * sw
        return np.sum((eps - xw @ np.linalg.lstsq(xw, eps, rcond=None)[0]) ** 2, axis=0)

    null0 = whitened_sse(base)
    null_f = np.max([(null0 - whitened_sse(np.column_stack([base, (runs >= r).astype(float)])))
                     / (whitened_sse(np.column_stack([base, (runs >= r).astype(float)])) / (df - 1))
                     for r in np.sort(runs)[2:len(y) - 1]], axis=0)
    expected = np.minimum(0.0, np.log(len(fs)) + stats.f.logsf(null_f, 1, df - 1))
    np.testing.assert_allclose(step.null_logp, expected, rtol=1e-6, atol=1e-9)


def test_the_joint_null_of_missing_terms_and_drift_is_their_f_for_standard_normal_errors():
    """The family p-values rest on each test's statistic for simulated errors: for a missing term and for drift
    the same added-variable F as observed, computed for the round's 99 standard normal draws (numpy here)."""
    from demid.criticism.catalogue import Round
    from demid.criticism.level1 import prepare_data
    from demid.criticism.models import Model, ModelForm

    table, _ = ccd_table(0, 2, "term", 6.0)
    data, _ = prepare_data(table, FACTORS[2], "y", None, ())
    hypotheses = Round(data, Model(data, ModelForm()), 99, np.random.default_rng(0)).hypotheses
    base = _quadratic(table)
    n, df = len(table), len(table) - base.shape[1]
    eps = np.random.default_rng(0).standard_normal((n, 99))

    def null_logp(column):
        def sse(design):
            return np.sum((eps - design @ np.linalg.lstsq(design, eps, rcond=None)[0]) ** 2, axis=0)
        sse0, sse1 = sse(base), sse(np.column_stack([base, column]))
        return stats.f.logsf((sse0 - sse1) / (sse1 / (df - 1)), 1, df - 1)

    a, b = (table[f].to_numpy(dtype=float) for f in FACTORS[2])
    columns = {("missing_term", "mu_r^3"): a ** 3, ("missing_term", "gamma^3"): b ** 3,
               ("drift", "run"): table["run"].to_numpy(dtype=float)}
    checked = 0
    for h in hypotheses:
        key = (h.cause, h.aliases[0] if h.cause == "missing_term" else h.detail)
        if key in columns:
            np.testing.assert_allclose(h.null_logp, null_logp(columns[key]), rtol=1e-6, atol=1e-9)
            checked += 1
    assert checked == 3

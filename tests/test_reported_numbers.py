"""Known answers for numbers the report prints (not only for the decisions made from them).

Each reference is computed here from its definition with statsmodels/scipy, independently of the
code under test.
"""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
import statsmodels.api as sm
from scipy import optimize, special, stats

from demid.criticism import criticize

from .generators import FACTORS, ccd_table
from .criticism.test_criticism import quadratic_ols

GRID_STEP = 0.01  # the lambda grid the interval is read on


@pytest.mark.parametrize("seed, size", [(13, 3.0), (4, 2.5), (21, 3.0)])
def test_box_cox_lambda_and_its_interval(seed, size):
    """λ̂ maximises the profile likelihood; the 95 % interval is where the likelihood ratio in F form,
    df·(exp(LR/n) − 1), stays below F(0.95; 1, df), df = n − p − 1 (p: the quadratic's terms)."""
    table, _ = ccd_table(seed, 2, "log", size)
    finding = next(f for f in criticize(table, FACTORS[2], "y").findings if f.cause == "response_transform")
    y = table["y"].to_numpy(float)
    x = quadratic_ols(table, FACTORS[2]).model.exog
    n, df = len(y), len(y) - x.shape[1] - 1

    def profile(lam):
        return -0.5 * n * np.log(sm.OLS(special.boxcox(y, lam), x).fit().ssr / n) + (lam - 1) * np.log(y).sum()

    best = optimize.minimize_scalar(lambda v: -profile(v), bounds=(-3, 3), method="bounded",
                                    options={"xatol": 1e-6})
    lam_hat, top = best.x, -best.fun
    crit = stats.f.ppf(0.95, 1, df)

    def excess(lam):
        return df * np.expm1(2 * (top - profile(lam)) / n) - crit

    lo = optimize.brentq(excess, -3, lam_hat)
    hi = optimize.brentq(excess, lam_hat, 3)
    assert finding.info["lambda_hat"] == pytest.approx(lam_hat, abs=GRID_STEP)
    reported_lo, reported_hi = finding.info["lambda_ci"]
    # the grid's inside points: the reported ends lie within one step inside the exact ends
    assert lo - 1e-9 <= reported_lo <= lo + GRID_STEP + 1e-9
    assert hi - GRID_STEP - 1e-9 <= reported_hi <= hi + 1e-9


# --------------------------------------------------------------------------- closest approach of an empty set
def _linear_in_a(name: str, slope: float = 1.0, offset: float = 0.0):
    from demid.design import quadratic_terms
    from demid.surrogate import Surrogate

    coef = np.array([offset, slope, 0.0, 0.0, 0.0, 0.0])  # Intercept, a, b, a:b, a^2, b^2
    return Surrogate(name, ["a", "b"], quadratic_terms(2), coef, np.zeros((6, 6)), 0.0, 7)


@pytest.mark.parametrize("upper, best_a, best_error", [
    (3.0, 4.0 / 3.0, 1.0 / 3.0),   # interior: (a - 1)/1 = (2 - a)/2
    (1.2, 1.2, 0.4),               # cut by the bound: |1.2 - 2|/2
])
def test_closest_approach_of_an_empty_set(upper, best_a, best_error):
    """y1 = y2 = a with targets 1 and 2 cannot both be met within 10 %: the largest relative error is
    smallest where the two errors are equal, max(|a − 1|/1, |a − 2|/2), or at the bound."""
    from demid.sampling import Domain
    from demid.sampling.evaluate import evaluate_set

    surrogates = {"y1": _linear_in_a("y1"), "y2": _linear_in_a("y2")}
    domain = Domain(("a", "b"), (0.0, 0.0), (upper, 1.0), (False, False))
    aset = evaluate_set(surrogates, domain, ("y1", "y2"), {"y1": 1.0, "y2": 2.0}, 0.1, 101)
    assert aset.fraction == 0
    assert aset.best_error == pytest.approx(best_error, abs=1e-7)
    assert aset.best_point[0] == pytest.approx(best_a, abs=1e-6)


# --------------------------------------------------------------------------- the exact fraction's error estimate
@pytest.mark.parametrize("target, tolerance", [(0.04, 0.5), (0.09, 0.2), (0.01, 0.9)])
def test_exact_fraction_error_bounds_the_annulus_area(target, tolerance):
    """y = (a − ½)² + (b − ½)² within ε of t is an annulus of area π·t·2ε (inside the unit square):
    the reported fraction is that area to within its reported error, and the error is small."""
    from demid.design import quadratic_terms
    from demid.sampling import Domain
    from demid.sampling.evaluate import evaluate_set
    from demid.surrogate import Surrogate

    coef = np.array([0.5, -1.0, -1.0, 0.0, 1.0, 1.0])  # Intercept, a, b, a:b, a^2, b^2
    sur = Surrogate("y", ["a", "b"], quadratic_terms(2), coef, np.zeros((6, 6)), 0.0, 7)
    domain = Domain(("a", "b"), (0.0, 0.0), (1.0, 1.0), (False, False))
    aset = evaluate_set({"y": sur}, domain, ("y",), {"y": target}, tolerance, 101)
    area = np.pi * target * 2 * tolerance
    assert 0 <= aset.fraction_error <= 1e-6
    assert abs(aset.fraction - area) <= aset.fraction_error + 1e-12
    radius = np.sqrt(target * (1 + tolerance))
    np.testing.assert_allclose(aset.lower, [0.5 - radius] * 2, atol=1e-9)
    np.testing.assert_allclose(aset.upper, [0.5 + radius] * 2, atol=1e-9)


def _table_with_run_5_slipped(tmp_path, seed: int, noise: float):
    """A two-factor CCD table (responses to 2 decimals) whose run 5 response is printed a tenth of its value: the
    file and its validated material."""
    from demid.data import validate_material

    from .helpers import make_ccd_table
    from .transcription.test_likely_typos import _cfg

    table = make_ccd_table(lambda x: {"y": 100 + 20 * x[:, 0] - 3 * x[:, 1] + 8 * x[:, 0] ** 2},
                           [0.1, 1], [0.9, 11], noise=noise, seed=seed, decimals=2)
    true_value = table.loc[table["run"] == 5, "y"].iloc[0]
    path = tmp_path / "t.csv"
    table.to_csv(path, index=False)
    lines = [ln if not ln.startswith("5,") else ",".join(ln.split(",")[:-1] + [f"{true_value / 10:.3f}"])
             for ln in path.read_text().splitlines()]
    path.write_text("\n".join(lines) + "\n")
    vt = validate_material(_cfg(path))
    return path, vt


# --------------------------------------------------------------------------- the typo screen's prediction
@pytest.mark.parametrize("seed", range(3))
def test_typo_flag_prediction_and_its_error_from_the_other_runs(tmp_path, seed):
    """The flag's prediction and standard error are those of an OLS fit without the run (statsmodels'
    ``get_prediction(...).se_obs``); its studentised residual is statsmodels' external one."""
    from demid.data import read_printed
    from demid.design import model_matrix, model_units, quadratic_terms
    from demid.transcription import likely_typos

    from .transcription.test_likely_typos import _cfg

    path, vt = _table_with_run_5_slipped(tmp_path, seed, noise=0.3)
    (flag,) = likely_typos(vt, _cfg(path), read_printed(path, vt.table))

    data = vt.table
    x = model_matrix(vt.coding.to_coded(model_units(data[["x1", "x2"]].to_numpy(float), ["x1", "x2"], ())),
                     quadratic_terms(2))
    y = data["y"].to_numpy(float)
    i = int(np.flatnonzero(data["run"].to_numpy() == 5)[0])
    full = sm.OLS(y, x).fit()
    others = np.arange(len(y)) != i
    without = sm.OLS(y[others], x[others]).fit()
    prediction = without.get_prediction(x[i:i + 1])
    assert flag["predicted_from_other_runs"] == pytest.approx(float(prediction.predicted_mean[0]), rel=1e-9)
    assert flag["prediction_se"] == pytest.approx(float(prediction.se_obs[0]), rel=1e-9)
    assert flag["student_resid"] == pytest.approx(full.get_influence().resid_studentized_external[i], rel=1e-9)
    # flagged at the family-wise 5 % level: Bonferroni over the runs, t with n - p - 1 degrees of freedom
    assert full.outlier_test(method="bonf")[i, 2] < 0.05


@pytest.mark.parametrize("seed", range(2))
def test_typo_screen_flags_at_the_bonferroni_p_with_n_minus_p_minus_1_degrees_of_freedom(tmp_path, seed):
    """A run is screened when its Bonferroni p (statsmodels' outlier test: n times the two-sided t tail with
    n - p - 1 degrees of freedom) is below the family level: a level just above the slipped run's p flags it,
    one just below does not."""
    from demid.data import read_printed
    from demid.design import model_matrix, model_units, quadratic_terms
    from demid.transcription import likely_typos

    from .transcription.test_likely_typos import _cfg

    path, vt = _table_with_run_5_slipped(tmp_path, seed, noise=3.0)
    data = vt.table
    x = model_matrix(vt.coding.to_coded(model_units(data[["x1", "x2"]].to_numpy(float), ["x1", "x2"], ())),
                     quadratic_terms(2))
    i = int(np.flatnonzero(data["run"].to_numpy() == 5)[0])
    p_bonf = float(sm.OLS(data["y"].to_numpy(float), x).fit().outlier_test(method="bonf")[i, 2])
    assert 1e-12 < p_bonf < 0.5  # premise: a p the screen's tail (absolute error ~1e-16) computes to 2 %
    printed = read_printed(path, vt.table)
    flagged = likely_typos(vt, _cfg(path), printed, family_alpha=p_bonf * 1.02)
    assert [f["run"] for f in flagged] == [5]
    assert likely_typos(vt, _cfg(path), printed, family_alpha=p_bonf / 1.02) == []


# --------------------------------------------------------------------------- the verdict's numbers
def _lack_of_fit_p(table, factors, response="y"):
    """Lack of fit against the replicated runs: the quadratic against the cell-means model (statsmodels)."""
    full = quadratic_ols(table, factors, response)
    cells = table[factors].round(9).astype(str).agg("|".join, axis=1)
    means = sm.OLS(table[response].to_numpy(float),
                   np.asarray(pd.get_dummies(cells), dtype=float)).fit()
    df_lof = full.df_resid - means.df_resid
    f = ((full.ssr - means.ssr) / df_lof) / (means.ssr / means.df_resid)
    return float(stats.f.sf(f, df_lof, means.df_resid))


def _fit_numbers(table, factors, response="y"):
    res = quadratic_ols(table, factors, response)
    y = table[response].to_numpy(float)
    press = float(np.sum((res.resid / (1 - res.get_influence().hat_matrix_diag)) ** 2))
    return {"q2": 1 - press / float(np.sum((y - y.mean()) ** 2)), "loo_rmse": np.sqrt(press / len(y)),
            "rmse": np.sqrt(res.ssr / len(y)), "resid_std": np.sqrt(res.scale)}


@pytest.mark.parametrize("kind, seed", [("step", 300), ("step", 303), ("hidden", 301), ("batch", 302)])
def test_unexplained_verdict_reports_its_family_p_and_the_fit(kind, seed):
    """An unexplained verdict: the family-wise p is the smallest family p of the tests that fired (or
    remained), each at or above its nominal p; the lack-of-fit p is the F test against the cell means;
    Q², the leave-one-out RMSE and the RMSE are statsmodels'."""
    from .generators import off_catalogue_table

    table, _ = off_catalogue_table(seed, 2, kind, 20 if kind != "batch" else 10)
    result = criticize(table, FACTORS[2], "y", n_null=199)
    assert result.verdict == "unexplained"
    u = result.unexplained
    entries = u["tests"] + u["remaining"]
    assert u["p_value"] == min(e["p_family"] for e in entries)
    for e in u["tests"]:
        assert e["p_nominal"] <= e["p_family"] <= 0.05
        assert f"(family-wise p = {e['p_family']:.3g})" in u["message"]
        if e["cause"] in ("outlier", "factor_level"):  # the run is named as a run
            assert f"(run {e['detail']}) (family-wise p = {e['p_family']:.3g})" in u["message"]
        elif e["cause"] == "heteroscedasticity":  # the factor the scatter grows with
            assert f"unequal scatter with {e['detail']} (family-wise p" in u["message"]
    lof = [e for e in entries if e["cause"] == "lack_of_fit"]
    assert (f"lack of fit against the replicated runs (family-wise p = {lof[0]['p_family']:.3g})"
            in u["message"])
    assert lof and lof[0]["p_nominal"] == pytest.approx(_lack_of_fit_p(table, FACTORS[2]), rel=1e-9)
    detail = result.verdict_detail
    assert detail["lof_p"] == pytest.approx(_lack_of_fit_p(table, FACTORS[2]), rel=1e-9)
    expected = _fit_numbers(table, FACTORS[2])
    for key in ("q2", "loo_rmse", "rmse"):
        assert detail[key] == pytest.approx(expected[key], rel=1e-9), key


@pytest.mark.parametrize("seed", [500, 503])
def test_adequate_verdict_reports_the_detectable_size_in_response_units(seed):
    """The power caveat's size is k residual SDs, sqrt(SSE/(n - p)) in response units, and the message
    prints both."""
    from .generators import ccd_table as table_of

    table, _ = table_of(seed, 2, "clean")
    result = criticize(table, FACTORS[2], "y", n_null=199)
    assert result.verdict == "adequate"
    detail = result.verdict_detail
    expected = _fit_numbers(table, FACTORS[2])
    assert detail["detectable"] == pytest.approx(detail["detectable_sd"] * expected["resid_std"], rel=1e-9)
    assert f"{detail['detectable_sd']:.1f} residual standard deviations" in detail["message"]
    for key in ("q2", "loo_rmse", "rmse"):
        assert detail[key] == pytest.approx(expected[key], rel=1e-9), key


@pytest.mark.parametrize("df_resid, n_tests, alpha", [(7, 10, 0.05), (10, 14, 0.05), (4, 3, 0.1), (30, 1, 0.05)])
def test_detectable_departure_from_the_noncentral_t(df_resid, n_tests, alpha):
    """F(1, d; λ) is the square of a noncentral t(d; √λ): the size k is where the two-sided t test at
    level α/m, d = df_resid − 1, has 80 % power."""
    from demid.criticism.verdict import detectable_departure

    d = df_resid - 1
    crit = stats.t.ppf(1 - alpha / n_tests / 2, d)
    power = lambda k: stats.nct.sf(crit, d, k) + stats.nct.sf(crit, d, -k)  # noqa: E731  P(|T| > c)
    k = optimize.brentq(lambda k: power(k) - 0.8, 1e-3, 15)
    assert detectable_departure(df_resid, n_tests, alpha) == pytest.approx(k, rel=1e-6)
    assert detectable_departure(2, 5, 0.05) is None
    assert detectable_departure(10, 0, 0.05) is None


# --------------------------------------------------------------------------- the run order's correlations
def _ccd2_standard_order():
    """A 2-factor CCD written in its standard order: factorial (first factor fastest), axial, 5 centres."""
    a = np.sqrt(2.0)
    return np.array([[-1, -1], [1, -1], [-1, 1], [1, 1], [-a, 0], [a, 0], [0, -a], [0, a]] + [[0, 0]] * 5)


def test_run_order_correlation_with_a_standard_order_is_spearmans():
    """The reported rank correlation with the standard order is Spearman's ρ of the run numbers and the
    standard positions: 1 in standard order, 1 − 6Σd²/(n(n²−1)) with two neighbouring factorial runs
    swapped (Σd² = 2) — no other standard order fits better."""
    from demid.criticism.run_order import assess_run_order, standard_order_correlation

    coded = _ccd2_standard_order()
    n = len(coded)
    runs = np.arange(1, n + 1)
    assert standard_order_correlation(runs, coded) == pytest.approx(1.0)
    swapped = runs.copy()
    swapped[[0, 1]] = swapped[[1, 0]]
    expected = 1 - 6 * 2 / (n * (n * n - 1))
    assert expected == pytest.approx(stats.spearmanr(swapped, runs)[0])
    assert standard_order_correlation(swapped, coded) == pytest.approx(expected, rel=1e-12)
    rng = np.random.default_rng(0)
    order = assess_run_order(swapped, coded, {"y": rng.normal(size=n)})
    assert order.reason == "standard_order" and not order.drift_tested
    assert order.to_json()["rank_correlation"] == pytest.approx(round(expected, 6), abs=1e-12)


def test_run_order_sorted_by_a_response_reports_spearmans_rho_and_the_response():
    """Runs sorted by y2 apart from one swap: the reported correlation is scipy's Spearman ρ with y2
    (signed), not with y1, which the runs do not follow."""
    from demid.criticism.run_order import assess_run_order

    coded = _ccd2_standard_order()
    n = len(coded)
    rng = np.random.default_rng(3)
    runs = rng.permutation(n) + 1
    y2 = -(runs + 0.0)
    y2[[2, 5]] = y2[[5, 2]]  # not perfectly sorted
    y1 = rng.normal(size=n)
    order = assess_run_order(runs, coded, {"y1": y1, "y2": y2})
    assert order.reason == "sorted_by_response" and order.response == "y2"
    assert order.correlation == pytest.approx(stats.spearmanr(runs, y2)[0], rel=1e-12)
    assert order.correlation < 0
    assert order.to_json()["follows_response"] == "y2"
    assert f"{order.correlation:+.2f}" in order.message


# --------------------------------------------------------------------------- the ranking of observable sets
def _linear(name: str, slope_a: float, slope_b: float):
    from demid.design import quadratic_terms
    from demid.surrogate import Surrogate

    coef = np.array([0.0, slope_a, slope_b, 0.0, 0.0, 0.0])  # Intercept, a, b, a:b, a^2, b^2
    return Surrogate(name, ["a", "b"], quadratic_terms(2), coef, np.zeros((6, 6)), 0.0, 7)


def test_ranking_reports_gain_fraction_and_contraction_in_closed_form():
    """y1 = a and y2 = b on the unit square, targets ½, σ = 0.05, tolerance 10 %: each alone keeps a band
    of width 0.1 (10 %), both a square (1 %); the posterior of one is N(½, σ²) along its factor, whose
    gain over the uniform prior is log2(1/(σ√(2πe))) bits, twice that for both.  y3 = a with target 5
    cannot be met (a ≤ 1): no gain, ranked last."""
    from demid.sampling import Domain
    from demid.uncertainty.ranking import rank_observable_sets

    sigma = 0.05
    surrogates = {"y1": _linear("y1", 1, 0), "y2": _linear("y2", 0, 1), "y3": _linear("y3", 1, 0)}
    domain = Domain(("a", "b"), (0.0, 0.0), (1.0, 1.0), (False, False))
    targets = {"y1": 0.5, "y2": 0.5, "y3": 5.0}
    frame = rank_observable_sets(surrogates, domain, ("y1", "y2", "y3"), targets,
                                 {o: sigma for o in surrogates}, 0.1, 101).set_index("observables")
    one = np.log2(1 / (sigma * np.sqrt(2 * np.pi * np.e)))
    assert frame.loc["y1", "information_gain_bits"] == pytest.approx(one, abs=5e-3)
    assert frame.loc["y2", "information_gain_bits"] == pytest.approx(one, abs=5e-3)
    both = frame.loc["y1+y2"]
    assert both["information_gain_bits"] == pytest.approx(2 * one, abs=1e-2)
    assert frame.loc["y1", "feasible_fraction_pct"] == pytest.approx(10.0, abs=1e-6)
    assert both["feasible_fraction_pct"] == pytest.approx(1.0, abs=1e-6)
    assert frame.loc["y1", "contraction_pct_vs_best_subset"] == pytest.approx(90.0, abs=1e-5)
    assert both["contraction_pct_vs_best_subset"] == pytest.approx(90.0, abs=1e-5)
    assert both["best_subset"] in ("y1", "y2")
    assert both["gain_vs_best_subset_bits"] == pytest.approx(one, abs=1e-2)
    assert both["rank"] == 1 and both["rank_by_fraction"] == 1
    assert frame.loc["y1", "rank_by_fraction"] == 2 and frame.loc["y2", "rank_by_fraction"] == 2
    assert both["targets_reachable"] and frame.loc["y1", "targets_reachable"]
    assert 0 <= both["information_gain_error_bits"] < 0.05
    unreachable = frame[frame.index.str.contains("y3")]
    assert len(unreachable) == 4 and not unreachable["targets_reachable"].any()
    assert unreachable["information_gain_bits"].isna().all()
    assert unreachable["information_gain_error_bits"].isna().all()
    assert set(unreachable["rank"]) == {4, 5, 6, 7} and set(unreachable["rank_by_fraction"]) == {4}
    assert frame.loc["y3", "feasible_fraction_pct"] == 0


@pytest.mark.parametrize("x, text", [(10000.0, "10,000"), (-10000.0, "-10,000"), (19668.2, "19,668"),
                                     (9999.4, "9999"), (1.5, "1.5")])
def test_numbers_in_running_text_carry_no_exponent_from_ten_thousand_on(x, text):
    from demid.criticism.verdict import plain_number

    assert plain_number(x) == text


# --------------------------------------------------------------------------- the next wave's proposed runs
@pytest.mark.parametrize("k, existing, count", [
    (2, [(-1, -1), (1, -1), (-1, 1), (1, 1), (0, 0)], 4),
    (2, [(a, b) for a in (-1, 0, 1) for b in (-1, 0, 1)], 5),
    (3, [(0, 0, 0), (1, 1, 1), (-1, -1, 1)], 6),
])
def test_next_wave_runs_each_maximise_the_determinant(k, existing, count):
    """Each proposed run is, among the grid points not yet run, one that maximises det(X'X) of the full
    quadratic over the earlier and already proposed runs (brute force over the 5^k grid, numpy's det)."""
    from itertools import product

    from demid.design import model_matrix, quadratic_terms
    from demid.wave_runs import d_optimal_augment

    terms = quadratic_terms(k)
    grid = np.array(list(product((-1.0, -0.5, 0.0, 0.5, 1.0), repeat=k)))
    runs = np.array(existing, dtype=float).reshape(-1, k)
    chosen = d_optimal_augment(runs, count, k)
    assert chosen.shape == (count, k)
    ridge = 1e-9 * np.eye(len(terms))
    for point in chosen:
        def det(p):
            x = model_matrix(np.vstack([runs, p[None, :]]), terms)
            return np.linalg.det(x.T @ x + ridge)

        fresh = [p for p in grid if not any(np.allclose(p, r) for r in runs)]
        best = max(det(p) for p in fresh)
        assert not any(np.allclose(point, r) for r in runs)  # no repeat while unused points remain
        assert det(point) == pytest.approx(best, rel=1e-6)
        runs = np.vstack([runs, point])


# --------------------------------------------------------------------------- level 2: best point and its errors
def test_level2_best_point_errors_biases_and_extensions_in_closed_form():
    """y1 = y2 = a with targets 1 and 2, y3 = b with target ½, a in [½, 3], b in [¼, 1], tolerance 10 %.
    Relative errors e1 = a − 1, e2 = a/2 − 1, e3 = 2b − 1.
    Best point: e1 = −e2 at a = 4/3 (largest error 1/3).  Without y1 (or y2) the rest is met exactly
    (0), without y3 the largest error stays 1/3.  The bias y1 needs where y2 is met (a = 2) is +1, the
    bias y2 needs where y1 is met (a = 1) is −½: y2 is the bottleneck (the smaller bias), either could be
    biased.  A shared bias leaves half the spread of e1 − e2 = a/2, smallest at a = ½: 1/8, with
    δ = (e1 + e2)/2 = −5/8 and b = ¼ (e3 = −½ between them).  At the reference point (1, ¼) the errors
    are 0, −½, −½."""
    from demid.criticism.level2 import calibration_check
    from demid.sampling import Domain

    surrogates = {"y1": _linear("y1", 1, 0), "y2": _linear("y2", 1, 0), "y3": _linear("y3", 0, 1)}
    domain = Domain(("a", "b"), (0.5, 0.25), (3.0, 1.0), (False, False))
    result = calibration_check(surrogates, domain, {"y1": 1.0, "y2": 2.0, "y3": 0.5}, 0.1, 31,
                               reference_point={"a": 1.0, "b": 0.25})
    out = result.to_json()
    tol = 1e-6
    assert not out["feasible"]
    assert out["best_max_error"] == pytest.approx(1 / 3, abs=tol)
    assert out["best_point"]["a"] == pytest.approx(4 / 3, abs=tol)
    assert out["best_values"]["y1"] == pytest.approx(4 / 3, abs=tol)
    assert out["best_errors"]["y1"] == pytest.approx(1 / 3, abs=tol)
    assert out["best_errors"]["y2"] == pytest.approx(-1 / 3, abs=tol)
    assert abs(out["best_errors"]["y3"]) <= 1 / 3 + tol
    assert out["best_errors"]["y3"] == pytest.approx(2 * out["best_point"]["b"] - 1, abs=1e-12)
    without = out["max_error_without"]
    assert without["y1"] == pytest.approx(0, abs=tol) and without["y2"] == pytest.approx(0, abs=tol)
    assert without["y3"] == pytest.approx(1 / 3, abs=tol)
    bias = out["implied_bias"]
    assert bias["y1"] == pytest.approx(1.0, abs=tol) and bias["y2"] == pytest.approx(-0.5, abs=tol)
    assert bias["y3"] == pytest.approx(0.0, abs=tol)
    assert out["bottleneck"] == "y2" and out["bias_candidates"] == ["y1", "y2"] and out["biased_observable"] is None
    shared = out["shared_bias"]
    assert shared["max_error"] == pytest.approx(1 / 8, abs=tol) and shared["delta"] == pytest.approx(-5 / 8, abs=tol)
    assert shared["point"]["a"] == pytest.approx(0.5, abs=tol) and shared["point"]["b"] == pytest.approx(0.25, abs=tol)
    assert out["reference_errors"] == pytest.approx({"y1": 0.0, "y2": -0.5, "y3": -0.5}, abs=1e-12)
    assert out["reference_max_error"] == pytest.approx(0.5, abs=1e-12)
    rows = {e["model"]: e for e in out["extensions"]}
    assert [e["n_params"] for e in out["extensions"]] == [2, 3, 3, 5]
    assert [e["spare_measurements"] for e in out["extensions"]] == [1, 0, 0, -2]
    assert rows["simulation as calibrated (no discrepancy)"]["max_error"] == pytest.approx(1 / 3, abs=tol)
    assert rows["bias on y2"]["max_error"] == pytest.approx(0, abs=tol)
    assert rows["shared relative bias on all observables"]["max_error"] == pytest.approx(1 / 8, abs=tol)
    assert rows["bias on every observable"]["max_error"] == 0
    frame = result.to_frame().set_index("observable")
    assert frame.loc["y1", "rel_error_best"] == pytest.approx(1 / 3, abs=tol)
    assert frame.loc["y2", "at_best"] == pytest.approx(4 / 3, abs=tol)
    assert frame.loc["y3", "at_reference"] == 0.25 and frame.loc["y2", "rel_error_reference"] == -0.5
    assert list(frame["within_tolerance"][["y1", "y2"]]) == [False, False]
    assert list(frame["within_tolerance_reference"]) == [True, False, False]
    assert list(frame["bottleneck"]) == [False, True, False]
    assert list(frame["bias_candidate"]) == [True, True, False]
    assert frame.loc["y2", "implied_bias"] == pytest.approx(-0.5, abs=tol)


def test_strongest_rival_is_the_most_significant_test_of_another_kind():
    """A rival is a test of another kind with smaller nominal p than the named cause's best test; a run's
    outlier and slip tests are one kind; a cause at p ≤ 1e-4 (OVERWHELMING_P) has no rival."""
    import math
    from types import SimpleNamespace as H

    from demid.criticism.verdict import OVERWHELMING_P, strongest_rival

    def h(cause, p):
        return H(cause=cause, logp=math.log(p))

    named = h("outlier", 0.01)
    tests = [named, h("factor_level", 0.001), h("lack_of_fit", 0.005), h("drift", 0.002), h("missing_term", 0.2)]
    # the run's own best test is the slip at 0.001: nothing of another kind is as significant
    assert strongest_rival(named, tests) is None
    tests[1] = h("factor_level", 0.03)
    assert strongest_rival(named, tests) is tests[3]  # drift 0.002 beats lack of fit 0.005
    named = h("missing_term", 0.003)
    tests = [named, h("lack_of_fit", 0.003), h("outlier", 0.0029)]
    assert strongest_rival(named, tests) is tests[2]  # ties are no rival, a smaller p is
    named = h("missing_term", OVERWHELMING_P)
    assert strongest_rival(named, [named, h("outlier", 1e-6)]) is None
    named = h("missing_term", OVERWHELMING_P * 1.001)
    assert strongest_rival(named, [named, h("outlier", 1e-6)]).cause == "outlier"
    named = h("response_transform", 0.04)
    assert strongest_rival(named, [named, h("outlier", 1e-6)]) is None


def test_unexplained_evidence_after_a_tried_extension_reports_the_misfit_left_behind():
    """When the best catalogue extension leaves misfit behind, the verdict's p is the smallest family p of
    the tests that fired and those still rejected after the extension, and the message names both."""
    from demid.criticism.verdict import unexplained_evidence

    fired = [{"cause": "missing_term", "detail": "a^3", "p_family": 0.02},
             {"cause": "lack_of_fit", "detail": "", "p_family": 0.01}]
    tried = [{"cause": "missing_term", "detail": "a^3"}]
    remaining = [{"cause": "lack_of_fit", "detail": "", "p_family": 0.004}]
    out = unexplained_evidence("y", fired, tried, remaining, 0.05)
    assert out["p_value"] == 0.004
    assert out["detail"] == "missing_term;lack_of_fit"
    assert ("The best catalogue explanation, missing term a^3, leaves misfit behind (lack of fit against the "
            "replicated runs (family-wise p = 0.004)), so it is not named.") in out["message"]
    assert "family-wise 5 % level: missing term a^3 (family-wise p = 0.02); lack of fit" in out["message"]
    assert unexplained_evidence("y", [{"cause": "drift", "detail": "", "p_family": None}], [], [], 0.05)[
        "p_value"] is None


@pytest.mark.parametrize("share", [1.0, 0.5])
def test_power_caveat_quotes_k_residual_sds_and_their_size(share):
    """A specific test runs at α·share/m: the quoted k is the noncentral-t size at that level, the size in
    response units k·s, and both appear in the message; too few spare runs give no size."""
    from demid.criticism.verdict import power_caveat

    d, m, s = 7 - 1, 10, 2.5
    crit = stats.t.ppf(1 - 0.05 * share / m / 2, d)
    k = optimize.brentq(lambda k: stats.nct.sf(crit, d, k) + stats.nct.sf(crit, d, -k) - 0.8, 1e-3, 15)
    out = power_caveat("y", 13, 7, m, 0.05, s, specific_share=share)
    assert out["detectable_sd"] == pytest.approx(k, rel=1e-6)
    assert out["detectable"] == pytest.approx(k * s, rel=1e-6)
    assert out["power"] == 0.8
    assert f"about {k:.1f} residual standard deviations" in out["message"]
    assert "none of the 10 tests fired at the family-wise 5 % level. With 13 runs" in out["message"]
    assert f"({k * s:.3g} in response units" in out["message"]  # three significant digits
    big = power_caveat("y", 13, 7, m, 0.05, 4000.0, specific_share=share)
    assert f"({k * 4000:,.0f} in response units" in big["message"]  # no exponent from 10,000 on
    none = power_caveat("y", 8, 2, m, 0.05, s)
    assert none["detectable_sd"] is None and none["detectable"] is None and "8 runs too few" in none["message"]


def test_ambiguous_message_quotes_the_largest_aicc_gap_and_the_deciding_runs():
    from demid.criticism.verdict import ambiguous_message

    candidates = [{"cause": "missing_term", "detail": "a^3", "delta_aicc": 0.0},
                  {"cause": "response_transform", "detail": "boxcox", "delta_aicc": 1.37}]
    runs = [{"a": 0.5, "b": -1.25, "purpose": "x", "expected": 1, "separation": 2}]
    text = ambiguous_message("y", candidates, runs)
    assert "missing term a^3 and response transform explain" in text
    assert "lie within 1.4 of each other" in text
    assert "1 more run made after these, at (a=0.5, b=-1.25), would decide" in text
    replicated = [{"a": 0.5, "b": -1.25, "purpose": "x"}, {"a": 0.1, "b": 0.0, "purpose": "x"},
                  {"a": 0.5, "b": -1.25, "purpose": "x"}, {"a": 0.5, "b": -1.25, "purpose": "x"}]
    text = ambiguous_message("y", candidates, replicated)
    assert "4 more runs made after these, at (a=0.5, b=-1.25) ×3; (a=0.1, b=0), would decide" in text


@pytest.mark.parametrize("verdict", ["does_not_predict", "defect", "adequate"])
def test_the_verdict_message_joins_the_ambiguity_or_the_confirming_runs(monkeypatch, verdict):
    """A surrogate that does not predict keeps its verdict and adds the ambiguity after a space; any other verdict
    with candidates becomes 'ambiguous' with that message alone; a named cause (a defect, or under a surrogate that
    does not predict) adds the runs that would confirm it."""
    from types import SimpleNamespace

    from demid.criticism import verdict as v

    monkeypatch.setattr(v, "_verdict", lambda *a: (verdict, {"message": "y: base."}))
    monkeypatch.setattr(v, "unpredictable_runs_message", lambda fit: "")
    data = SimpleNamespace(response="y", run_candidates=None)
    candidates = [{"cause": "missing_term", "detail": "a^3", "delta_aicc": 0.0},
                  {"cause": "response_transform", "detail": "boxcox", "delta_aicc": 1.37}]
    runs = [{"a": 0.5, "b": -1.25, "purpose": "x", "expected": {"missing_term": 1.0, "drift": 2.0}}]
    ambiguous = v.ambiguous_message("y", candidates, runs)
    got, detail = v.verdict_of(data, None, [], None, [], 0.05, candidates, runs)
    if verdict == "does_not_predict":
        assert (got, detail["message"]) == (verdict, "y: base. " + ambiguous)
    else:
        assert (got, detail["message"]) == ("ambiguous", ambiguous)
    got, detail = v.verdict_of(data, None, [], None, [], 0.05, (), runs)
    if verdict in ("defect", "does_not_predict"):
        assert detail["message"] == (
            "y: base. The runs cannot rule out every rival (drift: fitted less well, but a misnamed cause is corrected "
            "only by runs that separate it from the truth): 1 more run made after these, at (a=0.5, b=-1.25), where "
            "missing_term and it predict most differently, would confirm it or correct it; a next wave (next_runs) "
            "makes those inside its box first.")
    else:
        assert detail["message"] == "y: base."


def test_measurement_order_quotes_the_gains_and_fractions_of_the_ranking():
    """The advice reads the ranking's numbers: the best first measurement with its gain and fraction, the
    gain of each added measurement (from → to), the fraction's contraction, the runner-up's gain and the
    fraction criterion where it disagrees; an unreachable target is named and left out."""
    from demid.story.measurements import measurement_order

    ranking = pd.DataFrame({
        "observables": ["y1+y2", "y1", "y2", "y3", "y1+y3", "y2+y3", "y1+y2+y3"],
        "information_gain_bits": [4.5, 2.25, 1.5, np.nan, np.nan, np.nan, np.nan],
        "feasible_fraction_pct": [1.0, 10.0, 4.0, 0.0, 0.0, 0.0, 0.0]})
    lines = measurement_order(ranking)
    assert lines[0].startswith("The target of y3 cannot be met anywhere")
    assert ("As a first measurement, y1 is the most informative: 2.25 bits, admissible fraction 10 % of the "
            "domain; y2 would gain 1.50 bits; by fraction alone y2 contracts more (4 % vs 10 %).") in lines
    assert ("From y1, adding y2 gains 2.25 bits (2.25 -> 4.50) and shrinks the admissible fraction by 90.0 % "
            "(10 % -> 1 %).") in lines
    assert ("From y2, adding y1 gains 3.00 bits (1.50 -> 4.50) and shrinks the admissible fraction by 75.0 % "
            "(4 % -> 1 %).") in lines
    assert len(lines) == 4


@pytest.mark.parametrize("value", [0.0, 3.0, 117.25])
def test_a_response_that_never_changes_is_reported_with_its_value(value):
    """Every run the same (zero included): adequate with no detectable size, and the value is printed."""
    table, _ = ccd_table(1, 2, "clean")
    table["y"] = value
    with np.errstate(all="ignore"):
        import warnings

        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            result = criticize(table, FACTORS[2], "y", n_null=99)
    assert result.verdict == "adequate"
    assert result.verdict_detail["detectable"] is None and result.verdict_detail["detectable_sd"] is None
    assert result.verdict_message.startswith(f"y: the same value ({value:.4g}) in every run")


@pytest.mark.parametrize("centre_first, centre_value", [(True, 0.0), (False, 1e-6), (True, -1e-6)])
def test_standard_order_with_the_centre_runs_first_or_off_zero_by_round_off(centre_first, centre_value):
    """The centre runs listed first are a standard order too, and coded values within 1e-6 of zero are
    on the centre level: the run column in that order correlates 1 with it."""
    from demid.criticism.run_order import standard_order_correlation

    coded = _ccd2_standard_order()
    coded[coded[:, 0] == 0] = np.where(coded[coded[:, 0] == 0] == 0, centre_value, coded[coded[:, 0] == 0])
    if centre_first:
        coded = np.vstack([coded[-5:], coded[:-5]])
    runs = np.arange(1, len(coded) + 1)
    assert standard_order_correlation(runs, coded) == pytest.approx(1.0, abs=1e-12)


def test_run_order_follows_the_response_it_is_most_strongly_rank_correlated_with():
    """Two responses above the threshold: the one with the larger |ρ| is named, whatever its sign."""
    from demid.criticism.run_order import assess_run_order

    coded = _ccd2_standard_order()
    runs = np.arange(1, len(coded) + 1) * 1.0
    down = -runs.copy()  # ρ = −1
    up = runs.copy()
    up[[0, 2]], up[[6, 8]] = up[[2, 0]], up[[8, 6]]  # ρ ≈ 0.956
    assert 0.9 <= stats.spearmanr(runs, up)[0] < 1
    for responses in ({"down": down, "up": up}, {"up": up, "down": down}):
        order = assess_run_order(runs, coded, responses)
        assert order.response == "down" and order.correlation == pytest.approx(-1.0)


@pytest.mark.parametrize("causes", [["missing_term"], ["lack_of_fit"], ["missing_term", "lack_of_fit"],
                                    ["drift", "outlier", "lack_of_fit", "heteroscedasticity"],
                                    ["drift", "outlier", "heteroscedasticity"]])
def test_the_power_caveats_specific_share_is_the_smallest_weight_of_a_specific_test(causes):
    """Beside lack of fit (LOF_SHARE of the family's level), each of the m - 1 specific tests runs at
    (1 − LOF_SHARE)/(m − 1) of it, i.e. at share (1 − LOF_SHARE)·m/(m − 1) of the level an equal split gives;
    without lack of fit (or with it alone) every test gets an equal share, 1."""
    from demid.criticism.catalogue import LOF_SHARE
    from demid.criticism.verdict import _specific_share

    m = len(causes)
    expected = (1 - LOF_SHARE) * m / (m - 1) if "lack_of_fit" in causes and m > 1 else 1.0
    assert _specific_share(causes) == pytest.approx(expected, rel=1e-12)

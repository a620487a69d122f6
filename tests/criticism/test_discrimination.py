"""Causes the runs cannot tell apart and the runs that decide (criticism.discrimination): the ambiguity rule,
the power of the proposed runs, and the closed loop with the generator simulating the runs."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest
from scipy import stats

from demid.criticism import criticize, discrimination
from demid.criticism.discrimination import (AMBIGUOUS_AICC, DECIDING_POWER, new_run_prediction, close_candidates,
                                            pair_progress, target_separation)
from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm
from demid.design import model_matrix, quadratic_terms
from tests.generators import FACTORS, ccd_table, later_runs


def _entry(cause, detail, aicc):
    return {"cause": cause, "detail": detail, "aicc": aicc}


def test_a_cause_fitted_worse_than_a_rival_of_another_kind_is_not_named_over_it():
    named = ("missing_term", "gamma^3")
    entries = [_entry("response_transform", "log", -48.0), _entry("missing_term", "gamma^3", -26.0),
               _entry("outlier", 19, -17.0)]
    out = close_candidates(entries, named=named)
    assert [(e["cause"], e["detail"]) for e in out] == [("response_transform", "log"), named]
    # a rival just inside the margin is listed, one just outside is not
    entries = [_entry("drift", "run", 0.0), _entry("step", 7, AMBIGUOUS_AICC - 0.1),
               _entry("outlier", 3, AMBIGUOUS_AICC + 0.1)]
    assert [e["cause"] for e in close_candidates(entries, named=("drift", "run"))] == ["drift", "step"]
    # the wider margin within which a named cause comes with confirming runs
    wider = close_candidates(entries, named=("drift", "run"), margin=discrimination.CONFIRM_AICC)
    assert [e["cause"] for e in wider] == ["drift", "step", "outlier"]
    # an outlier and a slip of the same run are one candidate; steps at two change-points are two
    entries = [_entry("factor_level", 8, -25.0), _entry("outlier", 8, -16.0), _entry("step", 9, -15.0),
               _entry("step", 10, -14.0)]
    out = close_candidates(entries, named=("outlier", 8))
    assert [(e["cause"], e["detail"]) for e in out] == [("outlier", 8), ("step", 9), ("step", 10)]
    assert close_candidates(entries, named=("drift", "run")) == []  # the named cause was not fitted


def test_a_run_that_decides_one_pair_is_preferred_to_one_that_moves_every_pair_a_little():
    """Progress over target per pair (points x pairs): a point that takes one pair past its target and leaves the
    other where it was beats one that takes both a third of the way (maximin would pick the latter and, where no
    point separates every pair, spend every run deciding none); beyond its target a pair counts no more."""
    progress = np.array([[3.0, 0.0], [0.3, 0.3], [1.0, 0.0], [0.9, 0.45]])
    gain = pair_progress(progress)
    assert gain[0] > gain[1] and gain[0] == pytest.approx(gain[2], abs=1e-2)
    assert int(np.argmax(gain)) == 3  # 1.35 of the two targets
    assert np.min(progress[:2], axis=1).argmax() == 1 and pair_progress(progress[:2]).argmax() == 0


@pytest.mark.parametrize("gap", [0.0, 3.0, 10.0])
def test_target_separation_decides_with_its_power(gap):
    """Under the other candidate, new runs of summed squared separation d^2 add d^2 + 2 d Z to the favoured
    one's -2 log-likelihood; the target makes that exceed the margin plus the gap with DECIDING_POWER."""
    d2 = target_separation(gap)
    d = math.sqrt(d2)
    assert stats.norm.sf((AMBIGUOUS_AICC + gap - d2) / (2 * d)) == pytest.approx(DECIDING_POWER, abs=1e-9)
    z = np.random.default_rng(0).normal(size=200_000)
    assert np.mean(d2 + 2 * d * z > AMBIGUOUS_AICC + gap) == pytest.approx(DECIDING_POWER, abs=0.005)


def test_a_drift_goes_on_in_the_predictions_of_later_runs_a_step_does_not():
    table, _ = ccd_table(7, 2, "drift", 8.0)
    data, _ = prepare_data(table, FACTORS[2], "y", None, ())
    centre = np.zeros((1, 2))
    drift, step = Model(data, ModelForm(drift=True)), Model(data, ModelForm(step=6))
    per_run = drift.beta[drift.names.index("run")] / drift.run_scale
    later = new_run_prediction(drift, centre, 4)[0][0] - new_run_prediction(drift, centre, 1)[0][0]
    assert later == pytest.approx(3 * per_run)
    assert new_run_prediction(step, centre, 4)[0][0] == pytest.approx(new_run_prediction(step, centre, 1)[0][0])
    # a new run is the next one unless said otherwise: one run after the last, at the centre's fitted value
    # plus the drift since the runs' mean position
    runs = data.runs.astype(float)
    next_run = drift.beta[0] + per_run * (runs.max() + 1 - runs.mean())
    assert new_run_prediction(drift, centre)[0][0] == pytest.approx(next_run, rel=1e-12)


def _simulate_drift(seed: int, k: int, size: float, runs: list[dict]) -> pd.DataFrame:
    """The proposed runs as ccd_table's drift would have made them after its runs (the drift goes on)."""
    new, _ = later_runs(seed, k, runs)
    n = new["run"].iloc[0] - 1
    new["y"] += size * (new["run"].to_numpy() - (n + 1) / 2) / (n - 1)
    return new


@pytest.mark.workflow  # a benchmark-like batch of tables
def test_a_drift_that_also_fits_a_step_is_ambiguous_and_the_proposed_runs_name_the_drift():
    decided = []
    for k in (2, 3):
        for seed in range(20):
            table, _ = ccd_table(seed, k, "drift", 8.0)
            first = criticize(table, FACTORS[k], "y", n_null=499)
            if first.verdict != "ambiguous" or {c["cause"] for c in first.candidates} != {"drift", "step"}:
                continue
            runs = first.discriminating_runs
            assert 1 <= len(runs) <= discrimination.MAX_RUNS
            again = criticize(pd.concat([table, _simulate_drift(seed, k, 8.0, runs)], ignore_index=True),
                              FACTORS[k], "y", n_null=499)
            decided.append((k, seed, [(f.cause, f.detail) for f in again.findings[:1]]))
    assert len(decided) >= 3, decided
    assert all(named == [("drift", "run")] for _, _, named in decided), decided


def test_the_separation_of_several_runs_against_statsmodels_predictions():
    """Two candidate models' predictions of three new runs (a point, its replicate, another point): the
    squared Mahalanobis distance with each model's estimation covariance (statsmodels cov_params) shared by
    the runs and its residual variance added per run; a replicate adds less than a run of its own."""
    import statsmodels.api as sm

    from demid.criticism.discrimination import joint_separation, prediction_parts
    from demid.design import parse_term

    table, _ = ccd_table(3, 2, "term", 6.0, term="mu_r^3")
    data, _ = prepare_data(table, FACTORS[2], "y", None, ())
    cubic = parse_term("mu_r^3", FACTORS[2])
    plain, extended = Model(data, ModelForm()), Model(data, ModelForm(extra_terms=(cubic,)))
    points = np.array([[1.0, 1.0], [1.0, 1.0], [-1.0, 0.0]])

    def statsmodels_prediction(terms):
        fit = sm.OLS(data.y, model_matrix(data.coded, terms)).fit()
        rows = model_matrix(points, terms)
        return rows @ fit.params, rows @ fit.cov_params() @ rows.T + fit.scale * np.eye(len(points))

    mean_a, cov_a = statsmodels_prediction(quadratic_terms(2))
    mean_b, cov_b = statsmodels_prediction(quadratic_terms(2) + [cubic])
    delta = mean_a - mean_b
    # the means' part, and the spreads' part: the symmetrised Kullback-Leibler divergence of N(0, cov_a), N(0, cov_b)
    spread = (np.trace(np.linalg.inv(cov_a) @ cov_b) + np.trace(np.linalg.inv(cov_b) @ cov_a) - 2 * len(points)) / 4
    expected = float(delta @ np.linalg.solve(cov_a + cov_b, delta)) + spread

    parts_a, parts_b = prediction_parts(plain, points), prediction_parts(extended, points)
    chosen_a = [(parts_a[0][i], parts_a[1][i], parts_a[2][i]) for i in (0, 1)]
    chosen_b = [(parts_b[0][i], parts_b[1][i], parts_b[2][i]) for i in (0, 1)]
    assert joint_separation(chosen_a, chosen_b, parts_a, parts_b)[2] == pytest.approx(expected, rel=1e-9)
    one = joint_separation([], [], parts_a, parts_b)
    two = joint_separation(chosen_a[:1], chosen_b[:1], parts_a, parts_b)[1]
    assert one[0] < two < 2 * one[0]


def test_the_spread_separation_is_the_symmetrised_divergence_of_the_two_predictive_distributions():
    """Monte Carlo of E_a[log p_a - log p_b] and E_b[log p_b - log p_a] (scipy's densities), averaged: the part
    of the divergence of N(0, S_a) and N(0, S_b) their spreads make; zero for equal spreads."""
    from demid.criticism.discrimination import spread_separation

    cov_a = np.array([[1.0, 0.3, 0.0], [0.3, 2.0, 0.2], [0.0, 0.2, 0.5]])
    cov_b = np.array([[4.0, 0.1, 0.0], [0.1, 0.6, 0.0], [0.0, 0.0, 0.5]])
    rng = np.random.default_rng(0)
    pa, pb = stats.multivariate_normal(np.zeros(3), cov_a), stats.multivariate_normal(np.zeros(3), cov_b)
    xa, xb = pa.rvs(400_000, random_state=rng), pb.rvs(400_000, random_state=rng)
    kl = (np.mean(pa.logpdf(xa) - pb.logpdf(xa)) + np.mean(pb.logpdf(xb) - pa.logpdf(xb))) / 2
    got = spread_separation(np.stack([cov_a, cov_a]), np.stack([cov_b, cov_a]))
    assert got[0] == pytest.approx(kl, rel=0.02)  # the means' part is the same divergence for equal spreads
    assert got[1] == pytest.approx(0.0, abs=1e-12)


@pytest.mark.parametrize("seed", range(4))
def test_unequal_scatter_and_equal_scatter_are_separated_by_runs_at_an_end_of_the_scatter_factor(seed):
    """Two models with nearly the same mean surface, one with scatter growing 12-fold across a factor: the runs
    that decide are at an end of that factor's range (where the scatters differ most), not where the means
    happen to differ, and they separate the two far beyond what their means alone would."""
    table, planted = ccd_table(seed, 2, "het", 30.0)
    data, _ = prepare_data(table, FACTORS[2], "y", None, ())
    j = FACTORS[2].index(planted.factor)
    v = data.coded[:, j] / data.alpha
    plain = Model(data, ModelForm())
    het = Model(data, ModelForm(weight_on=planted.factor, weight_gamma=2.5, weight_values=tuple(float(x) for x in v)))
    runs = discrimination.discriminating_runs(data, [plain, het], ["equal", "unequal"])
    coded = data.coding.to_coded(np.array([[r[f] for f in FACTORS[2]] for r in runs]))
    assert np.allclose(np.abs(coded[:, j]), data.alpha, atol=1e-3)
    assert runs[-1]["separation"] > target_separation(0.0) / 2


def test_a_cause_named_with_a_rival_not_far_behind_comes_with_runs_that_confirm_or_correct_it():
    """A drift over 13 runs is often fitted nearly as well by a step: where the named cause leads by 6-10 in
    AICc it is named with confirming runs (a step named in place of the drift among them); simulated as the
    generator's drift goes on, they leave the drift named every time."""
    from demid.criticism.discrimination import CONFIRM_PURPOSE

    confirmed, corrected = 0, 0
    for seed in range(16):
        table, _ = ccd_table(seed, 2, "drift", 8.0)
        first = criticize(table, FACTORS[2], "y", n_null=499)
        runs = first.discriminating_runs
        if not runs or first.candidates:
            continue
        assert first.verdict == "defect" and first.findings
        assert all(r["purpose"] == CONFIRM_PURPOSE for r in runs) and 1 <= len(runs) <= discrimination.MAX_RUNS
        assert "would confirm it or correct it" in first.verdict_message
        again = criticize(pd.concat([table, _simulate_drift(seed, 2, 8.0, runs)], ignore_index=True),
                          FACTORS[2], "y", n_null=499)
        assert [(f.cause, f.detail) for f in again.findings[:1]] == [("drift", "run")], (seed, again.verdict_message)
        confirmed += first.findings[0].cause == "drift"
        corrected += first.findings[0].cause != "drift"
    assert confirmed >= 2 and corrected >= 1, (confirmed, corrected)


@pytest.mark.parametrize("lam", [0.0, 0.5])
def test_a_transformed_models_prediction_is_back_transformed_with_the_delta_method_variance(lam):
    """A model fitted on the Box-Cox scale predicts a new run's response (original scale) as the back-transform
    of the statsmodels prediction on that scale, with variance (d y / d z)^2 (x' cov x + scale), the slope of
    the back-transform written in closed form: exp(z) for lambda 0, (1 + lambda z)^(1/lambda - 1) otherwise."""
    import statsmodels.api as sm
    from scipy import special

    table, _ = ccd_table(5, 2, "clean")
    table["y"] = table["y"] - table["y"].min() + 5.0  # positive, so the transform applies
    data, _ = prepare_data(table, FACTORS[2], "y", None, ())
    model = Model(data, ModelForm(lam=lam))
    points = np.array([[0.0, 0.0], [1.0, -1.0], [-data.alpha, 0.0]])

    terms = quadratic_terms(2)
    fit = sm.OLS(special.boxcox(data.y, lam), model_matrix(data.coded, terms)).fit()
    rows = model_matrix(points, terms)
    z = rows @ fit.params
    if lam == 0.0:
        mean, slope = np.exp(z), np.exp(z)
    else:
        mean, slope = (1 + lam * z) ** (1 / lam), (1 + lam * z) ** (1 / lam - 1)
    variance = slope ** 2 * (np.einsum("ij,jk,ik->i", rows, fit.cov_params(), rows) + fit.scale)
    got_mean, got_variance = new_run_prediction(model, points)
    assert got_mean == pytest.approx(mean, rel=1e-9)
    assert got_variance == pytest.approx(variance, rel=1e-6)

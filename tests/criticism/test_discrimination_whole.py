"""The numbers the deciding runs are chosen by (criticism.discrimination), each against an independent computation
over generated inputs: a new run's mean and variance against statsmodels' prediction of a new observation, the
separation of two models' predictions of 1-3 runs against Mahalanobis distances and Kullback-Leibler divergences
written out with explicit covariance matrices, the target separation against the power it is defined by, the
pairs' progress and the candidate grid against their definitions."""

from __future__ import annotations

from itertools import product

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import stats
from statsmodels.regression.linear_model import OLS

from demid.criticism.discrimination import (AMBIGUOUS_AICC, DECIDING_POWER, candidate_grid, joint_separation,
                                            new_run_prediction, pair_progress, prediction_parts,
                                            target_separation)
from demid.criticism.models import Model, ModelForm
from demid.design import model_matrix, quadratic_terms
from tests.criticism.test_models_properties import _data


@given(seed=st.integers(0, 1000), centre=st.sampled_from([3, 8]))
@settings(max_examples=10, deadline=None, derandomize=True)
def test_a_new_runs_mean_and_variance_are_statsmodels_prediction_of_a_new_observation(seed, centre):
    data = _data(seed, centre)
    model = Model(data, ModelForm())
    points = candidate_grid(data)
    mean, var = new_run_prediction(model, points)
    fit = OLS(data.y, model_matrix(data.coded, quadratic_terms(2))).fit()
    frame = fit.get_prediction(model_matrix(points, quadratic_terms(2))).summary_frame()
    np.testing.assert_allclose(mean, frame["mean"], rtol=1e-10)
    np.testing.assert_allclose(var, frame["obs_ci_upper"].sub(frame["mean"]).div(
        stats.t.ppf(0.975, fit.df_resid)).pow(2), rtol=1e-8)
    # the candidate grid: every combination of the levels -alpha, -1, 0, 1, alpha within the farthest run
    levels = sorted({-data.alpha, -1.0, 0.0, 1.0, data.alpha})
    reach = np.max(np.linalg.norm(data.coded, axis=1))
    expected = [p for p in product(levels, repeat=2) if np.linalg.norm(p) <= reach + 1e-9]
    np.testing.assert_array_equal(points, np.array(expected))


def _parts(rng, p: int, n_points: int):
    jac = rng.normal(size=(n_points, p))
    a = rng.normal(size=(p, p))
    return rng.normal(size=n_points) * 3, jac, rng.uniform(0.2, 2.0, n_points), a @ a.T / p


@given(seed=st.integers(0, 10 ** 6), chosen=st.integers(0, 2), p=st.integers(1, 4))
@settings(max_examples=25, deadline=None, derandomize=True)
def test_the_separation_of_two_models_predictions_is_mahalanobis_plus_their_spreads_divergence(seed, chosen, p):
    rng = np.random.default_rng(seed)
    n_points = 5
    parts_a, parts_b = _parts(rng, p, n_points), _parts(rng, p, n_points)
    runs_a = [(rng.normal(), rng.normal(size=p), rng.uniform(0.2, 2)) for _ in range(chosen)]
    runs_b = [(rng.normal(), rng.normal(size=p), rng.uniform(0.2, 2)) for _ in range(chosen)]
    got = joint_separation(runs_a, runs_b, parts_a, parts_b)
    for q in range(n_points):
        def stacked(runs, parts):
            mean, jac, noise, cov = parts
            means = np.array([r[0] for r in runs] + [mean[q]])
            rows = np.array([r[1] for r in runs] + [jac[q]])
            return means, rows @ cov @ rows.T + np.diag([r[2] for r in runs] + [noise[q]])
        mean_a, cov_a = stacked(runs_a, parts_a)
        mean_b, cov_b = stacked(runs_b, parts_b)
        delta = mean_a - mean_b
        m = len(delta)
        mahalanobis = delta @ np.linalg.inv(cov_a + cov_b) @ delta
        divergence = (np.trace(np.linalg.inv(cov_a) @ cov_b) + np.trace(np.linalg.inv(cov_b) @ cov_a) - 2 * m) / 4
        assert got[q] == pytest.approx(mahalanobis + max(divergence, 0.0), rel=1e-8, abs=1e-10)
    same = joint_separation(runs_a, runs_a, parts_a, parts_a)
    np.testing.assert_allclose(same, 0.0, atol=1e-9)  # a model is not separated from itself


@given(gap=st.floats(-5, 60))
@settings(max_examples=20, deadline=None, derandomize=True)
def test_the_target_separation_decides_with_the_stated_power(gap):
    """Under the other candidate the runs add d^2 + 2 d Z to the favoured one's -2 log-likelihood: d^2 is the
    smallest separation for which that exceeds AMBIGUOUS_AICC + gap with probability DECIDING_POWER."""
    target = target_separation(gap)
    d = np.sqrt(target)
    need = AMBIGUOUS_AICC + max(gap, 0.0)
    assert stats.norm.sf((need - target) / (2 * d)) == pytest.approx(DECIDING_POWER, rel=1e-9)
    assert target_separation(gap + 1.0) > target if gap >= 0 else target == target_separation(0.0)


def test_pair_progress_caps_each_pair_at_its_target_and_breaks_ties_by_the_least_separated():
    progress = np.array([[0.5, 2.0, 0.1], [1.0, 1.0, 1.0], [0.0, 0.0, 0.0], [3.0, 0.2, 0.9]])
    expected = [0.5 + 1.0 + 0.1 + 1e-3 * 0.1, 3.0 + 1e-3, 0.0, 1.0 + 0.2 + 0.9 + 1e-3 * 0.2]
    np.testing.assert_allclose(pair_progress(progress), expected, rtol=1e-12)


def test_a_transformed_models_new_run_is_back_transformed_by_the_delta_method():
    data = _data(3, 3)
    model = Model(data, ModelForm(lam=0.0))
    points = candidate_grid(data)
    mean, jac, noise, cov = prediction_parts(model, points)
    eta = model_matrix(points, quadratic_terms(2)) @ model.beta
    np.testing.assert_allclose(mean, np.exp(eta), rtol=1e-10)  # log: the median on the original scale
    sigma2 = model.ssr / model.df_resid
    np.testing.assert_allclose(noise, sigma2 * np.exp(eta) ** 2, rtol=1e-6)  # d exp(eta) / d eta = exp(eta)
    np.testing.assert_allclose(jac, model_matrix(points, quadratic_terms(2)) * np.exp(eta)[:, None], rtol=1e-6)
    expected = sigma2 * np.linalg.inv(model.x.T @ model.x)
    np.testing.assert_allclose(cov, expected, rtol=1e-8, atol=1e-12 * np.abs(expected).max())

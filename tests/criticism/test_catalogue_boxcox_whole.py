"""The transform test's bootstrap p-value, P(LR* >= LR | all y* > 0), against the same null draws re-made in
the test and a Box-Cox profile written out with numpy's least squares; a tie counts as reaching the observed
ratio, so a response whose best lambda is 1 (LR = 0) has p = 1 exactly."""
from __future__ import annotations

import types

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from demid.criticism.catalogue import Round
from demid.criticism.models import orthonormal_basis
from demid.design import ccd_points, model_matrix, quadratic_terms

LAMBDAS = np.round(np.arange(-2.0, 2.0001, 0.05), 10)  # the test's grid: -2 to 2 in steps of 0.05


def _design(k: int) -> np.ndarray:
    return model_matrix(ccd_points(k, np.sqrt(k), 3), quadratic_terms(k))


def _lr_by_least_squares(y: np.ndarray, x: np.ndarray) -> np.ndarray:
    """2 (max_lambda l - l(1)), l = -n/2 log(SSE/n) + (lambda - 1) sum log y, each column of y fitted alone."""
    n = y.shape[0]
    logy = np.log(y)
    prof = []
    for lam in LAMBDAS:
        z = logy if lam == 0 else (y ** lam - 1.0) / lam
        beta = np.linalg.lstsq(x, z, rcond=None)[0]
        sse = np.sum((z - x @ beta) ** 2, axis=0)
        prof.append(-0.5 * n * np.log(sse / n) + (lam - 1.0) * logy.sum(axis=0))
    prof = np.array(prof)
    return 2.0 * (prof.max(axis=0) - prof[int(np.flatnonzero(LAMBDAS == 1.0)[0])])


def _null_model(x: np.ndarray, fitted: np.ndarray, sd: float):
    n, p = x.shape
    return types.SimpleNamespace(ssr=sd ** 2 * (n - p), df_resid=n - p, fitted_z=fitted, y=fitted)


def _positive_draws(fitted, sd, n_null, seed, max_batches=20):
    """The bootstrap's draws re-made: batches of n_null normal columns, the all-positive ones kept in order."""
    rng = np.random.default_rng(seed)
    kept, tried = [], 0
    for _ in range(max_batches):
        y = fitted[:, None] + sd * rng.standard_normal((len(fitted), n_null))
        tried += n_null
        kept.extend(y[:, j] for j in np.flatnonzero(np.all(y > 0, axis=0)))
        if len(kept) >= n_null:
            break
    return np.array(kept[:n_null]).T, tried


@settings(max_examples=6, deadline=None, derandomize=True)
@given(k=st.integers(2, 3), mean=st.sampled_from([1.5, 2.5, 6.0]), sd=st.sampled_from([0.6, 1.2]),
       slope=st.floats(-0.5, 0.5), seed=st.integers(0, 50), quantile=st.floats(0.05, 0.95))
def test_bootstrap_p_counts_the_null_ratios_at_or_above_the_observed_one(k, mean, sd, slope, seed, quantile):
    x = _design(k)
    fitted = mean + slope * x[:, 1]
    n_null = 300
    draws, _ = _positive_draws(fitted, sd, n_null, seed)
    lr_null = np.sort(_lr_by_least_squares(draws, x))
    # an observed ratio halfway between two null ratios well apart (no tie within round-off)
    gaps = np.flatnonzero(np.diff(lr_null) > 1e-5)
    i = int(gaps[int(quantile * (len(gaps) - 1))])
    lr_obs = float(lr_null[i] + lr_null[i + 1]) / 2.0
    expected_exceed = int(np.sum(lr_null >= lr_obs))
    p, used = Round._boxcox_bootstrap(Round.__new__(Round), _null_model(x, fitted, sd), orthonormal_basis(x),
                                      lr_obs, n_null, np.random.default_rng(seed))
    assert used == draws.shape[1] == n_null
    assert p == pytest.approx((expected_exceed + 1.0) / (n_null + 1.0), rel=1e-12)


@pytest.mark.parametrize("k, mean, sd", [(2, 2.0, 1.5), (2, 5.0, 0.5), (3, 10.0, 1.0)])
def test_a_response_whose_best_lambda_is_one_has_p_one(k, mean, sd):
    """LR = 0 is the least a ratio can be: every null draw reaches it, ties at 0 included (some draws' best
    lambda on the grid is 1 exactly, their ratio 0.0), so p = (B + 1) / (B + 1) = 1."""
    x = _design(k)
    fitted = mean + 0.3 * x[:, 1]
    n_null = 400
    draws, _ = _positive_draws(fitted, sd, n_null, 7)
    assert np.any(np.abs(_lr_by_least_squares(draws, x)) < 1e-8)  # the ties this test is about occur
    p, used = Round._boxcox_bootstrap(Round.__new__(Round), _null_model(x, fitted, sd), orthonormal_basis(x),
                                      0.0, n_null, np.random.default_rng(7))
    assert (p, used) == (1.0, n_null)


def test_a_tie_with_one_null_ratio_counts_it():
    """An observed ratio equal to a null draw's (to the last bit) is reached by that draw."""
    x = _design(2)
    fitted = 3.0 + 0.4 * x[:, 1]
    n_null = 200
    draws, _ = _positive_draws(fitted, 1.0, n_null, 11)
    lr_null = Round._boxcox_lr(draws, orthonormal_basis(x))
    np.testing.assert_allclose(lr_null, _lr_by_least_squares(draws, x), atol=1e-6)
    values = np.sort(np.unique(lr_null))
    lr_obs = float(values[len(values) // 2])
    p, _ = Round._boxcox_bootstrap(Round.__new__(Round), _null_model(x, fitted, 1.0), orthonormal_basis(x),
                                   lr_obs, n_null, np.random.default_rng(11))
    assert p == (np.sum(lr_null >= lr_obs) + 1.0) / (n_null + 1.0)


def test_an_observed_ratio_a_round_off_above_a_null_ratio_is_reached_by_it():
    """The observed ratio and the null ratios are computed in different batches, so a tie can differ in its last
    digits: an observed ratio 5e-10 above a null draw's (far below any real gap between draws) is still reached."""
    x = _design(2)
    fitted = 3.0 + 0.4 * x[:, 1]
    n_null = 200
    draws, _ = _positive_draws(fitted, 1.0, n_null, 11)
    lr_null = Round._boxcox_lr(draws, orthonormal_basis(x))
    values = np.sort(np.unique(lr_null))
    tied = float(values[len(values) // 2])
    assert np.min(np.abs(np.diff(values))) > 1e-6  # the draw it ties with is the only one within round-off
    p, _ = Round._boxcox_bootstrap(Round.__new__(Round), _null_model(x, fitted, 1.0), orthonormal_basis(x),
                                   tied + 5e-10, n_null, np.random.default_rng(11))
    assert p == (np.sum(lr_null >= tied) + 1.0) / (n_null + 1.0)


def test_no_positive_null_draw_gives_one_over_the_draws_tried():
    """A fitted null model that never yields an all-positive response: the positivity is the evidence."""
    x = _design(2)
    fitted = 0.2 + 0.0 * x[:, 1]
    n_null, batches = 50, 4
    draws, tried = _positive_draws(fitted, 1.0, n_null, 3, max_batches=batches)
    assert draws.size == 0 and tried == n_null * batches
    p, used = Round._boxcox_bootstrap(Round.__new__(Round), _null_model(x, fitted, 1.0), orthonormal_basis(x),
                                      1.0, n_null, np.random.default_rng(3), max_batches=batches)
    assert (p, used) == (1.0 / (tried + 1.0), 0)

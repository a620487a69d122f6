"""Every number a kriging surrogate answers, against a Gaussian process written out here with numpy (explicit
inverses, the trend's columns in another order, the leave-one-out residuals by refits without each run), over
generated inputs: 1-3 factors, some on a log scale, search ranges away from the origin, responses of either sign
and of scales 1e-3 to 1e3, a rescaled output (an own tolerance), chunked evaluation, planned new runs; and the
likelihood search's pick (within its bounds, no worse than where it started)."""

from __future__ import annotations

import json
from itertools import combinations_with_replacement

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.kriging import JITTER, LENGTH_BOUNDS, NUGGET_BOUNDS, STARTS, GaussianSystem, KrigingSurrogate, \
    fit_hyperparameters, quadratic_trend

_FAST = settings(max_examples=12, deadline=None, derandomize=True)


def _trend(u: np.ndarray) -> np.ndarray:
    """The full quadratic, its columns in another order than demid's (the fit does not depend on it)."""
    k = u.shape[1]
    cols = [np.ones(len(u))] + [u[:, i] * u[:, j] for i, j in combinations_with_replacement(range(k), 2)]
    return np.column_stack(cols + [u[:, i] for i in range(k)])


def _corr(a: np.ndarray, b: np.ndarray, lengths: np.ndarray) -> np.ndarray:
    out = np.empty((len(a), len(b)))
    for i, p in enumerate(a):
        for j, q in enumerate(b):
            d = np.sqrt(5.0) * np.sqrt(np.sum(((p - q) / lengths) ** 2))
            out[i, j] = (1.0 + d + d * d / 3.0) * np.exp(-d)
    return out


def _gp(u, z, lengths, nugget):
    """(predict-mean function, mean-variance function, sigma2) of the universal-kriging fit."""
    n = len(u)
    kinv = np.linalg.inv(_corr(u, u, lengths) + (nugget + JITTER) * np.eye(n))
    f = _trend(u)
    info_inv = np.linalg.inv(f.T @ kinv @ f)
    beta = info_inv @ f.T @ kinv @ z
    r = z - f @ beta
    sigma2 = float(r @ kinv @ r) / (n - f.shape[1])

    def mean(at):
        return _trend(at) @ beta + _corr(at, u, lengths) @ kinv @ r

    def variance(at):
        out = []
        for point in at:
            k = _corr(point[None, :], u, lengths)[0]
            gap = _trend(point[None, :])[0] - f.T @ kinv @ k
            out.append(max(1.0 - k @ kinv @ k + gap @ info_inv @ gap, 0.0))
        return np.array(out)

    return mean, variance, sigma2


def _study(k, extra, seed, log_mask, y_scale, y_shift):
    rng = np.random.default_rng(seed)
    n = (k + 1) * (k + 2) // 2 + extra
    lower = rng.uniform(-3.0, 3.0, k)
    upper = lower + rng.uniform(0.5, 4.0, k)
    log = tuple(f"f{i}" for i in range(k) if log_mask >> i & 1)
    u = rng.random((n, k))
    search = lower + u * (upper - lower)
    x = search.copy()
    for i in range(k):
        if f"f{i}" in log:
            x[:, i] = 10 ** search[:, i]
    y = y_shift + y_scale * (np.sin(2.5 * u).sum(axis=1) + np.cos(4 * u[:, 0]) + 0.05 * rng.standard_normal(n))
    lengths = rng.uniform(0.2, 1.2, k)
    nugget = float(rng.uniform(1e-3, 0.3))
    sur = KrigingSurrogate("y", [f"f{i}" for i in range(k)], x, y, lower, upper, lengths, nugget, log)
    at_u = rng.uniform(-0.2, 1.2, (7, k))
    at_x = lower + at_u * (upper - lower)
    for i in range(k):
        if f"f{i}" in log:
            at_x[:, i] = 10 ** at_x[:, i]
    return sur, u, y, lengths, nugget, at_u, at_x, rng


_STUDIES = dict(k=st.integers(1, 3), extra=st.integers(2, 7), seed=st.integers(0, 10_000),
                log_mask=st.integers(0, 7), y_scale=st.sampled_from([-1e3, -1.0, 1e-3, 2.0]),
                y_shift=st.sampled_from([-50.0, 0.0, 7.5]))


@_FAST
@given(**_STUDIES, target=st.floats(-10, 10), scale=st.sampled_from([-2.0, 0.3, 1.0, 4.0]))
def test_every_prediction_and_standard_error_matches_a_numpy_gaussian_process(k, extra, seed, log_mask, y_scale,
                                                                             y_shift, target, scale):
    sur, u, y, lengths, nugget, at_u, at_x, _ = _study(k, extra, seed, log_mask, y_scale, y_shift)
    centre, sd = y.mean(), y.std()
    mean, variance, sigma2 = _gp(u, (y - centre) / sd, lengths, nugget)
    assert sur.unit(at_x) == pytest.approx(at_u, rel=1e-9, abs=1e-9)
    predicted = centre + sd * mean(at_u)
    se = sd * np.sqrt(sigma2 * variance(at_u))
    assert sur.predict(at_x) == pytest.approx(predicted, rel=1e-7, abs=1e-7 * sd)
    assert sur.predict(at_x, chunk=2) == pytest.approx(predicted, rel=1e-7, abs=1e-7 * sd)
    assert sur.se_mean(at_x) == pytest.approx(se, rel=1e-5, abs=1e-9 * sd)
    assert sur.se_mean(at_x, chunk=3) == pytest.approx(se, rel=1e-5, abs=1e-9 * sd)
    assert sur.resid_var == pytest.approx(sd ** 2 * sigma2 * nugget, rel=1e-7)
    assert sur.se_prediction(at_x) == pytest.approx(np.sqrt(se ** 2 + sd ** 2 * sigma2 * nugget), rel=1e-5)
    assert sur.system.sigma2 == pytest.approx(sigma2, rel=1e-7)
    assert len(sur.predict(np.empty((0, k)))) == 0 and len(sur.se_mean(np.empty((0, k)))) == 0
    # an own tolerance: target + c (ŷ - target), errors times |c|; twice is the product of the two
    once = sur.rescaled(target, scale)
    assert once.predict(at_x) == pytest.approx(target + scale * (predicted - target), rel=1e-7, abs=1e-6 * sd)
    assert once.se_mean(at_x) == pytest.approx(abs(scale) * se, rel=1e-5, abs=1e-9 * sd)
    assert once.resid_var == pytest.approx(scale ** 2 * sd ** 2 * sigma2 * nugget, rel=1e-7)
    twice = once.rescaled(-target, 0.5)
    assert twice.predict(at_x) == pytest.approx(-target + 0.5 * (target + scale * (predicted - target) + target),
                                                rel=1e-7, abs=1e-6 * sd)
    assert twice.se_prediction(at_x) == pytest.approx(0.5 * abs(scale) * sur.se_prediction(at_x), rel=1e-7)


@_FAST
@given(**_STUDIES)
def test_leave_one_out_residuals_and_q2_are_those_of_refits_without_each_run(k, extra, seed, log_mask, y_scale,
                                                                            y_shift):
    sur, u, y, lengths, nugget, *_ = _study(k, extra, seed, log_mask, y_scale, y_shift)
    centre, sd = y.mean(), y.std()
    z = (y - centre) / sd
    residuals = []
    for i in range(len(u)):
        keep = np.arange(len(u)) != i
        mean, _, _ = _gp(u[keep], z[keep], lengths, nugget)
        residuals.append(sd * (z[i] - mean(u[i:i + 1])[0]))
    residuals = np.array(residuals)
    assert sur.loo_residuals == pytest.approx(residuals, rel=1e-5, abs=1e-8 * sd)
    q2 = 1.0 - np.sum(residuals ** 2) / np.sum((y - y.mean()) ** 2)
    assert sur.q2 == pytest.approx(q2, rel=1e-6, abs=1e-9)
    # Q² belongs to the fit, not to how its output is reported
    assert sur.rescaled(1.0, 3.0).q2 == pytest.approx(sur.q2, rel=1e-12)


@_FAST
@given(**_STUDIES, new=st.integers(1, 4))
def test_the_error_after_planned_runs_is_the_grown_designs_at_the_same_scale(k, extra, seed, log_mask, y_scale,
                                                                            y_shift, new):
    sur, u, y, lengths, nugget, at_u, at_x, rng = _study(k, extra, seed, log_mask, y_scale, y_shift)
    sd = y.std()
    _, _, sigma2 = _gp(u, (y - y.mean()) / sd, lengths, nugget)
    new_u = rng.random((new, k))
    new_x = sur.lower + new_u * (sur.upper - sur.lower)
    for i, f in enumerate(sur.factors):
        if f in sur.log_factors:
            new_x[:, i] = 10 ** new_x[:, i]
    _, grown_variance, _ = _gp(np.vstack([u, new_u]), np.zeros(len(u) + new), lengths, nugget)
    expected = sd * np.sqrt(sigma2 * grown_variance(at_u))
    assert sur.se_mean_after(at_x, new_x) == pytest.approx(expected, rel=1e-5, abs=1e-9 * sd)
    assert sur.rescaled(0.0, -2.0).se_mean_after(at_x, new_x) == pytest.approx(2.0 * expected, rel=1e-5,
                                                                                abs=1e-9 * sd)


def test_a_constant_response_is_standardised_by_one_and_has_no_q2():
    u = np.random.default_rng(3).random((9, 1))
    sur = KrigingSurrogate("y", ["a"], u, np.full(9, -4.0), np.zeros(1), np.ones(1), np.array([0.5]), 0.01)
    assert sur.y_center == -4.0 and sur.y_scale == 1.0
    assert np.isnan(sur.q2)


@given(k=st.integers(1, 2), extra=st.integers(3, 5), seed=st.integers(0, 10_000))
@settings(max_examples=3, deadline=None, derandomize=True)
def test_the_likelihood_search_stays_in_bounds_and_ends_no_worse_than_any_start(k, extra, seed):
    rng = np.random.default_rng(seed)
    n = (k + 1) * (k + 2) // 2 + extra
    u = rng.random((n, k))
    z = np.tanh(3 * (u[:, 0] - 0.5)) + 0.3 * u[:, -1] ** 3 + 0.02 * rng.standard_normal(n)
    z = (z - z.mean()) / z.std()
    lengths, nugget = fit_hyperparameters(u, z)
    assert lengths.shape == (k,)
    assert np.all((lengths >= LENGTH_BOUNDS[0] * (1 - 1e-9)) & (lengths <= LENGTH_BOUNDS[1] * (1 + 1e-9)))
    assert NUGGET_BOUNDS[0] * (1 - 1e-9) <= nugget <= NUGGET_BOUNDS[1] * (1 + 1e-9)
    best = GaussianSystem(u, z, lengths, nugget).restricted_nll()
    for length, start_nugget in STARTS:
        assert best <= GaussianSystem(u, z, np.full(k, length), start_nugget).restricted_nll() + 1e-9


def test_the_fitted_surrogate_stores_and_rebuilds_its_hyperparameters_exactly():
    rng = np.random.default_rng(11)
    x = rng.uniform([1.0, 10.0], [3.0, 1000.0], (10, 2))
    y = x[:, 0] ** 2 - np.log10(x[:, 1]) + 0.01 * rng.standard_normal(10)
    fitted = KrigingSurrogate.fit("y", ["a", "b"], x, y, [1.0, 1.0], [3.0, 3.0], log_factors=("b",))
    lengths, nugget = fit_hyperparameters(fitted.unit(x), (y - y.mean()) / y.std())
    assert np.array_equal(fitted.lengths, lengths) and fitted.nugget == nugget
    stored = json.loads(fitted.hyperparameters_json())
    assert stored == {"lengths": [float(v) for v in lengths], "nugget": float(nugget)}
    assert list(stored) == sorted(stored)
    rebuilt = KrigingSurrogate.from_hyperparameters("y", ["a", "b"], x, y, [1.0, 1.0], [3.0, 3.0],
                                                    fitted.hyperparameters_json(), log_factors=("b",))
    at = rng.uniform([1.0, 10.0], [3.0, 1000.0], (5, 2))
    assert np.array_equal(rebuilt.predict(at), fitted.predict(at))
    assert np.array_equal(rebuilt.se_prediction(at), fitted.se_prediction(at))
    assert rebuilt.log_factors == ("b",) and rebuilt.factors == ["a", "b"] and rebuilt.kind == "kriging"


@given(k=st.integers(1, 4))
@settings(max_examples=4, deadline=None, derandomize=True)
def test_the_trend_is_the_full_quadratic(k):
    u = np.random.default_rng(k).random((2 * (k + 1) * (k + 2), k))
    mine, theirs = _trend(u), quadratic_trend(u)
    assert theirs.shape == mine.shape
    # the same column space: each of demid's columns is one of these, and the columns are all distinct
    for column in theirs.T:
        assert min(np.max(np.abs(column - other)) for other in mine.T) == 0.0
    assert np.linalg.matrix_rank(theirs) == theirs.shape[1]

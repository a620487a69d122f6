"""Level 1's model fits (criticism.models.Model) over generated CCD tables and model forms (a Box-Cox transform or
none, run-order drift, excluded runs, variance weights on a factor): the likelihood, AICc, parameter count,
leverages and exact leave-one-out errors against a weighted least-squares fit written out with numpy and a refit
without each run."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import special, stats

from demid.criticism.models import Data, Model, ModelForm
from demid.design import Coding, ccd_points, model_matrix, quadratic_terms


def _data(seed: int, centre: int) -> Data:
    rng = np.random.default_rng(seed)
    coded = ccd_points(2, 1.41421, centre)
    runs = rng.permutation(len(coded)) + 1
    x = model_matrix(coded, quadratic_terms(2))
    y = np.exp(x @ rng.normal(scale=0.2, size=x.shape[1]) + 2.0 + rng.normal(scale=0.05, size=len(coded)))
    return Data("y", ["a", "b"], coded, y, runs, Coding(("a", "b"), (0.0, 0.0), (1.0, 1.0)), 1.41421, (),
                quadratic_terms(2))


def _wls(x, z, w):
    sw = np.sqrt(w)
    beta = np.linalg.lstsq(x * sw[:, None], z * sw, rcond=None)[0]
    return beta, (z - x @ beta) * sw


@given(seed=st.integers(0, 1000), lam=st.sampled_from([None, 0.0, 0.5, -1.0]), drift=st.booleans(),
       dropped=st.sampled_from([(), (2,), (0, 9)]), gamma=st.sampled_from([None, 0.7, -1.2]),
       centre=st.sampled_from([3, 8]))
@settings(max_examples=25, deadline=None, derandomize=True)
def test_a_models_likelihood_aicc_and_leave_one_out_errors_are_those_of_its_weighted_fit(seed, lam, drift, dropped,
                                                                                         gamma, centre):
    data = _data(seed, centre)
    weighted = gamma is not None
    form = ModelForm(drift=drift, dropped=dropped, lam=lam, weight_on="a" if weighted else None,
                     weight_gamma=gamma or 0.0, weight_values=tuple(data.coded[:, 0]) if weighted else ())
    model = Model(data, form)
    n = data.n
    keep = np.ones(n, dtype=bool)
    keep[list(dropped)] = False
    y = data.y[keep]
    z = y if lam is None else stats.boxcox(y, lmbda=lam)
    x = model_matrix(data.coded[keep], quadratic_terms(2))
    if drift:
        runs = data.runs.astype(float)
        x = np.column_stack([x, (runs[keep] - runs[keep].mean()) / max(np.ptp(runs), 1.0)])
    w = np.exp(-gamma * data.coded[keep, 0]) if weighted else np.ones(keep.sum())
    beta, resid_w = _wls(x, z, w)
    ssr = float(resid_w @ resid_w)
    ll = -0.5 * n * (np.log(2 * np.pi * ssr / n) + 1) + 0.5 * np.sum(np.log(w))
    if weighted and dropped:
        ll += 0.5 * np.sum(-gamma * data.coded[~keep, 0])
    if lam is not None:
        ll += (lam - 1) * np.sum(np.log(data.y))
    k = x.shape[1] + 1 + len(dropped) + int(lam is not None) + int(weighted)
    assert model.ssr == pytest.approx(ssr, rel=1e-9)
    assert model.loglik == pytest.approx(ll, rel=1e-10, abs=1e-9)
    assert model.n_params == k
    if n - k - 1 > 0:
        assert model.aicc == pytest.approx(-2 * ll + 2 * k * n / (n - k - 1), rel=1e-10, abs=1e-9)
    else:  # as many parameters as runs allow: no AICc
        assert np.isnan(model.aicc)
    xw = x * np.sqrt(w)[:, None]
    np.testing.assert_allclose(model.hat, np.diag(xw @ np.linalg.pinv(xw)), atol=1e-10)
    np.testing.assert_allclose(model.fitted, z_inv(x @ beta, lam), rtol=1e-9)
    loo = []
    for i in range(len(y)):
        others = np.arange(len(y)) != i
        b, _ = _wls(x[others], z[others], w[others])
        loo.append(y[i] - z_inv(x[i] @ b, lam))
    loo = np.array(loo)
    # where scipy's back-transform has no value (1 + lam z <= 0, far outside the data) the model's is clipped
    # finite; a run the others cannot predict (leverage near 1) has none
    predictable = np.diag(xw @ np.linalg.pinv(xw)) < 0.99
    compared = np.isfinite(loo) & predictable
    np.testing.assert_allclose(model.loo_errors[compared], loo[compared], rtol=1e-7, atol=1e-9 * np.abs(y).max())
    assert np.all(np.isfinite(model.loo_errors[predictable]))
    assert np.all(np.isnan(model.loo_errors[~predictable]))
    expected_predictable = np.zeros(n, dtype=bool)
    expected_predictable[keep] = predictable
    np.testing.assert_array_equal(model.predictable, expected_predictable)
    if compared.all():  # the leave-one-out RMSE over the runs it keeps and predicts
        assert model.loo_rmse_on(np.ones(n, dtype=bool)) == pytest.approx(
            np.sqrt(np.mean(np.square(loo[predictable]))), rel=1e-7)


def z_inv(z, lam):
    return z if lam is None else special.inv_boxcox(z, lam)


@given(seed=st.integers(0, 1000), dropped=st.sampled_from([(), (1,)]))
@settings(max_examples=5, deadline=None, derandomize=True)
def test_the_variance_covariates_are_the_factors_over_alpha_and_the_fitted_values_scaled_to_plus_minus_one(seed,
                                                                                                      dropped):
    from demid.criticism.catalogue import Round

    data = _data(seed, 3)
    model = Model(data, ModelForm(dropped=dropped))
    covariates = Round(data, model, 19, np.random.default_rng(seed)).covariates()
    assert list(covariates) == ["a", "b", "fitted"]
    for j, f in enumerate(("a", "b")):
        np.testing.assert_allclose(covariates[f], data.coded[model.keep, j] / data.alpha)
    fitted = covariates["fitted"]
    assert (fitted.min(), fitted.max()) == pytest.approx((-1.0, 1.0))
    np.testing.assert_allclose(fitted, -1 + 2 * (model.fitted_z - model.fitted_z.min()) / np.ptp(model.fitted_z),
                               atol=1e-12)


@given(seed=st.integers(0, 1000))
@settings(max_examples=3, deadline=None, derandomize=True)
def test_each_candidate_cause_pays_twice_the_log_of_the_places_it_chose_from(seed):
    """AICc + 2 log(choices): the alias classes a missing term, the covariates unequal scatter, the predictable
    runs an outlier, the change-points a step, the candidate slips a factor level was chosen from (1: none)."""
    import math

    from demid.criticism.catalogue import Round
    from demid.criticism.naming import candidate_entries
    from demid.criticism.slips import slip_candidates
    from demid.design import LEVERAGE_UNPREDICTABLE

    data = _data(seed, 3)
    base = Model(data, ModelForm())
    first = Round(data, base, 19, np.random.default_rng(seed))
    counted = {cause: sum(h.cause == cause for h in first.hypotheses) for cause in ("missing_term", "heteroscedasticity")}
    counted["outlier"] = int(np.sum(base.hat < LEVERAGE_UNPREDICTABLE))
    counted["factor_level"] = max(len(slip_candidates(data, base)), 1)
    steps = [h for h in first.hypotheses if h.cause == "step"]
    if steps:
        counted["step"] = int(steps[0].info["change_points"])
    entries = candidate_entries(data, base, first)
    assert {e["cause"] for e in entries} >= {"missing_term", "heteroscedasticity", "outlier"}
    for entry in entries:
        if "model" in entry:
            price = 2 * math.log(counted.get(entry["cause"], 1))
            assert entry["aicc"] - entry["model"].aicc == pytest.approx(price, abs=1e-9), entry["cause"]


@given(seed=st.integers(0, 1000), rank=st.integers(0, 4), zero_columns=st.integers(0, 2))
@settings(max_examples=30, deadline=None, derandomize=True)
def test_the_orthonormal_basis_spans_the_column_space_of_a_rank_deficient_matrix(seed, rank, zero_columns):
    """Orthonormal columns, as many as the rank, projecting every column of x onto itself (zero columns and
    products of a smaller basis included; a matrix of zeros has none)."""
    from demid.criticism.models import orthonormal_basis, residualize

    rng = np.random.default_rng(seed)
    x = rng.normal(size=(12, rank)) @ rng.normal(size=(rank, 5)) if rank else np.zeros((12, 5))
    x = np.column_stack([x, np.zeros((12, zero_columns))])
    q = orthonormal_basis(x)
    assert q.shape == (12, rank)
    np.testing.assert_allclose(q.T @ q, np.eye(rank), atol=1e-10)
    np.testing.assert_allclose(residualize(q, x), 0.0, atol=1e-9 * max(1.0, np.abs(x).max()))

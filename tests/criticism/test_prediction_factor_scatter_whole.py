"""A new run's response under scatter that grows along a factor (criticism.discrimination.new_run_prediction), on
CCDs whose axial distance is not 1: the mean and the variance against statsmodels' weighted least squares with the
model's own weights.  The variance is the estimation part x' cov x plus the run's scatter sigma^2 exp(gamma c), the
covariate c the factor's coded value over the axial distance, as the weights of the runs were made: so at every run
of the table the scatter is sigma^2 / w of that run, and from the axial point at -alpha to the one at +alpha the
standard deviation grows by the fitted ratio exp(gamma).  2-3 factors, either factor, three axial distances."""

from __future__ import annotations

import numpy as np
import pytest
import statsmodels.api as sm

from demid.criticism.catalogue import Hypothesis
from demid.criticism.discrimination import new_run_prediction
from demid.criticism.extensions import extend_for
from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm
from demid.design import model_matrix, quadratic_terms
from tests.generators import FACTORS, ccd_table


@pytest.mark.parametrize("k, which, alpha, seed", [(2, 0, 1.414213562373095, 1), (2, 1, 2.0, 4),
                                                   (3, 2, 1.6817928305074292, 2), (3, 0, 1.3, 7)])
def test_a_new_runs_variance_under_scatter_along_a_factor_against_weighted_least_squares(k, which, alpha, seed):
    factor = FACTORS[k][which]
    table, _ = ccd_table(seed, k, "het", 6.0, factor=factor, alpha=alpha)
    data, _ = prepare_data(table, FACTORS[k], "y", None, ())
    assert abs(data.alpha - alpha) < 1e-5  # the axial distance read back from the table's levels
    alpha = data.alpha
    spec, info = extend_for(data, Model(data, ModelForm()), Hypothesis("heteroscedasticity", factor))
    model = Model(data, spec)
    gamma = spec.weight_gamma
    assert abs(gamma) > 0.1
    # the weights the fit gives the runs, written out: scatter sd exp(gamma c / 2), c = x / alpha in [-1, 1]
    coded = data.coded[:, which]
    weights = np.exp(-gamma * coded / alpha)
    np.testing.assert_allclose(model.w, weights, rtol=1e-12)
    x = model_matrix(data.coded, quadratic_terms(k))
    wls = sm.WLS(data.y, x, weights=weights).fit()
    rng = np.random.default_rng(seed)
    new = rng.uniform(-alpha, alpha, (6, k))
    axial = np.zeros((2, k))
    axial[:, which] = [-alpha, alpha]
    points = np.vstack([data.coded, new, axial])
    rows = model_matrix(points, quadratic_terms(k))
    scatter = wls.scale * np.exp(gamma * points[:, which] / alpha)
    mean, var = new_run_prediction(model, points)
    np.testing.assert_allclose(mean, rows @ wls.params, rtol=1e-9, atol=1e-9 * np.abs(data.y).max())
    np.testing.assert_allclose(var, np.einsum("ij,jk,ik->i", rows, wls.cov_params(), rows) + scatter, rtol=1e-8)
    # at the runs themselves the scatter is sigma^2 / w; across the axial points it grows by exp(gamma)
    at_runs = var[:len(data.y)] - np.einsum("ij,jk,ik->i", x, wls.cov_params(), x)
    np.testing.assert_allclose(at_runs, wls.scale / model.w, rtol=1e-7)
    lo, hi = var[-2:] - np.einsum("ij,jk,ik->i", rows[-2:], wls.cov_params(), rows[-2:])
    np.testing.assert_allclose(np.sqrt(hi / lo), info["sd_ratio"], rtol=1e-9)

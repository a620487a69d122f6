"""A new run's scatter under unequal scatter along the predicted value, on runs made in blocks
(criticism.discrimination.prediction_parts): at a new point the covariate is the quadratic's prediction with the
blocks at their average, scaled as the runs' covariate was (the kept runs' fitted values, block effects included,
span -1 to 1), and the noise is sigma^2 exp(gamma covariate).  Against statsmodels' OLS with one effect-coded
column per later block (their average is 0 at a new run); two and three blocks, the runs' own points and new ones."""

from __future__ import annotations

import numpy as np
import pytest
import statsmodels.api as sm

from demid.criticism.catalogue import Hypothesis
from demid.criticism.discrimination import prediction_parts
from demid.criticism.extensions import extend_for
from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm
from demid.design import model_matrix, quadratic_terms
from tests.generators import FACTORS, ccd_table


@pytest.mark.parametrize("n_blocks", [2, 3])
@pytest.mark.parametrize("seed", [0, 3])
def test_a_new_runs_scatter_follows_the_prediction_with_the_blocks_at_their_average(n_blocks, seed):
    table, _ = ccd_table(seed, 2, "clean", 0.0)
    block = np.minimum((table["run"].to_numpy() - 1) * n_blocks // len(table), n_blocks - 1)
    table["y"] += 7.0 * block
    table["block"] = [f"wave {b + 1}" for b in block]
    data, _ = prepare_data(table, FACTORS[2], "y", None, ())
    base = Model(data, ModelForm())
    spec, _ = extend_for(data, base, Hypothesis("heteroscedasticity", "fitted"))
    model = Model(data, spec)
    # the runs' covariate: statsmodels' fit with effect-coded block columns (each later block +1, the first -1)
    effect = np.where(block[:, None] == 0, -1.0, (block[:, None] == np.arange(1, n_blocks)[None, :]).astype(float))
    x = np.column_stack([model_matrix(data.coded, quadratic_terms(2)), effect])
    fit = sm.OLS(data.y, x).fit()
    lo, hi = fit.fittedvalues.min(), fit.fittedvalues.max()
    points = np.vstack([data.coded[:5], [[0.3, -0.7], [1.2, 0.4], [-1.0, -1.0]]])
    at_points = model_matrix(points, quadratic_terms(2)) @ fit.params[:6]  # the blocks' average effect is 0
    covariate = (at_points - (hi + lo) / 2) / ((hi - lo) / 2)
    _, _, noise, _ = prediction_parts(model, points)
    sigma2 = model.ssr / model.df_resid
    np.testing.assert_allclose(noise, sigma2 * np.exp(spec.weight_gamma * covariate), rtol=1e-7)
    assert spec.weight_gamma != 0.0

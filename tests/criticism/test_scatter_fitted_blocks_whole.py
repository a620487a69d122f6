"""Unequal scatter that follows the predicted value, on runs made in blocks (criticism.extensions.extend_for): the
covariate of every run, the excluded one too, is the quadratic's prediction with its block's effect, scaled so that
the kept runs span -1 to 1 -- against a least-squares fit with one column per block written out with numpy; two and
three blocks, with and without an excluded run; and on a model that carries a drift or a step, the kept runs'
covariate is the tested one, the fitted values with their run-order part."""

from __future__ import annotations

import numpy as np
import pytest

from demid.criticism.catalogue import Hypothesis
from demid.criticism.extensions import extend_for
from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm
from demid.design import model_matrix, quadratic_terms
from tests.generators import FACTORS, ccd_table


@pytest.mark.parametrize("n_blocks", [2, 3])
@pytest.mark.parametrize("dropped", [(), (2,)])
@pytest.mark.parametrize("seed", [0, 1])
def test_the_predicted_value_covariate_carries_each_runs_block_effect(n_blocks, dropped, seed):
    table, _ = ccd_table(seed, 2, "clean", 0.0)
    block = np.minimum((table["run"].to_numpy() - 1) * n_blocks // len(table), n_blocks - 1)
    table["y"] += 7.0 * block  # each later block shifted
    table["block"] = [f"wave {b + 1}" for b in block]
    data, _ = prepare_data(table, FACTORS[2], "y", None, ())
    assert data.blocks is not None and data.blocks.shape[1] == n_blocks - 1
    model = Model(data, ModelForm(dropped=dropped))
    spec, _ = extend_for(data, model, Hypothesis("heteroscedasticity", "fitted"))
    kept = np.setdiff1d(np.arange(data.n), dropped)
    onehot = (block[:, None] == np.arange(1, n_blocks)[None, :]).astype(float)  # later blocks against the first
    x = np.column_stack([model_matrix(data.coded, quadratic_terms(2)), onehot])
    beta = np.linalg.lstsq(x[kept], data.y[kept], rcond=None)[0]
    fitted = x @ beta
    lo, hi = fitted[kept].min(), fitted[kept].max()
    expected = (fitted - (hi + lo) / 2) / ((hi - lo) / 2)
    np.testing.assert_allclose(spec.weight_values, expected, rtol=1e-8, atol=1e-9)
    assert spec.weight_on == "fitted"
    assert min(spec.weight_values[i] for i in kept) == pytest.approx(-1.0) and \
        max(spec.weight_values[i] for i in kept) == pytest.approx(1.0)


@pytest.mark.parametrize("run_order", ["drift", "step"])
@pytest.mark.parametrize("n_blocks", [2, 3])
def test_after_a_run_order_cause_the_kept_runs_covariate_is_the_tested_predicted_value(run_order, n_blocks):
    """On a model that already carries a drift or a step (an earlier finding), the kept runs' covariate is the one
    the catalogue tests (Round.covariates: the fitted values, run order included, spanning -1 to 1); the excluded
    run's is its prediction with its block's effect at the average run."""
    table, _ = ccd_table(3, 2, "clean", 0.0)
    block = np.minimum((table["run"].to_numpy() - 1) * n_blocks // len(table), n_blocks - 1)
    table["y"] += 5.0 * block + 0.4 * table["run"].to_numpy()
    table["block"] = [f"wave {b + 1}" for b in block]
    data, _ = prepare_data(table, FACTORS[2], "y", None, ())
    dropped, step = (4,), 6
    form = ModelForm(dropped=dropped, drift=True) if run_order == "drift" else ModelForm(dropped=dropped, step=step)
    model = Model(data, form)
    spec, _ = extend_for(data, model, Hypothesis("heteroscedasticity", "fitted"))
    kept = np.setdiff1d(np.arange(data.n), dropped)
    runs = data.runs.astype(float)
    order = runs if run_order == "drift" else (runs >= runs[step]).astype(float)
    order = order - order[kept].mean()  # 0 at the average kept run
    onehot = (block[:, None] == np.arange(1, n_blocks)[None, :]).astype(float)
    x = np.column_stack([model_matrix(data.coded, quadratic_terms(2)), onehot, order])
    beta = np.linalg.lstsq(x[kept], data.y[kept], rcond=None)[0]
    fitted = x[kept] @ beta
    lo, hi = fitted.min(), fitted.max()
    np.testing.assert_allclose(np.array(spec.weight_values)[kept], (fitted - (hi + lo) / 2) / ((hi - lo) / 2),
                               rtol=1e-8, atol=1e-9)
    at_average_run = x[dropped[0], :-1] @ beta[:-1]
    assert spec.weight_values[dropped[0]] == pytest.approx((at_average_run - (hi + lo) / 2) / ((hi - lo) / 2),
                                                           rel=1e-8, abs=1e-9)

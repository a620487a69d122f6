"""A new run's predicted response and its variance under a level-1 model with blocks, drift or a step
(criticism.models.Model.new_run_row through discrimination.new_run_prediction), against statsmodels' OLS on the
raw columns: the blocks effect-coded (their average, 0 in every column, at a new run), the drift as the raw run
number (a new run ``later`` runs after the last, the next one unless said otherwise), the step as 0/1 (a new run
is after it).  The model's centring and scaling of its run-order columns must not change what it predicts; 2 and 3
factors, 1-3 blocks."""
from __future__ import annotations

import numpy as np
import pytest
import statsmodels.api as sm

from demid.criticism.discrimination import new_run_prediction, prediction_parts
from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm
from demid.design import model_matrix, quadratic_terms
from tests.generators import FACTORS, ccd_table

# (factors, blocks, drift, step halfway through the runs, seed); a step at a block boundary would be the block
CASES = [(2, 1, True, False, 0), (2, 2, False, False, 1), (2, 3, True, False, 2), (3, 1, False, True, 3),
         (2, 3, False, True, 4), (3, 3, False, False, 5)]


def _table(k, n_blocks, seed):
    table, _ = ccd_table(seed, k, "clean", 0.0)
    rng = np.random.default_rng(seed)
    table["y"] += 0.3 * table["run"] + rng.normal(scale=0.5, size=len(table))  # a trend the drift can take
    if n_blocks > 1:
        block = np.minimum((table["run"].to_numpy() - 1) * n_blocks // len(table), n_blocks - 1)
        table["y"] += 5.0 * block
        table["block"] = [f"w{b}" for b in block]
    return table


@pytest.mark.parametrize("k, n_blocks, drift, step, seed", CASES)
def test_a_new_runs_prediction_and_variance_are_the_ols_ones_with_blocks_at_their_average(k, n_blocks, drift, step,
                                                                                            seed):
    table = _table(k, n_blocks, seed)
    data, _ = prepare_data(table, FACTORS[k], "y", None, ())
    runs = data.runs.astype(float)
    order = np.argsort(runs)
    first_after = int(order[len(order) // 2]) if step else None
    model = Model(data, ModelForm(drift=drift, step=first_after))
    cols = [model_matrix(data.coded, quadratic_terms(k))]
    if data.blocks is not None:
        labels = np.asarray(data.block_labels, dtype=object)
        levels = sorted(set(labels))
        effect = np.column_stack([(labels == lv).astype(float) - (labels == levels[-1]) for lv in levels[:-1]])
        cols.append(effect)
    if drift:
        cols.append(runs)
    if step:
        cols.append((runs >= runs[first_after]).astype(float))
    fit = sm.OLS(data.y, np.column_stack(cols)).fit()
    rng = np.random.default_rng(seed)
    points = np.vstack([data.coded[:3], rng.uniform(-1.0, 1.0, (3, k))])
    for later in (1, 3):
        new = [model_matrix(points, quadratic_terms(k))]
        if data.blocks is not None:
            new.append(np.zeros((len(points), len(levels) - 1)))
        if drift:
            new.append(np.full((len(points), 1), runs.max() + later))
        if step:
            new.append(np.ones((len(points), 1)))
        x0 = np.column_stack(new)
        mean, var = new_run_prediction(model, points, later)
        np.testing.assert_allclose(mean, x0 @ fit.params, rtol=1e-9, atol=1e-9 * np.ptp(data.y))
        want_var = np.einsum("ij,jk,ik->i", x0, fit.cov_params(), x0) + fit.scale
        np.testing.assert_allclose(var, want_var, rtol=1e-7)
        if later == 1:  # a new run not said to be later is the next one
            np.testing.assert_allclose(prediction_parts(model, points)[0], mean, rtol=1e-12)

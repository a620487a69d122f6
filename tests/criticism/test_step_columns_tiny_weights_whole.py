"""The step cause's change-points and unit step columns (criticism.step_changes.step_direction_chunks, step_starts,
step_projections) on weighted fits whose weights are all far below or above one (exp(-gamma v) with v a factor
shifted by +-40): a change-point is dropped only when its step column lies in the model's span relative to the
column's own length, so the same change-points are tested whatever the weights' overall scale.  Against step
columns built one by one and residualised by least squares, chunk by chunk."""

from __future__ import annotations

import numpy as np
import pytest

from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm
from demid.criticism.step_changes import (STEP_MIN_RUNS, step_direction_chunks, step_projections,
                                          step_starts)
from tests.criticism.test_large_studies import _table


def _unit_steps(model):
    """(first run of each change-point, its unit residualised step column), built one by one."""
    kept = np.flatnonzero(model.keep)
    labels = model.data.runs[kept].astype(float)
    order = np.argsort(labels, kind="stable")
    x = model.xw
    starts, cols = [], []
    for c in range(STEP_MIN_RUNS, len(kept) - STEP_MIN_RUNS + 1):
        after = (labels >= labels[order[c]]).astype(float)
        col = (after - after.mean()) * model.sw
        r = col - x @ np.linalg.lstsq(x, col, rcond=None)[0]
        if np.linalg.norm(r) > 1e-6 * np.linalg.norm(col):
            starts.append(int(kept[order[c]]))
            cols.append(r / np.linalg.norm(r))
    return starts, np.column_stack(cols)


@pytest.mark.parametrize("n,shift,gamma,size", [(24, 40.0, 1.0, 5), (31, -40.0, 1.0, 7), (20, 40.0, 0.9, 100),
                                                (27, 0.0, -1.2, 4)])
def test_change_points_and_unit_columns_whatever_the_weights_scale(n, shift, gamma, size):
    data, _ = prepare_data(_table(n, n, "scatter"), ["a", "b"], "y", 1.0, (), None)
    form = ModelForm(dropped=(1,), weight_on="a", weight_gamma=gamma,
                     weight_values=tuple(data.coded[:, 0] + shift))
    model = Model(data, form)
    assert np.all((model.w < 1e-15) | (model.w > 1e15)) == (shift != 0.0)
    q = np.linalg.svd(model.xw, full_matrices=False)[0]
    expected_starts, expected_cols = _unit_steps(model)
    assert len(expected_starts) == (n - 1) - 2 * STEP_MIN_RUNS + 1  # no block: every change-point is tested
    chunks = list(step_direction_chunks(model, q, size))
    assert [len(s) for s, _ in chunks] == [min(size, len(expected_starts) - i)
                                            for i in range(0, len(expected_starts), size)]
    starts = [s for chunk, _ in chunks for s in chunk]
    assert starts == expected_starts == step_starts(model, q)
    cols = np.column_stack([c for _, c in chunks])
    np.testing.assert_allclose(np.abs(np.sum(cols * expected_cols, axis=0)), 1.0, atol=1e-8)
    e = np.column_stack([model.resid_w, np.random.default_rng(n).standard_normal(len(model.y))])
    proj_starts, proj = step_projections(model, q, e)
    assert proj_starts == expected_starts
    np.testing.assert_allclose(proj, expected_cols.T @ e, rtol=1e-7,
                               atol=1e-9 * float(np.max(np.abs(expected_cols.T @ e))))

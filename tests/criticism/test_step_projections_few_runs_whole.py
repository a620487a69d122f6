"""The step cause's change-points (criticism.step_changes.step_projections) on fits with 2 to 8 kept runs: no
change-point below 2 * STEP_MIN_RUNS runs, an empty (0, B) projection for B residual columns, and from there on
the change-points and projections against step columns built one by one and residualised by least squares."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm
from demid.criticism.step_changes import STEP_MIN_RUNS, step_projections, step_starts
from tests.criticism.test_large_studies import _table
from tests.criticism.test_step_changes_whole import _brute_force


@pytest.mark.parametrize("kept", [2, 3, 4, 5, 8])
@pytest.mark.parametrize("columns", [1, 3])
def test_few_kept_runs_give_the_change_points_of_a_brute_force(kept, columns):
    data, _ = prepare_data(_table(20, 3), ["a", "b"], "y", 1.0, (), None)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # a saturated fit of a few runs is rank-deficient on purpose
        model = Model(data, ModelForm(dropped=tuple(range(20 - kept))))
    q = np.linalg.svd(model.xw, full_matrices=False)[0]
    q = q[:, :np.linalg.matrix_rank(model.xw)]
    e = np.random.default_rng(kept).standard_normal((kept, columns))
    starts, proj = step_projections(model, q, e)
    positions = range(STEP_MIN_RUNS, kept - STEP_MIN_RUNS + 1)
    expected_starts, expected = _brute_force(model, model.xw, e, positions)
    assert starts == expected_starts
    assert proj.shape == (len(expected_starts), columns)
    if expected:
        np.testing.assert_allclose(proj, np.array(expected), atol=1e-10)
    assert starts == step_starts(model, q)
    if kept < 2 * STEP_MIN_RUNS:
        assert starts == []

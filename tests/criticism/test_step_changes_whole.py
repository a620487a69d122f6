"""The step cause's change-points (criticism.step_changes) over generated tables: weighted fits, excluded runs,
tied run labels, 20 to 20,000 runs.  The change-points and projections from running sums against step columns
built one by one and residualised by least squares, and the change-points next to either end of a very long
table kept (a step over the last two runs is as testable there as in a short table)."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm
from demid.criticism.step_changes import STEP_MIN_RUNS, step_projections, step_starts
from tests.criticism.test_large_studies import _table


def _brute_force(model: Model, x: np.ndarray, e: np.ndarray, positions) -> tuple[list[int], list[np.ndarray]]:
    """Change-points at the given positions in run order: each step column (indicator of the runs at or after
    it, less its mean, times the weights' root) residualised on the weighted model matrix by least squares."""
    kept = np.flatnonzero(model.keep)
    labels = model.data.runs[kept].astype(float)
    order = np.argsort(labels, kind="stable")
    starts, projections = [], []
    for c in positions:
        after = (labels >= labels[order[c]]).astype(float)
        col = (after - after.mean()) * model.sw
        r = col - x @ np.linalg.lstsq(x, col, rcond=None)[0]
        if np.linalg.norm(r) > 1e-6 * np.linalg.norm(col):
            starts.append(int(kept[order[c]]))
            projections.append(r @ e / np.linalg.norm(r))
    return starts, projections


@given(seed=st.integers(0, 10 ** 4), n=st.integers(20, 60), gamma=st.sampled_from([None, 0.8, -1.5]),
       dropped=st.sampled_from([(), (1,), (0, 7)]))
@settings(max_examples=12, deadline=None, derandomize=True)
def test_projections_on_weighted_step_columns_equal_those_built_one_by_one(seed, n, gamma, dropped):
    data, _ = prepare_data(_table(n, seed, "scatter"), ["a", "b"], "y", 1.0, (), None)
    form = ModelForm(dropped=dropped) if gamma is None else ModelForm(
        dropped=dropped, weight_on="a", weight_gamma=gamma, weight_values=tuple(data.coded[:, 0]))
    model = Model(data, form)
    q = np.linalg.svd(model.xw, full_matrices=False)[0]
    e = np.column_stack([model.resid_w, np.random.default_rng(seed).standard_normal((len(model.y), 2))])
    starts, proj = step_projections(model, q, e)
    kept = len(model.y)
    expected_starts, expected = _brute_force(model, model.xw, e, range(STEP_MIN_RUNS, kept - STEP_MIN_RUNS + 1))
    assert starts == expected_starts
    np.testing.assert_allclose(proj, np.array(expected), atol=1e-10)
    assert sorted(set(starts)) == sorted(set(step_starts(model, q)))


def test_a_long_table_keeps_the_change_points_next_to_either_end():
    n = 20000
    data, _ = prepare_data(_table(n, 0), ["a", "b"], "y", 1.0, (), None)
    model = Model(data, ModelForm())
    q = np.linalg.svd(model.xw, full_matrices=False)[0]
    e = model.resid_w[:, None]
    starts, proj = step_projections(model, q, e)
    edges = [*range(STEP_MIN_RUNS, STEP_MIN_RUNS + 3), *range(n - STEP_MIN_RUNS - 2, n - STEP_MIN_RUNS + 1)]
    expected_starts, expected = _brute_force(model, model.xw, e, edges)
    assert len(starts) == n - 2 * STEP_MIN_RUNS + 1  # every change-point of the run order is a candidate
    assert starts[:3] + starts[-3:] == expected_starts
    np.testing.assert_allclose(np.concatenate([proj[:3], proj[-3:]]), np.array(expected), rtol=1e-8, atol=1e-10)

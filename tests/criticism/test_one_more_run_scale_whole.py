"""The separating runs' state (criticism.aliasing.OneMoreRun.of) on a base model the runs cannot estimate: which
candidates lie off the row space of the base matrix X (``outside``: a new run there adds a base direction) and the
prediction error z - B'x of the others, against numpy's pseudo-inverse, for candidates in the row space scaled from
1 to 1e12 (round-off in the projection grows with the candidate's norm: the threshold is relative to it) and
candidates that leave it by a tenth, a thousandth or a millionth of their norm."""

from __future__ import annotations

import numpy as np
import pytest

from demid.criticism.aliasing import OneMoreRun
from demid.design import model_matrix, quadratic_terms


def _factorial_with_centre(k):
    corners = np.array(np.meshgrid(*[[-1.0, 1.0]] * k, indexing="ij")).reshape(k, -1).T
    return np.vstack([corners, np.zeros((1, k))])


@pytest.mark.parametrize("k", [2, 3])
def test_candidates_in_and_off_the_row_space_at_every_scale(k):
    coded = _factorial_with_centre(k)
    base = quadratic_terms(k)
    x = model_matrix(coded, base)
    assert np.linalg.matrix_rank(x) < x.shape[1]  # the squares share one column: X is rank-deficient
    rng = np.random.default_rng(k)
    # a direction orthogonal to the row space (the null space of X), of unit norm
    _, s, vt = np.linalg.svd(x)
    null = vt[np.linalg.matrix_rank(x):][0]
    rows, expect_out = [], []
    for scale in (1.0, 1e3, 1e6, 1e12):
        inside = scale * (rng.uniform(-1, 1, len(x)) @ x)          # a combination of the design's rows
        rows.append(inside)
        expect_out.append(False)
        for share in (1e-1, 1e-3, 1e-6):
            rows.append(inside + share * np.linalg.norm(inside) * null)
            expect_out.append(True)
    cand_base = np.array(rows)
    members_terms = [tuple(3 if j == i else 0 for j in range(k)) for i in range(k)]
    cols = model_matrix(coded, members_terms)
    cand_members = rng.normal(size=(len(rows), len(members_terms)))
    state = OneMoreRun.of(coded, base, members_terms, cand_base, cand_members)
    np.testing.assert_array_equal(state.outside, np.array(expect_out))
    pinv = np.linalg.pinv(x)
    error = cand_members - cand_base @ (pinv @ cols)
    error[np.array(expect_out)] = 0.0
    scale = np.maximum(np.abs(cand_members), np.abs(cand_base @ (pinv @ cols)))
    assert np.all(np.abs(state.error - error) <= 1e-9 * np.maximum(scale, 1.0))
    resid = cols - x @ (pinv @ cols)
    np.testing.assert_allclose(state.current, resid.T @ resid, atol=1e-10)
    assert state.column_ss == pytest.approx(float(np.sum(cols * cols)), rel=1e-14)

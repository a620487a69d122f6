"""The separating runs' state (criticism.aliasing.OneMoreRun.of) judges the design's rank relative to its largest
singular value, as numpy's pseudo-inverse with a relative cut-off does: a design written in large units (levels of
about ±12,000, squares of about 1.5e8) whose squares share one column stays rank-deficient, although the round-off
left in that column's singular value (about 1e-8) is far above an absolute 1e-10.  The candidates' errors z - B'x and
which of them leave the row space are checked against the pseudo-inverse at every scale."""

from __future__ import annotations

import numpy as np
import pytest

from demid.criticism.aliasing import OneMoreRun
from demid.design import model_matrix, quadratic_terms


def _shifted_factorial(k, scale):
    """A two-level factorial with two centre runs, levels scale * (0.1 +- 1): its squares share one column."""
    corners = np.array(np.meshgrid(*[[-1.0, 1.0]] * k, indexing="ij")).reshape(k, -1).T
    return scale * (np.vstack([corners, np.zeros((2, k))]) + 0.1)


@pytest.mark.parametrize("k, scale", [(2, 1.0), (2, 123.4567), (2, 12345.67), (3, 1.0), (3, 12345.67)])
def test_rank_is_judged_relative_to_the_design_at_every_scale(k, scale):
    coded = _shifted_factorial(k, scale)
    base = quadratic_terms(k)
    x = model_matrix(coded, base)
    s = np.linalg.svd(x, compute_uv=False)
    rank = int(np.sum(s > s[0] * 1e-10))
    assert rank < x.shape[1]  # the squares coincide: X cannot estimate the quadratic
    rng = np.random.default_rng(k)
    _, _, vt = np.linalg.svd(x)
    null = vt[rank]  # a unit direction off the row space
    inside = (rng.uniform(-1, 1, (4, len(x))) @ x)  # combinations of the design's rows
    cand_base = np.vstack([inside, inside[:2] + 1e-3 * np.linalg.norm(inside[:2], axis=1)[:, None] * null])
    expect_out = np.array([False] * 4 + [True] * 2)
    members = [tuple(3 if j == i else 0 for j in range(k)) for i in range(k)]
    cols = model_matrix(coded, members)
    cand_members = rng.normal(size=(len(cand_base), len(members))) * scale ** 3
    state = OneMoreRun.of(coded, base, members, cand_base, cand_members)
    assert state.outside is not None
    np.testing.assert_array_equal(state.outside, expect_out)
    pinv = np.linalg.pinv(x, rcond=1e-10)
    fitted = cand_base @ (pinv @ cols)
    expected = np.where(expect_out[:, None], 0.0, cand_members - fitted)
    size = np.maximum(np.abs(cand_members), np.abs(fitted))
    assert np.all(np.abs(state.error - expected) <= 1e-7 * np.maximum(size, 1.0))
    np.testing.assert_allclose(state.leverage[~expect_out],
                               np.einsum("ij,jk,ik->i", cand_base, pinv @ pinv.T, cand_base)[~expect_out],
                               rtol=1e-6)

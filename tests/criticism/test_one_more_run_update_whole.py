"""The separating runs' running state (criticism.aliasing.OneMoreRun) after a run joins the design: the rank-one
update of with_run against the state built afresh from the design with that run (OneMoreRun.of) -- (X'X)^-1, each
candidate's leverage and prediction error, the members' residual cross-product, the members' sum of squares that
sets the rank's floor -- and the criteria (rank and log pseudo-determinant of every candidate) that follow, over
2-3 factor CCDs, one to three runs added in turn, 1-3 third-order members."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from demid.criticism.aliasing import OneMoreRun, candidate_points
from demid.design import ccd_points, model_matrix, quadratic_terms


def _cubic_terms(k):
    return [t for t in itertools.product(range(4), repeat=k) if sum(t) == 3]


@pytest.mark.parametrize("k,n_members,picks", [(2, 1, (5,)), (2, 2, (3, 40, 17)), (3, 3, (100, 7)),
                                               (3, 1, (200, 201, 5))])
def test_a_run_added_by_update_is_the_design_rebuilt_with_it(k, n_members, picks):
    alpha = float((2 ** k) ** 0.25)
    coded = ccd_points(k, alpha, 2)
    base, members = quadratic_terms(k), _cubic_terms(k)[:n_members]
    cands = candidate_points(k, alpha)
    cand_base, cand_members = model_matrix(cands, base), model_matrix(cands, members)
    state = OneMoreRun.of(coded, base, members, cand_base, cand_members)
    assert state.outside is None  # a CCD estimates its quadratic: the update path
    for index in picks:
        state = state.with_run(index, cands[index], base, members)
        coded = np.vstack([coded, cands[index]])
        fresh = OneMoreRun.of(coded, base, members, cand_base, cand_members)
        assert state.column_ss == pytest.approx(fresh.column_ss, rel=1e-12)
        assert state.column_ss == pytest.approx(float(np.sum(model_matrix(coded, members) ** 2)), rel=1e-12)
        np.testing.assert_allclose(state.inverse, fresh.inverse, rtol=1e-8, atol=1e-10)
        np.testing.assert_allclose(state.leverage, fresh.leverage, rtol=1e-8, atol=1e-10)
        np.testing.assert_allclose(state.error, fresh.error, rtol=1e-8, atol=1e-9)
        np.testing.assert_allclose(state.current, fresh.current, rtol=1e-8, atol=1e-9)
        ranks, logdets = state.criteria()
        fresh_ranks, fresh_logdets = fresh.criteria()
        np.testing.assert_array_equal(ranks, fresh_ranks)
        np.testing.assert_allclose(logdets, fresh_logdets, rtol=1e-7, atol=1e-7)

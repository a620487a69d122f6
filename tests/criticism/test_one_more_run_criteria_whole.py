"""The separating runs' criteria (criticism.aliasing.OneMoreRun.criteria) for every candidate run at once against the
design rebuilt with that candidate, one at a time: the rank of the members' residual cross-product Z'(I - P_X)Z and
its log pseudo-determinant (least squares and eigenvalues written out here), both for candidates that raise the rank
and for those that only enlarge it within its range (where the members are already estimable, or along the one
direction already there)."""

from __future__ import annotations

import numpy as np
import pytest

from demid.criticism.aliasing import OneMoreRun, candidate_points
from demid.design import ccd_points, model_matrix, quadratic_terms


def _by_hand(coded, base, members):
    """(rank, log pseudo-determinant) of Z'(I - P_X)Z, eigenvalues above 1e-12 of the members' sum of squares."""
    x, z = model_matrix(coded, base), model_matrix(coded, members)
    resid = z - x @ np.linalg.lstsq(x, z, rcond=None)[0]
    ev = np.linalg.eigvalsh(resid.T @ resid)
    keep = ev > np.sum(z * z) * 1e-12
    return int(keep.sum()), float(np.sum(np.log(ev[keep])))


@pytest.mark.parametrize("k, members, centre", [(2, [(3, 0)], 3), (2, [(3, 0), (1, 2)], 2),
                                                (2, [(0, 3), (2, 1), (1, 2)], 3), (3, [(1, 1, 1), (3, 0, 0)], 2)])
def test_each_candidates_rank_and_log_determinant_are_the_design_rebuilt_with_it(k, members, centre):
    alpha = float((2 ** k) ** 0.25)
    coded = ccd_points(k, alpha, centre)
    base = quadratic_terms(k)
    cands = candidate_points(k, alpha)
    state = OneMoreRun.of(coded, base, members, model_matrix(cands, base), model_matrix(cands, members))
    ranks, logdets = state.criteria()
    rng = np.random.default_rng(k + len(members))
    for c in rng.choice(len(cands), size=min(len(cands), 25), replace=False):
        rank, logdet = _by_hand(np.vstack([coded, cands[c]]), base, members)
        assert ranks[c] == rank
        assert logdets[c] == pytest.approx(logdet, rel=1e-7, abs=1e-7)


def test_a_candidate_that_leaves_the_members_inestimable_has_no_log_determinant():
    """A face-centred CCD, whose levels -1, 0, 1 make a^3 the column a: the cubic is not estimable (rank 0), a
    candidate at a = +-0.5 makes it so (rank 1) and any other leaves it at rank 0, whose log pseudo-determinant is
    -inf (no direction to measure), as for the design rebuilt with that candidate."""
    coded = ccd_points(2, 1.0, 3)
    base, members = quadratic_terms(2), [(3, 0)]
    cands = candidate_points(2, 1.0)
    state = OneMoreRun.of(coded, base, members, model_matrix(cands, base), model_matrix(cands, members))
    ranks, logdets = state.criteria()
    for c in range(len(cands)):
        rank, logdet = _by_hand(np.vstack([coded, cands[c]]), base, members)
        assert ranks[c] == rank == int(abs(cands[c, 0]) == 0.5)
        assert logdets[c] == (pytest.approx(logdet, rel=1e-7, abs=1e-7) if rank else -np.inf)

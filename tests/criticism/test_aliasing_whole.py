"""The runs proposed to separate aliased terms, against the greedy rule written out: each step adds the
candidate whose design has the highest rank of the members' residualised block, ties broken by its log
pseudo-determinant (the first in candidate order unless another is more than 1e-4 above), the block computed
with numpy's pseudo-inverse for the whole design at each candidate.  Designs whose quadratic base the runs
cannot estimate (two-level factorials, some runs missing) and full-rank central composites, 2-3 factors,
1-3 third-order members."""
from __future__ import annotations

import itertools

import numpy as np
from hypothesis import given, settings, strategies as st

from demid.criticism.aliasing import candidate_points, separating_runs
from demid.design import ccd_points, model_matrix, quadratic_terms


def _levels(alpha: float) -> list[float]:
    return sorted({-alpha, -1.0, -0.5, 0.0, 0.5, 1.0, alpha})


def _criterion(coded, base, members):
    """(rank, log pseudo-determinant) of Z'(I - X X^+) Z with eigenvalues above 1e-12 of Z's sum of squares."""
    x, z = model_matrix(coded, base), model_matrix(coded, members)
    r = z - x @ (np.linalg.pinv(x) @ z)
    ev = np.linalg.eigvalsh(r.T @ r)
    keep = ev > max(float(np.sum(z * z)), 1e-300) * 1e-12
    return int(keep.sum()), (float(np.sum(np.log(ev[keep]))) if keep.any() else -np.inf)


def _greedy(coded, base, members, alpha):
    cands = np.array(list(itertools.product(_levels(alpha), repeat=coded.shape[1])))
    chosen = []
    rank, _ = _criterion(coded, base, members)
    while rank < len(members) and len(chosen) < len(members):
        scores = [_criterion(np.vstack([coded, c]), base, members) for c in cands]
        top = max(r for r, _ in scores)
        if top <= rank:
            break
        best = None
        for i, (r, logdet) in enumerate(scores):
            if r == top and (best is None or logdet > scores[best][1] + 1e-4):
                best = i
        chosen.append(cands[best])
        coded = np.vstack([coded, cands[best]])
        rank = top
    return np.array(chosen).reshape(-1, cands.shape[1])


def _cubic_terms(k):
    return [t for t in itertools.product(range(4), repeat=k) if sum(t) == 3]


@settings(max_examples=10, deadline=None, derandomize=True)
@given(k=st.integers(2, 3), kind=st.sampled_from(["factorial", "factorial centred", "factorial less one", "ccd", "ccd less three"]),
       n_members=st.integers(1, 3), pick=st.integers(0, 10 ** 6), alpha_scale=st.sampled_from([1.0, 1.2]))
def test_separating_runs_follow_the_greedy_rank_and_determinant_rule(k, kind, n_members, pick, alpha_scale):
    rng = np.random.default_rng(pick)
    alpha = float(np.sqrt(k)) * alpha_scale
    if kind.startswith("factorial"):
        coded = np.array(list(itertools.product([-1.0, 1.0], repeat=k)))
        if kind.endswith("centred"):
            coded = np.vstack([coded, np.zeros((1, k))])
    else:
        coded = ccd_points(k, alpha, 1)
    if kind.endswith("less one"):
        coded = np.delete(coded, int(rng.integers(len(coded))), axis=0)
    elif kind.endswith("less three"):
        coded = np.delete(coded, rng.permutation(len(coded))[:3], axis=0)
    cubic = _cubic_terms(k)
    members = [cubic[i] for i in rng.permutation(len(cubic))[:n_members]]
    base = quadratic_terms(k)
    got = separating_runs(coded, base, members, alpha)
    want = _greedy(coded, base, members, alpha)
    np.testing.assert_allclose(got, want, atol=1e-12)
    # each proposed run raises the rank: the members become estimable together, or as far as the candidates allow
    rank0, _ = _criterion(coded, base, members)
    assert _criterion(np.vstack([coded, got]), base, members)[0] == rank0 + len(got)


def test_a_factorial_with_a_centre_run_gets_two_runs_for_two_interactions_of_third_order():
    """a^2 and b^2 are one column on a 2^2 factorial with a centre run (the quadratic base is not estimable);
    a^2 b and a b^2 are b and a there: two runs separate them, the ones the rule written out finds."""
    coded = np.vstack([np.array(list(itertools.product([-1.0, 1.0], repeat=2))), [[0.0, 0.0]]])
    members = [(2, 1), (1, 2)]
    got = separating_runs(coded, quadratic_terms(2), members, 1.414)
    np.testing.assert_allclose(got, _greedy(coded, quadratic_terms(2), members, 1.414), atol=1e-12)
    assert len(got) == 2 and _criterion(np.vstack([coded, got]), quadratic_terms(2), members)[0] == 2


def test_candidate_points_are_every_combination_of_the_seven_levels():
    for k, alpha in [(1, 1.0), (2, 1.414), (3, 1.682)]:
        pts = candidate_points(k, alpha)
        levels = _levels(alpha)
        assert pts.shape == (len(levels) ** k, k)
        assert [tuple(p) for p in pts] == list(itertools.product(levels, repeat=k))

"""Which candidate terms the runs cannot estimate or cannot tell apart (aliasing.term_classes), over three-level
factorials of two and three factors with replicated runs and random weights: a cubic x^3 equals x on levels -1, 0,
1 and is not estimable beside the quadratic, whatever the scale of the weights; estimable terms are grouped with
the terms whose residualised columns are collinear with theirs, as computed apart."""

from __future__ import annotations

import itertools

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.criticism.aliasing import term_classes
from demid.design import model_matrix, quadratic_terms


@given(k=st.sampled_from([2, 3]), seed=st.integers(0, 1000), weighted=st.booleans(),
       scale=st.sampled_from([1e-6, 1.0, 1e6]))
@settings(max_examples=15, deadline=None, derandomize=True)
def test_a_cubic_on_three_levels_is_not_estimable_and_other_terms_are_grouped_by_collinearity(k, seed, weighted,
                                                                                               scale):
    rng = np.random.default_rng(seed)
    coded = np.array(list(itertools.product([-1.0, 0.0, 1.0], repeat=k)))
    coded = np.vstack([coded, coded[rng.integers(0, len(coded), size=3)]])
    weights = scale * rng.uniform(0.5, 2.0, size=len(coded)) if weighted else None
    base = quadratic_terms(k)
    cubes = [tuple(3 if i == j else 0 for i in range(k)) for j in range(k)]
    mixed = [tuple(2 if i == 0 else 1 if i == 1 else 0 for i in range(k))]  # x1^2 x2: estimable on a 3^k grid
    classes = term_classes(coded, base, cubes + mixed, weights=weights)
    inestimable = [c.terms for c in classes if c.direction is None]
    estimable = [c for c in classes if c.direction is not None]
    assert sorted(t for terms in inestimable for t in terms) == sorted(cubes)
    assert [c.terms for c in estimable] == [mixed]
    # its direction: the candidate's column residualised on the model (weighted), normalised
    sw = np.ones(len(coded)) if weights is None else np.sqrt(weights)
    x = model_matrix(coded, base) * sw[:, None]
    col = model_matrix(coded, mixed)[:, 0] * sw
    resid = col - x @ np.linalg.lstsq(x, col, rcond=None)[0]
    assert abs(float(estimable[0].direction @ (resid / np.linalg.norm(resid)))) > 1 - 1e-9

"""The runs that separate aliased terms over Omega (demid/next_wave.py), on boxes away from the origin and of
unequal sides (search units): each run lies inside the box, is the criticism's separating run in Omega's coding
(centre and half-width of each side) mapped back, and with the earlier runs makes the aliased terms separately
estimable (full rank of the quadratic plus both terms, in that coding); at most ``budget`` of them, labelled."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from demid.criticism import separating_runs
from demid.design import model_matrix, quadratic_terms
from demid.next_wave import _separating_over_omega


@pytest.mark.parametrize("lo, hi", [([2.0, -3.0], [12.0, 1.0]), ([-50.0, 0.5], [-10.0, 0.75]), ([0.0, 0.0], [1.0, 1.0])])
@pytest.mark.parametrize("budget", [1, 4])
def test_separating_runs_over_omega_lie_in_the_box_in_its_coding(lo, hi, budget):
    lo, hi = np.array(lo), np.array(hi)
    center, half = (lo + hi) / 2, (hi - lo) / 2
    levels = np.array(list(itertools.product((-1.0, 0.0, 1.0), repeat=2)))
    existing = center + levels * half  # a three-level factorial over Omega
    alias = (((3, 0), (1, 2)), ["y"])
    runs, labels = _separating_over_omega([alias], existing, lo, hi, budget)
    expected = separating_runs(levels, quadratic_terms(2), [(3, 0), (1, 2)], 1.0)[:budget]
    assert 1 <= len(runs) <= budget and len(labels) == len(runs)
    assert labels == [alias] * len(runs)
    assert np.all(runs >= lo - 1e-12) and np.all(runs <= hi + 1e-12)
    assert np.allclose((runs - center) / half, np.reshape(expected, (-1, 2)), atol=1e-12)
    terms = quadratic_terms(2) + [(3, 0), (1, 2)]
    coded = (np.vstack([existing, runs]) - center) / half
    if len(runs) == len(expected) and budget >= 4:
        assert np.linalg.matrix_rank(model_matrix(coded, terms)) == len(terms)

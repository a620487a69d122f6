"""The Sobol estimator's admissible sample points (more than three factors) over generated studies of two to three
observables with targets of either sign: which points are admissible, how many, the best point and its error,
against the worst relative error over every observable computed apart from the same points."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.design import quadratic_terms
from demid.sampling import Domain
from demid.sampling.sobol import sobol_admissible_set
from demid.surrogate import Surrogate

FACTORS = ("a", "b", "c", "d")


def _linear(name, coef) -> Surrogate:
    terms = quadratic_terms(4)
    full = np.zeros(len(terms))
    for i, t in enumerate(terms):
        powers = tuple(int(p) for p in t)
        if sum(powers) == 0:
            full[i] = coef[0]
        elif sum(powers) == 1:
            full[i] = coef[1 + powers.index(1)]
    return Surrogate(name, list(FACTORS), terms, full, np.zeros((len(terms), len(terms))), 0.0, 10)


@given(seed=st.integers(0, 1000), k=st.integers(2, 3), signs=st.lists(st.sampled_from([-1.0, 1.0]), min_size=3,
                                                                          max_size=3),
       tolerance=st.sampled_from([0.05, 0.2]))
@settings(max_examples=5, deadline=None, derandomize=True)
def test_admissible_points_are_those_whose_worst_observable_meets_the_tolerance(seed, k, signs, tolerance):
    rng = np.random.default_rng(seed)
    domain = Domain(FACTORS, (0.0,) * 4, (1.0,) * 4)
    names = [f"y{i}" for i in range(k)]
    surrogates = {o: _linear(o, np.r_[signs[i] * 2.0, rng.normal(scale=0.5, size=4)]) for i, o in enumerate(names)}
    targets = {o: signs[i] * 2.0 * (1 + 0.1 * i) for i, o in enumerate(names)}
    aset = sobol_admissible_set(surrogates, domain, names, targets, tolerance, 256)
    points = aset.points
    worst = np.max([np.abs(surrogates[o].predict(points) - targets[o]) / abs(targets[o]) for o in names], axis=0)
    np.testing.assert_array_equal(aset.mask, worst <= tolerance)
    assert aset.n_nodes == len(points) and aset.n_admissible_nodes == int(np.sum(worst <= tolerance))
    assert aset.node_fraction == pytest.approx(np.mean(worst <= tolerance))
    assert aset.best_error == pytest.approx(worst.min(), rel=1e-12)
    np.testing.assert_array_equal(aset.best_point, points[np.argmin(worst)])

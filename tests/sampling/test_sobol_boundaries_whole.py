"""The Sobol estimator's own sample on its boundary and the extreme points it polishes from, against rules written
out here: a sample point whose largest relative error is exactly the tolerance is admissible (targets of either
sign, one to three observables), and every field the set reads off its sample (mask, counts, node fraction, the
least-violating point and its error, the points, the evaluations, the interval's half width); the extreme points are
the union of each coordinate's few smallest and largest, in index order."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from hypothesis import Phase, given, settings
from hypothesis import strategies as st

from demid.sampling import Domain
from demid.sampling.sobol import _extreme_points, sobol_admissible_set, sobol_fraction
from tests.sampling.test_sobol_whole import Linear

SETTINGS = settings(max_examples=6, deadline=None, derandomize=True, phases=[Phase.explicit, Phase.generate])


@given(seed=st.integers(0, 10_000), k=st.integers(1, 3), sign=st.sampled_from([-1.0, 1.0]))
@SETTINGS
def test_a_sample_point_exactly_at_the_tolerance_is_admissible_and_every_sample_field(seed, k, sign):
    rng = np.random.default_rng(seed)
    dim, n = 4, 12
    domain = Domain(tuple(f"f{i}" for i in range(dim)), (0.0,) * dim, (1.0,) * dim)
    observables = [f"y{j}" for j in range(k)]
    targets = {o: sign * 2.0 ** (j + 1) for j, o in enumerate(observables)}
    fields = {o: Linear(np.r_[targets[o], rng.normal(size=dim) * 0.1]) for o in observables}
    points = rng.random((n, dim))
    # relative errors in quarters (exact in binary): the first point's largest is exactly the tolerance 0.25
    errors = rng.choice([-0.5, -0.25, 0.0, 0.25, 0.5], size=(k, n))
    errors[:, 0] = 0.0
    errors[rng.integers(k), 0] = rng.choice([-0.25, 0.25])
    errors[:, 1] = 0.125  # the least-violating point, unless another has no error at all
    sample = pd.DataFrame(points, columns=list(domain.factors))
    for j, o in enumerate(observables):
        sample[o] = targets[o] * (1 + errors[j])
    aset = sobol_admissible_set(fields, domain, observables, targets, 0.25, 64, sample)
    worst = np.max(np.abs(errors), axis=0)
    mask = worst <= 0.25
    assert mask[0] and aset.mask[0]
    np.testing.assert_array_equal(aset.mask, mask)
    assert (aset.n_nodes, aset.n_admissible_nodes, aset.node_fraction) == (n, int(mask.sum()), mask.mean())
    best = int(np.argmin(worst))
    assert aset.best_error == worst[best] and np.array_equal(aset.best_point, points[best])
    np.testing.assert_array_equal(aset.points, points)
    est = sobol_fraction(fields, domain, observables, targets, 0.25, 64, seed=0)
    assert aset.fraction == est.fraction and aset.fraction_ci == (est.ci_lower, est.ci_upper)
    assert aset.fraction_error == (est.ci_upper - est.ci_lower) / 2
    assert aset.evaluations == est.evaluations + k * n
    assert aset.tolerance == 0.25 and aset.observables == tuple(observables) and aset.method == "scrambled Sobol"


@given(seed=st.integers(0, 10_000), n=st.integers(1, 30), dim=st.integers(1, 5), per_side=st.integers(1, 4))
@SETTINGS
def test_the_extreme_points_are_each_coordinate_s_smallest_and_largest(seed, n, dim, per_side):
    rng = np.random.default_rng(seed)
    points = rng.random((n, dim))
    keep = set()
    for i in range(dim):
        ranked = sorted(range(n), key=lambda r: points[r, i])
        keep |= set(ranked[:per_side]) | set(ranked[max(n - per_side, 0):])
    np.testing.assert_array_equal(_extreme_points(points, per_side), points[sorted(keep)])
    assert len(_extreme_points(points)) <= min(n, 6 * dim)  # three a side by default

"""The shared relative bias of level 2 (one δ for every observable, each weighted by its own tolerance) over
generated errors of one to four observables, weights equal and unequal: the smallest largest weighted error and the
δ attaining it, against a brute-force minimisation over every candidate δ."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.criticism.searches import _shared_bias_envelope


def _brute_force(e, w):
    """min over δ of max_k w_k |e_k − δ|: the optimum of a convex piecewise-linear function lies at an e_k or
    where two of its pieces cross."""
    candidates = list(e) + [(w[i] * e[i] + w[j] * e[j]) / (w[i] + w[j]) for i in range(len(e))
                            for j in range(len(e)) if i != j]
    values = [np.max(w * np.abs(e - d)) for d in candidates]
    return min(values)


@given(seed=st.integers(0, 10_000), k=st.integers(1, 4), points=st.integers(1, 5), equal=st.booleans())
@settings(max_examples=60, deadline=None, derandomize=True)
def test_the_shared_bias_minimises_the_largest_weighted_error(seed, k, points, equal):
    rng = np.random.default_rng(seed)
    err = rng.normal(scale=0.2, size=(k, points))
    weights = np.ones(k) if equal else rng.uniform(0.2, 5.0, size=k)
    value, delta = _shared_bias_envelope(err, weights)
    assert value.shape == delta.shape == (points,)
    for m in range(points):
        e = err[:, m]
        assert value[m] == pytest.approx(_brute_force(e, weights), rel=1e-12, abs=1e-15)
        # δ attains it
        assert np.max(weights * np.abs(e - delta[m])) == pytest.approx(value[m], rel=1e-9, abs=1e-15)
        if equal:
            assert value[m] == pytest.approx(np.ptp(e) / 2, rel=1e-12, abs=1e-15)

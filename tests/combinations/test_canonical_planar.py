"""A planar surface (no curvature at all: B = 0) has no stationary point and rises along every direction of the
coded space: its canonical analysis is a rising ridge whose ridge directions span the space and whose slopes are
the linear coefficients projected on them, for one to four factors and slopes of either sign."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.canonical import canonical_analysis

SETTINGS = settings(max_examples=10, deadline=None, derandomize=True)


@given(k=st.integers(1, 4), seed=st.integers(0, 10_000), b0=st.sampled_from([-3.0, 0.0, 12.5]))
@SETTINGS
def test_a_plane_is_a_rising_ridge_along_every_direction(k, seed, b0):
    rng = np.random.default_rng(seed)
    b = rng.normal(size=k) * rng.choice([-1.0, 1.0], size=k) + 0.1 * np.sign(rng.normal(size=k))
    lo, hi = -np.ones(k), np.ones(k)
    result = canonical_analysis(b0, b, np.zeros((k, k)), region_lower=lo, region_upper=hi)
    assert result.kind == "rising ridge"
    assert result.ridge_directions.shape == (k, k)
    # the ridge directions are an orthonormal basis, so the slopes carry all of b
    np.testing.assert_allclose(result.ridge_directions.T @ result.ridge_directions, np.eye(k), atol=1e-12)
    np.testing.assert_allclose(result.ridge_slopes, result.ridge_directions.T @ b, atol=1e-12)
    np.testing.assert_allclose(np.sort(np.abs(result.ridge_slopes)) ** 2 @ np.ones(k), b @ b, rtol=1e-12)
    assert np.all(np.isnan(result.stationary_coded)) and np.isnan(result.value)
    # no curved direction to place the ridge point on: the design centre, where the plane is b0
    np.testing.assert_array_equal(result.ridge_point_coded, np.zeros(k))
    assert result.ridge_value == b0

"""Every field of a canonical analysis against numpy computations made apart, over generated quadratics of one to
four factors with curvatures of either sign, some below the ridge threshold (stationary and rising ridges), boxes
around or away from the stationary point, a map to actual units and thresholds given or not: the eigenvalues
(largest first) and oriented eigenvectors, the stationary point from the linear system 2 B x = -b, its value and
whether it is inside, the kind, the ridge directions and slopes, the ridge point kept in the box, and the JSON."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.stats import special_ortho_group

from demid.canonical import DEFAULT_THRESHOLD_FRACTION, canonical_analysis


@given(seed=st.integers(0, 10_000), k=st.integers(1, 4), n_flat=st.integers(0, 2), shift=st.sampled_from([0.0, 3.0]),
       given_threshold=st.booleans(), signs=st.lists(st.sampled_from([-1.0, 1.0]), min_size=4, max_size=4))
@settings(max_examples=40, deadline=None, derandomize=True)
def test_every_field_of_a_canonical_analysis(seed, k, n_flat, shift, given_threshold, signs):
    rng = np.random.default_rng(seed)
    n_flat = min(n_flat, k)
    curvatures = np.array(signs[:k]) * rng.uniform(0.5, 3.0, k)
    curvatures[:n_flat] *= 1e-3  # below the default threshold: a ridge
    rotation = special_ortho_group.rvs(k, random_state=seed) if k > 1 else np.eye(1)
    big_b = rotation @ np.diag(curvatures) @ rotation.T
    b = rng.normal(size=k)
    b0 = float(rng.normal())
    lo, hi = -np.ones(k) * 1.5 + shift, np.ones(k) * 1.5 + shift
    scale, centre = rng.uniform(0.5, 2, k), rng.normal(size=k)
    threshold = 0.3 if given_threshold else None
    result = canonical_analysis(b0, b, big_b, region_lower=lo, region_upper=hi,
                                to_actual=lambda x: centre + x * scale, threshold=threshold)

    values = np.sort(np.linalg.eigvalsh(big_b))[::-1]
    np.testing.assert_allclose(result.eigenvalues, values, atol=1e-12)
    vectors = result.eigenvectors
    np.testing.assert_allclose(vectors.T @ vectors, np.eye(k), atol=1e-10)
    np.testing.assert_allclose(big_b @ vectors, vectors * result.eigenvalues, atol=1e-10)
    for j in range(k):
        assert vectors[np.argmax(np.abs(vectors[:, j])), j] > 0
    want_threshold = threshold if given_threshold else DEFAULT_THRESHOLD_FRACTION * np.max(np.abs(values))
    assert result.threshold == pytest.approx(want_threshold)

    singular = np.min(np.abs(values)) <= 1e-12 * np.max(np.abs(values))
    xs = np.linalg.solve(2 * big_b, -b)
    if not singular:
        np.testing.assert_allclose(result.stationary_coded, xs, rtol=1e-7, atol=1e-9)
        np.testing.assert_allclose(result.stationary_actual, centre + xs * scale, rtol=1e-7, atol=1e-9)
        assert result.value == pytest.approx(b0 + xs @ b + xs @ big_b @ xs, rel=1e-7, abs=1e-9)
        assert result.inside is bool(np.all(xs >= lo - 1e-9) and np.all(xs <= hi + 1e-9))

    flat = np.abs(values) < want_threshold
    assert result.ridge_directions.shape == (k, int(flat.sum())) and result.is_ridge is bool(flat.any())
    np.testing.assert_allclose(result.ridge_slopes, vectors[:, flat].T @ b, atol=1e-10)
    if not flat.any():
        kind = "maximum" if np.all(values < 0) else "minimum" if np.all(values > 0) else "saddle point"
        assert result.kind == kind and "ridge_directions" not in result.to_json()
    else:
        big = ~flat
        xr = -0.5 * vectors[:, big] @ ((vectors[:, big].T @ b) / values[big]) if big.any() else np.zeros(k)
        xr = np.clip(xr, lo, hi)
        np.testing.assert_allclose(result.ridge_point_coded, xr, atol=1e-9)
        np.testing.assert_allclose(result.ridge_point_actual, centre + xr * scale, atol=1e-9)
        assert result.ridge_value == pytest.approx(b0 + xr @ b + xr @ big_b @ xr, rel=1e-9, abs=1e-12)
        radius = np.linalg.norm(hi - lo) / 2
        rising = np.any(np.abs(vectors[:, flat].T @ b) * radius > want_threshold * radius ** 2)
        assert result.kind == ("rising ridge" if rising and not result.inside else "stationary ridge")
        assert result.to_json()["ridge_slopes"] == pytest.approx(list(result.ridge_slopes))
    js = result.to_json()
    assert js["kind"] == result.kind and js["inside"] is result.inside
    assert js["eigenvalues"] == pytest.approx(list(values), abs=1e-12)


def test_a_flat_surface_has_no_stationary_point_and_every_direction_is_a_ridge():
    result = canonical_analysis(2.0, np.array([1.0, 0.0]), np.zeros((2, 2)), region_lower=[-1, -1],
                                region_upper=[1, 1])
    assert np.all(np.isnan(result.stationary_coded)) and np.isnan(result.value) and not result.inside
    assert result.ridge_directions.shape == (2, 2)
    assert result.kind == "rising ridge"
    np.testing.assert_array_equal(result.ridge_point_coded, [0.0, 0.0])
    assert result.ridge_value == 2.0

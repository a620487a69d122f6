"""A canonical analysis on each of its boundaries and in whole, against rules written out here: an eigenvalue of
exactly the threshold is no ridge; a ridge whose slope carries the response over the region's radius exactly as far
as a curvature at the threshold would is stationary, a hair more is rising; a stationary point on the box's face,
or 1e-9 beyond it, is inside, 2e-9 beyond it is not; and every field (eigenvalues, oriented eigenvectors,
stationary point by a linear solve, its value, the kind, the ridge directions, slopes and point, the JSON) over
generated surfaces of two to four factors with eigenvalues of either sign, some near zero, rotated at random."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import Phase, given, settings
from hypothesis import strategies as st

from demid.canonical import DEFAULT_THRESHOLD_FRACTION, canonical_analysis, quadratic_parts


def test_an_eigenvalue_of_exactly_the_threshold_is_no_ridge():
    # eigenvalues 1 and 0.1: the threshold is 0.1 * 1, the smaller one is on it
    up = canonical_analysis(1.0, [0.3, 0.2], np.diag([1.0, 0.1]), region_lower=[-1, -1], region_upper=[1, 1])
    assert up.threshold == 0.1 and up.kind == "minimum" and not up.is_ridge
    down = canonical_analysis(1.0, [0.3, 0.2], np.diag([-1.0, -0.1]), region_lower=[-1, -1], region_upper=[1, 1])
    assert down.kind == "maximum" and not down.is_ridge
    ridge = canonical_analysis(1.0, [0.3, 0.2], np.diag([1.0, 0.0999]), region_lower=[-1, -1], region_upper=[1, 1])
    assert ridge.is_ridge and ridge.kind == "rising ridge"  # slope 0.2 over a radius of sqrt(2), x_s outside


def test_a_ridge_slope_exactly_at_the_threshold_s_reach_is_stationary():
    # box [-3, 3] x [-4, 4]: radius 5; eigenvalues 1 and 0.05 (threshold 0.1): slope 0.5 moves 0.5 * 5 = 2.5 over
    # the radius, as much as the threshold's curvature does (0.1 * 25); the stationary point (0, -5) lies outside
    def kind(slope):
        return canonical_analysis(1.0, [0.0, slope], np.diag([1.0, 0.05]), region_lower=[-3, -4],
                                  region_upper=[3, 4])

    at = kind(0.5)
    assert 0.5 * 5.0 == at.threshold * 5.0 ** 2 and not at.inside
    assert at.kind == "stationary ridge"
    assert kind(0.5000001).kind == "rising ridge" and kind(-0.5000001).kind == "rising ridge"
    assert at.ridge_slopes.tolist() == [0.5] and at.ridge_point_coded.tolist() == [0.0, 0.0]


@pytest.mark.parametrize("beyond, inside", [(0.0, True), (1e-9, True), (4e-9, False), (-1.0, True)])
def test_a_stationary_point_on_the_box_s_face_is_inside(beyond, inside):
    # -x1^2 - x2^2 + b x1: the maximum at x1 = b / 2
    c = canonical_analysis(0.0, [2.0 + 2 * beyond, 0.0], np.diag([-1.0, -1.0]), region_lower=[-1, -1],
                           region_upper=[1, 1])
    assert c.stationary_coded[0] == pytest.approx(1.0 + beyond, abs=1e-15)
    assert c.inside is inside and c.kind == "maximum"


@pytest.mark.parametrize("scale, ratio, singular", [
    *[(scale, ratio, ratio < 1e-12) for scale in (1e-4, 1.0, 1e4) for ratio in (1e-13, 1e-11)],
    (1.0, 1e-12, True),  # exactly 1e-12 of the largest: singular
])
def test_a_surface_is_singular_by_its_smallest_eigenvalue_relative_to_its_largest_at_any_scale(scale, ratio,
                                                                                               singular):
    # scale * (2 + 0.6 x1 + x1^2 + ratio x2^2): eigenvalues scale and scale * ratio, x_s = (-0.3, 0) unless singular
    c = canonical_analysis(2.0 * scale, [0.6 * scale, 0.0], np.diag([scale, scale * ratio]),
                           region_lower=[-1, -1], region_upper=[1, 1])
    if singular:
        assert np.isnan(c.stationary_coded).all() and np.isnan(c.value) and not c.inside
    else:
        assert c.stationary_coded == pytest.approx([-0.3, 0.0], abs=1e-12) and c.inside
        assert c.value == pytest.approx(scale * (2.0 - 0.18 + 0.09))
    assert c.kind == "stationary ridge" and c.ridge_slopes.tolist() == [0.0]


def _rotation(rng, k):
    q, r = np.linalg.qr(rng.normal(size=(k, k)))
    return q * np.sign(np.diag(r))


@given(seed=st.integers(0, 10_000), k=st.integers(2, 4), threshold=st.sampled_from([None, 0.05, 0.3]))
@settings(max_examples=25, deadline=None, derandomize=True, phases=[Phase.explicit, Phase.generate])
def test_every_field_of_a_canonical_analysis_against_the_rules_written_out(seed, k, threshold):
    rng = np.random.default_rng(seed)
    magnitudes = rng.choice([0.01, 0.5, 1.0, 2.0], size=k) * rng.choice([-1.0, 1.0], size=k)
    q = _rotation(rng, k)
    big_b = q @ np.diag(magnitudes) @ q.T
    big_b = (big_b + big_b.T) / 2
    b = rng.normal(size=k)
    b0 = float(rng.normal())
    lo, hi = -rng.uniform(0.5, 2, k), rng.uniform(0.5, 2, k)
    c = canonical_analysis(b0, b, big_b, region_lower=lo, region_upper=hi, to_actual=lambda x: 10 + 2 * x,
                           threshold=threshold)
    values, vectors = np.linalg.eigh(big_b)
    order = np.argsort(values)[::-1]
    values, vectors = values[order], vectors[:, order]
    np.testing.assert_allclose(c.eigenvalues, values, rtol=1e-10, atol=1e-12)
    for j in range(k):  # unit columns, each one's largest loading positive, up to sign numpy's
        col = c.eigenvectors[:, j]
        assert col[np.argmax(np.abs(col))] > 0
        assert abs(col @ vectors[:, j]) == pytest.approx(1.0, abs=1e-8)
    want_threshold = DEFAULT_THRESHOLD_FRACTION * np.abs(values).max() if threshold is None else threshold
    assert c.threshold == pytest.approx(want_threshold, rel=1e-12)
    xs = np.linalg.solve(-2 * big_b, b)
    np.testing.assert_allclose(c.stationary_coded, xs, rtol=1e-8, atol=1e-8)
    np.testing.assert_allclose(c.stationary_actual, 10 + 2 * xs, rtol=1e-8, atol=1e-8)
    assert c.value == pytest.approx(b0 + xs @ b + xs @ big_b @ xs, rel=1e-8, abs=1e-8)
    assert c.inside == bool(np.all(xs >= lo - 1e-9) and np.all(xs <= hi + 1e-9))
    small = np.abs(values) < want_threshold
    assert c.ridge_directions.shape == (k, int(small.sum()))
    np.testing.assert_allclose(c.ridge_slopes, c.ridge_directions.T @ b, rtol=1e-12, atol=1e-12)
    if not small.any():
        want = "maximum" if np.all(values < 0) else "minimum" if np.all(values > 0) else "saddle point"
        assert c.kind == want and "ridge_slopes" not in c.to_json()
    else:
        big_v = c.eigenvectors[:, ~small]
        xr = np.clip(-0.5 * big_v @ ((big_v.T @ b) / c.eigenvalues[~small]), lo, hi)
        np.testing.assert_allclose(c.ridge_point_coded, xr, rtol=1e-10, atol=1e-12)
        np.testing.assert_allclose(c.ridge_point_actual, 10 + 2 * xr, rtol=1e-10, atol=1e-12)
        assert c.ridge_value == pytest.approx(b0 + xr @ b + xr @ big_b @ xr, rel=1e-10, abs=1e-12)
        radius = np.linalg.norm(hi - lo) / 2
        rising = np.any(np.abs(c.ridge_slopes) * radius > want_threshold * radius ** 2) and not c.inside
        assert c.kind == ("rising ridge" if rising else "stationary ridge")
        out = c.to_json()
        assert out["ridge_slopes"] == pytest.approx(list(c.ridge_slopes)) and out["kind"] == c.kind
        assert out["ridge_point_coded"] == pytest.approx(list(xr), abs=1e-12)
    out = c.to_json()
    assert out["eigenvalues"] == pytest.approx(list(values), abs=1e-12) and out["inside"] is c.inside
    assert out["threshold"] == c.threshold and out["predicted"] == c.value


@given(seed=st.integers(0, 10_000), k=st.integers(1, 4))
@settings(max_examples=15, deadline=None, derandomize=True, phases=[Phase.explicit, Phase.generate])
def test_quadratic_parts_give_back_the_polynomial_s_values(seed, k):
    rng = np.random.default_rng(seed)
    terms = [tuple(int(i == j) for i in range(k)) for j in range(k)]
    terms += [tuple(int(i in (a, c)) + int(i == a == c) for i in range(k)) for a in range(k) for c in range(a, k)]
    terms = [(0,) * k] + terms + [tuple(3 if i == 0 else 0 for i in range(k))]  # a cubic term: not used
    coefs = rng.normal(size=len(terms))
    b0, b, big_b = quadratic_parts(terms, coefs, k)
    assert np.allclose(big_b, big_b.T)
    for x in rng.normal(size=(4, k)):
        want = sum(cf * np.prod(x ** np.array(t)) for t, cf in zip(terms[:-1], coefs[:-1]))
        assert b0 + x @ b + x @ big_b @ x == pytest.approx(want, rel=1e-12, abs=1e-12)

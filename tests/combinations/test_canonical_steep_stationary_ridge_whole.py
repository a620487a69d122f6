"""A ridge steep at the centre whose stationary point lies inside the runs' box is a stationary ridge, not a rising
one (the textbook's rule: the response along the ridge climbs to the stationary point and falls past it, inside the
region).  The slope there carries the response over the region's radius further than a curvature at the threshold
would, so only the stationary point's position tells the two apart; the surfaces here are of two and three
factors, along the axes and rotated, and the climb and fall are read off the surface itself on a line through the
box."""

from __future__ import annotations

import numpy as np
import pytest

from demid.canonical import canonical_analysis


def _rotation(k: int, seed: int) -> np.ndarray:
    q, r = np.linalg.qr(np.random.default_rng(seed).normal(size=(k, k)))
    return q * np.sign(np.diag(r))


@pytest.mark.parametrize("k, small, slope, seed", [(2, -0.09, 0.15, None), (2, 0.09, -0.15, 1), (3, -0.095, 0.18, 2)])
def test_a_steep_ridge_with_its_stationary_point_inside_is_stationary(k, small, slope, seed):
    # eigenvalues -1 (or 1), ..., and one below the default threshold 0.1 * 1; the slope along the small one
    # moves the response |slope| * sqrt(k) over the box's radius, more than the threshold's 0.1 * k
    values = np.r_[np.sign(small) * np.ones(k - 1), small]
    v = np.eye(k) if seed is None else _rotation(k, seed)
    big_b = v @ np.diag(values) @ v.T
    b = v[:, -1] * slope
    assert abs(slope) * np.sqrt(k) > 0.1 * k
    result = canonical_analysis(2.0, b, big_b, region_lower=-np.ones(k), region_upper=np.ones(k))
    assert result.is_ridge and result.ridge_directions.shape[1] == 1
    assert result.inside
    assert result.kind == "stationary ridge"
    # independently: x_s solves b + 2 B x = 0, inside the box, and along the ridge through it the response
    # has its extreme at x_s, rising towards it from one face and falling past it
    xs = np.linalg.solve(2 * big_b, -b)
    np.testing.assert_allclose(result.stationary_coded, xs, atol=1e-12)
    assert np.all(np.abs(xs) <= 1)
    t = np.linspace(-1.0, 1.0, 2001) * np.sqrt(k)
    line = xs[None, :] + t[:, None] * v[:, -1][None, :]
    inside = np.all(np.abs(line) <= 1, axis=1)
    y = 2.0 + line @ b + np.einsum("ni,ij,nj->n", line, big_b, line)
    y = y[inside] * np.sign(-small)  # a maximum along the ridge either way
    top = int(np.argmax(y))
    assert 0 < top < len(y) - 1
    np.testing.assert_allclose(line[inside][top], xs, atol=2e-3)


def test_moving_the_box_off_the_stationary_point_makes_the_same_ridge_rising():
    # the same surface as the first case above, judged over a box that stops short of x_s = (0, 0.833)
    big_b, b = np.diag([-1.0, -0.09]), np.array([0.0, 0.15])
    result = canonical_analysis(2.0, b, big_b, region_lower=[-1.0, -1.0], region_upper=[1.0, 0.8])
    assert not result.inside and result.kind == "rising ridge"

"""The zooming minimiser (demid.sampling.quadrature.zoom_min) that places the exact sets' nearest points, against
minimisers known in closed form: many owners at once, minima anywhere in the bracket and at its ends, a kink and
a smooth bottom; the minimiser to 1e-11 of the range the caller sampled first (eight times the first bracket; each
round keeps two of its sixteen steps), the value the function's there, and a start already at a minimum of a flat
bottom kept (only a strictly smaller value moves it)."""

from __future__ import annotations

import numpy as np
import pytest

from demid.sampling.quadrature import zoom_min

POINTS = 17


def _first_bracket(func, owners, lower, upper):
    """The caller's start: the best of 17 points per owner and the bracket of its two neighbours."""
    x = lower[:, None] + (upper - lower)[:, None] * np.linspace(0.0, 1.0, POINTS)
    values = func(np.repeat(owners, POINTS), x.ravel()).reshape(len(owners), POINTS)
    i = np.argmin(values, axis=1)
    rows = np.arange(len(owners))
    return x[rows, np.maximum(i - 1, 0)], x[rows, np.minimum(i + 1, POINTS - 1)], x[rows, i], values[rows, i]


@pytest.mark.parametrize("seed", [0, 1])
@pytest.mark.parametrize("shape", ["kink", "bowl"])
def test_minimisers_are_found_to_a_hundred_billionth_of_the_range(seed, shape):
    rng = np.random.default_rng(seed)
    n = 300
    lower = rng.uniform(-5.0, 5.0, n)
    upper = lower + rng.uniform(0.5, 3.0, n)
    share = rng.uniform(0.0, 1.0, n)
    share[:4] = [0.0, 1.0, 0.5, 1 / 3]  # at either end, on a grid node, off every node
    minimiser = lower + share * (upper - lower)
    # a bowl's bottom is resolved only where its values are: a constant added would blur it to sqrt(eps)
    offset = rng.uniform(-2.0, 2.0, n) if shape == "kink" else np.zeros(n)

    def func(owner, x):
        gap = x - minimiser[owner]
        return offset[owner] + (np.abs(gap) if shape == "kink" else gap ** 2)

    owners = np.arange(n)
    best_x, best_value = zoom_min(func, owners, *_first_bracket(func, owners, lower, upper))
    assert np.all(np.abs(best_x - minimiser) <= 1e-11 * (upper - lower)), np.max(np.abs(best_x - minimiser))
    np.testing.assert_array_equal(best_value, func(owners, best_x))
    assert np.all(best_value >= offset) and np.all(best_x >= lower) and np.all(best_x <= upper)
    # a minimum at an end of the range is found at that end exactly
    assert best_x[0] == lower[0] and best_x[1] == upper[1]


def test_a_start_tied_with_a_flat_bottom_is_kept():
    """f = max(|x - c| - 0.25, 0) is 0 on [c - 0.25, c + 0.25]: a start at c with value 0 is never beaten."""
    centre = np.array([0.4, 0.55, 0.6])

    def func(owner, x):
        return np.maximum(np.abs(x - centre[owner]) - 0.25, 0.0)

    owners = np.arange(3)
    best_x, best_value = zoom_min(func, owners, np.zeros(3), np.ones(3), centre, np.zeros(3))
    np.testing.assert_array_equal(best_x, centre)
    np.testing.assert_array_equal(best_value, 0.0)

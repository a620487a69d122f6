"""Where a three-factor set's slicing starts (Solid.seed), against the documented rule: the best node of the
41-per-axis grid when that node is admissible, even when no other node is (a small ball around a point off the
grid, one node inside); a local search's admissible point when no node is (a ball between the nodes); None for an
empty set.  Balls are |u - c|^2 - r0 within r0 of zero: radius sqrt(2 r0)."""

from __future__ import annotations

import numpy as np
import pytest

from demid.sampling.planes import Solid


def _ball(centre, radius, shift=0.0):
    """The set 0 <= |u - centre|^2 <= radius^2 as one residual |u - c|^2 - r0 - shift within r0 = radius^2 / 2."""
    centre = np.asarray(centre, dtype=float)
    r0 = radius ** 2 / 2
    tensor = np.zeros((1, 3, 3, 3))
    tensor[0, 0, 0, 0] = centre @ centre - r0 - shift
    for i in range(3):
        index = [0, 0, 0]
        index[i] = 1
        tensor[(0, *index)] = -2 * centre[i]
        index[i] = 2
        tensor[(0, *index)] = 1.0
    return Solid(tensor, r0), centre, r0


def _residual(centre, r0, u, shift=0.0):
    return float(np.sum((u - centre) ** 2) - r0 - shift)


def test_the_only_admissible_node_is_the_seed():
    solid, centre, r0 = _ball([0.503, 0.502, 0.499], 0.01)
    nodes = np.stack(np.meshgrid(*[np.linspace(0, 1, 41)] * 3, indexing="ij"), axis=-1).reshape(-1, 3)
    inside = nodes[np.abs(np.sum((nodes - centre) ** 2, axis=1) - r0) <= r0]
    assert len(inside) == 1  # the rule's case: the best node admissible, the next best not
    assert np.array_equal(solid.seed, inside[0])


def test_without_an_admissible_node_the_seed_is_a_local_search_s_admissible_point():
    solid, centre, r0 = _ball([0.5125, 0.4875, 0.5125], 0.005)  # between nodes 1/80 away on every axis
    seed = solid.seed
    assert seed is not None
    assert abs(_residual(centre, r0, seed)) <= r0 * (1 + 1e-9)
    assert not np.allclose(seed * 40, np.round(seed * 40))  # off the grid


def test_an_empty_set_has_no_seed():
    solid, _, _ = _ball([0.5, 0.5, 0.5], 0.01, shift=1.0)  # |u - c|^2 - r0 - 1 is below -r0 in the whole cube
    assert solid.seed is None

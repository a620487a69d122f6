"""The start grid's basins (evaluate.basin_nodes) against a brute force: every node no higher than each of its
neighbours along an axis (edges have one), lowest first, the first of equal values first, at most ``count``;
grids of 1-3 axes and 2-9 nodes per axis, values with ties and plateaus."""

from __future__ import annotations

import itertools

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.sampling.evaluate import basin_nodes


def _brute_force(values, per_axis, dim, count):
    grid = values.reshape((per_axis,) * dim)
    lowest = []
    for index in itertools.product(range(per_axis), repeat=dim):
        ok = True
        for axis in range(dim):
            for step in (-1, 1):
                j = list(index)
                j[axis] += step
                if 0 <= j[axis] < per_axis and grid[tuple(j)] < grid[index]:
                    ok = False
        if ok:
            lowest.append(int(np.ravel_multi_index(index, grid.shape)))
    lowest.sort(key=lambda i: (values[i], i))
    return lowest[:count]


@given(seed=st.integers(0, 10_000), dim=st.integers(1, 3), per_axis=st.integers(2, 9), count=st.integers(1, 6),
       levels=st.sampled_from([3, 1000]))
@settings(max_examples=60, deadline=None, derandomize=True)
def test_basin_nodes_are_the_grid_s_lowest_nodes_of_their_neighbourhoods(seed, dim, per_axis, count, levels):
    rng = np.random.default_rng(seed)
    values = rng.integers(0, levels, per_axis ** dim).astype(float)  # three levels: ties and plateaus
    got = basin_nodes(values, per_axis, dim, count)
    assert list(got) == _brute_force(values, per_axis, dim, count)
    # the best node is always the first basin's
    assert got[0] == int(np.argmin(values))

"""Where level 2's local searches start (criticism.searches.spread_starts) at its documented limits: a node exactly
0.1 (search units, largest coordinate) from one taken before it is not taken -- it must be more than 0.1 away, in
every coordinate's largest difference -- while a node a hair further is; the starts stop at exactly the number
asked for, in the ranking's order."""

from __future__ import annotations

import numpy as np
import pytest

from demid.criticism.searches import spread_starts


@pytest.mark.parametrize("starts", [1, 2, 3, 4])
def test_spread_starts_take_nodes_more_than_a_tenth_apart_and_stop_at_the_count(starts):
    beyond = float(np.nextafter(0.1, 1.0))
    assert 0.1 - 0.0 == 0.1
    grid = np.array([[0.0, 0.0], [0.1, 0.05], [beyond, 0.0], [0.0, 0.1], [0.5, 0.5], [0.05, 0.1 + beyond],
                     [0.9, 0.2]])
    order = np.array([0, 1, 3, 2, 5, 4, 6])  # exactly 0.1 away (twice), then a hair more, then far
    picks = [int(p) for p in spread_starts(order, grid, starts)]
    assert picks == [0, 2, 5, 4][:starts]


def test_spread_starts_in_one_coordinate_and_the_largest_difference_decides():
    grid = np.array([[0.0], [0.1], [0.2], [0.3]])  # 0.2 - 0.1 and 0.3 - 0.2 are not exactly 0.1 in binary
    gaps = np.abs(np.diff(grid[:, 0]))
    picks = [int(p) for p in spread_starts(np.arange(4), grid, 4)]
    taken = [0]
    for i in range(1, 4):
        if min(abs(grid[i, 0] - grid[t, 0]) for t in taken) > 0.1:
            taken.append(i)
    assert picks == taken and gaps[0] == 0.1

"""The next wave's D-optimal runs where ties decide: a box with no earlier run, or only its centre run, is
symmetric, so candidates of equal prediction variance abound, and each tie goes to the candidate farthest from
every point already there, the runs this wave has just chosen included (then candidate order).  Checked against
the rule written out in tests/test_d_optimal_rule.py and, in two factors, against the known answer: after the
first corner the opposite one, not the next corner in the grid's order."""

from __future__ import annotations

import numpy as np
import pytest

from demid.wave_runs import candidate_points, d_optimal_augment
from tests.test_d_optimal_rule import _by_the_rule


def test_two_factors_without_earlier_runs_take_opposite_corners_first():
    runs = d_optimal_augment(np.zeros((0, 2)), 4, 2)
    assert runs.tolist() == [[-1.0, -1.0], [1.0, 1.0], [-1.0, 1.0], [1.0, -1.0]]


@pytest.mark.parametrize("k", [1, 2, 3])
@pytest.mark.parametrize("start", ["none", "centre", "two centres"])
@pytest.mark.parametrize("count", [2, 5, 9])
def test_ties_in_a_symmetric_box_go_to_the_candidate_farthest_from_the_runs_chosen_so_far(k, start, count):
    existing = {"none": np.zeros((0, k)), "centre": np.zeros((1, k)), "two centres": np.zeros((2, k))}[start]
    found = d_optimal_augment(existing, count, k)
    assert found.shape == (count, k)
    assert np.allclose(found, _by_the_rule(existing, count, k, candidate_points(k)))
    # every run is a distinct candidate until the grid is used up, none the centre already run
    if count <= len(candidate_points(k)) - len(existing[:1]):
        assert len({tuple(r) for r in found}) == count
        assert not (len(existing) and any(np.allclose(r, 0.0) for r in found))

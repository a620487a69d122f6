"""The next wave's D-optimal runs where ties decide: a box with no earlier run, or only its centre run, is
symmetric, so candidates of equal prediction variance abound, and each tie goes to the candidate farthest from
every point already there, the runs this wave has just chosen included (then candidate order).  Checked against
the rule written out in tests/test_d_optimal_rule.py and, in two factors, against the known answer: after the
first corner the opposite one, not the next corner in the grid's order.  Distances that agree to nine decimals are
a tie."""

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


@pytest.mark.parametrize("gap, farther_wins", [(3e-9, True), (2e-10, False)])
def test_equally_informative_candidates_go_to_the_farther_unless_their_distances_agree_to_nine_decimals(gap,
                                                                                                        farther_wins):
    """Around a centre run the prediction variance of a two-factor quadratic grows with a^2 + b^2 + a^2 b^2 + a^4
    + b^4 alone (M is diagonal): (1, 0) and the point at angle theta on the same level, r^2 + r^4 (1 - s) = 2 with
    s = cos^2 sin^2 theta, are equally informative, the latter farther from the centre by about s / 6.  A distance
    3e-9 larger is farther; one 2e-10 larger agrees to nine decimals, a tie that goes to candidate order."""
    s = 6 * gap
    theta = np.arcsin(2 * np.sqrt(s)) / 2
    r2 = (np.sqrt(1 + 8 * (1 - s)) - 1) / (2 * (1 - s))
    other = np.sqrt(r2) * np.array([np.cos(theta), np.sin(theta)])
    cands = np.array([[1.0, 0.0], other])
    a, b = cands.T
    level = a ** 2 + b ** 2 + a ** 2 * b ** 2 + a ** 4 + b ** 4
    assert abs(level[1] - level[0]) < 1e-14 and np.linalg.norm(other) - 1 == pytest.approx(gap, rel=0.01)
    chosen = d_optimal_augment(np.zeros((1, 2)), 1, 2, cands)
    assert chosen.tolist() == [cands[1 if farther_wins else 0].tolist()]

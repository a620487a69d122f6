"""Scores below a millionth of the largest count as nil in the boundary batch, at any score scale: once the one
candidate on the boundary is taken, its neighbours' leftover scores (a hundred millionth of it, as a
classification error far from the set's boundary is) do not hold the next runs next to it; distance alone decides,
and they go to the corners of the square, the farthest points, as a space-filling design would put them."""

from __future__ import annotations

import numpy as np
import pytest

from demid.boundary_runs import greedy_batch


@pytest.mark.parametrize("scale", [1e-6, 1e-3, 0.5])  # a classification error min(p, 1 - p) is at most 0.5
def test_runs_after_the_boundary_go_by_distance_not_by_nil_scores(scale):
    axis = np.linspace(0.0, 1.0, 11)
    cand = np.column_stack([g.ravel() for g in np.meshgrid(axis, axis, indexing="ij")])
    to_centre = np.linalg.norm(cand - 0.5, axis=1)
    score = np.zeros(len(cand))
    score[to_centre < 1e-9] = scale
    score[(to_centre > 1e-9) & (to_centre < 0.15)] = 1e-8 * scale  # the centre's eight neighbours
    picks = greedy_batch(score, cand, np.empty((0, 2)), 3, 0.5)
    assert to_centre[picks[0]] < 1e-9
    corners = {i for i, c in enumerate(cand) if set(c) <= {0.0, 1.0}}
    # every corner is 0.71 from the centre, at least as far from any other pick, farther than any other point
    assert set(picks[1:]) <= corners and picks[1] != picks[2]

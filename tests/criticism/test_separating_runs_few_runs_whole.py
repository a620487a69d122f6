"""Separating runs (criticism.separating_runs) from runs that do not estimate the quadratic, as a next wave's box may
hold: a replicated centre and the two ends of one axis.  On that axis the runs take three levels, so a cube of the
factor is the factor itself there; the run proposed must give the axis a fourth level, after which the cube is
estimable beside every quadratic term the runs estimate (the rank of the quadratic's columns with the cube is one
more than without it, counted here by numpy)."""

from __future__ import annotations

import numpy as np
import pytest

from demid.criticism import separating_runs
from demid.design import model_matrix, quadratic_terms


def _gain(points: np.ndarray, member) -> int:
    base = model_matrix(points, quadratic_terms(points.shape[1]))
    both = np.column_stack([base, model_matrix(points, [member])])
    return int(np.linalg.matrix_rank(both) - np.linalg.matrix_rank(base))


@pytest.mark.parametrize("k, axis", [(2, 0), (2, 1), (3, 0), (3, 2)])
def test_a_cube_aliased_with_its_factor_on_one_axis_gets_a_fourth_level_there(k, axis):
    runs = np.zeros((4, k))
    runs[2, axis], runs[3, axis] = 1.0, -1.0
    member = tuple(3 if i == axis else 0 for i in range(k))
    assert _gain(runs, member) == 0
    pts = separating_runs(runs, quadratic_terms(k), [member], 1.0)
    assert len(pts) == 1
    point = pts[0]
    assert np.all(np.delete(point, axis) == 0.0) and point[axis] not in (-1.0, 0.0, 1.0)
    assert _gain(np.vstack([runs, pts]), member) == 1

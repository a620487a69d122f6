"""A three-factor set of zero thickness (the plane u2 = 1/2 at zero tolerance) has no area in any slice across it:
Solid.span then slices the other way, along the plane, where the slice through its admissible seed holds the whole
plane.  Each factor along the plane spans the whole range; the documented fallback for a seed on a measure-zero
part of the set, reached for the first and the second coordinate."""

from __future__ import annotations

import numpy as np
import pytest

from demid.sampling.planes import Solid


def _plane(axis: int, level: float) -> Solid:
    tensor = np.zeros((1, 2, 2, 2))  # one residual, degree 1 in each unit coordinate
    tensor[0, 0, 0, 0] = -level
    tensor[(0, *[int(a == axis) for a in range(3)])] = 1.0
    return Solid(tensor, 0.0)


@pytest.mark.parametrize("coord", [0, 1])
def test_a_plane_across_the_first_slices_is_spanned_by_slicing_along_it(coord):
    solid = _plane(2, 0.5)
    assert solid.seed is not None and solid.seed[2] == 0.5
    assert solid.span(coord) == (0.0, 1.0)

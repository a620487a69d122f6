"""A three-factor exact set is integrated slice by slice along its widest span (the documented slicing axis): a
thin tube along each coordinate in turn reports the fraction and the error estimate of the integration along that
coordinate, and the fraction is the annulus' closed-form area times the tube's length."""

from __future__ import annotations

import math

import numpy as np
import pytest

from demid.sampling.exact import Polynomial, exact_set

TARGET, TOLERANCE = 4e-4, 0.99  # (u_a - 1/2)^2 + (u_b - 1/2)^2 within 4e-6 .. 7.96e-4: an annulus' tube


@pytest.mark.parametrize("long_axis", [0, 1, 2])
def test_a_tube_is_sliced_along_its_length(long_axis):
    exponents = [[2, 0, 0], [0, 2, 0], [0, 0, 2], [1, 0, 0], [0, 1, 0], [0, 0, 1], [0, 0, 0]]
    coefficients = np.zeros(7)
    for a in range(3):
        if a != long_axis:
            coefficients[a], coefficients[3 + a] = 1.0, -1.0
    coefficients[6] = 0.5
    aset = exact_set([Polynomial(np.array(exponents), coefficients)], [TARGET], TOLERANCE, [0.0] * 3, [1.0] * 3)
    spans = aset.spans
    assert spans["width"].to_numpy().argmax() == long_axis and spans["width"].iloc[long_axis] == 1.0
    along = aset._shape.integral(long_axis, 0.0, 1.0)
    assert (aset.fraction, aset.fraction_error) == along
    area = math.pi * TARGET * ((1 + TOLERANCE) - (1 - TOLERANCE))
    assert aset.fraction == pytest.approx(area, rel=1e-9)

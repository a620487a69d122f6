"""The reference distance and nearest point of an exact set against closed forms, from every direction.

The set is a ring (2 factors) or a shell (3 factors), ``r_in <= |x - c| <= r_out``: the strict set of
``y = s (|x - c|^2 + k)`` at the target ``s t`` (either sign ``s``), on a box whose factors share one range,
so that in fractions of the range the ring stays round.  A reference outside the ring is ``|ref - c| - r_out``
from it, one inside its hole ``r_in - |ref - c|``, the nearest point on the ray from c through the reference.
The directions include those within a few hundredths of a radian of the lines the set is cut along, where the
nearest point lies a hair from the end of a piece of the slicing."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.sampling.exact import Polynomial, exact_set


def _shifted_squares(c: np.ndarray, k: float, sign: float) -> Polynomial:
    """sign * (sum_i (x_i - c_i)^2 + k)."""
    dim = len(c)
    exps, coef = [[0] * dim], [sign * (float(np.sum(c ** 2)) + k)]
    for i in range(dim):
        e1, e2 = [0] * dim, [0] * dim
        e1[i], e2[i] = 1, 2
        exps += [e1, e2]
        coef += [-2 * sign * c[i], sign]
    return Polynomial(np.array(exps), np.array(coef))


#: Angles (radians) off an axis: on it, a hair off it, and well off it.
OFF_AXIS = [0.0, 0.002, -0.004, 0.008, -0.015, 0.03, 0.2, -0.45]


@given(seed=st.integers(0, 10_000), dim=st.sampled_from([2, 2, 2, 3]), sign=st.sampled_from([-1.0, 1.0]),
       quarter=st.integers(0, 3), off=st.sampled_from(OFF_AXIS), outside=st.booleans(),
       tilt=st.sampled_from([0.0, 0.01, 0.7]))
@settings(max_examples=16, deadline=None, derandomize=True)
def test_the_distance_to_a_ring_is_its_closed_form_from_every_direction(seed, dim, sign, quarter, off, outside,
                                                                         tilt):
    rng = np.random.default_rng(seed)
    width = 10.0 ** rng.uniform(-1, 2)
    lower = rng.normal(size=dim) * width
    upper = lower + width
    c = lower + width * rng.uniform(0.45, 0.55, dim)
    r_out = width * rng.uniform(0.2, 0.3)
    r_in = r_out * rng.uniform(0.4, 0.7)
    # |x - c|^2 + k within eps |t| of t: r_in^2 + k = t (1 - eps), r_out^2 + k = t (1 + eps)
    t_mid = 2.0 * r_out ** 2
    eps = (r_out ** 2 - r_in ** 2) / (2 * t_mid)
    k = t_mid - (r_out ** 2 + r_in ** 2) / 2
    angle = quarter * np.pi / 2 + off
    direction = np.zeros(dim)
    direction[:2] = [np.cos(angle), np.sin(angle)]
    if dim == 3:
        direction = np.array([direction[0] * np.cos(tilt), direction[1] * np.cos(tilt), np.sin(tilt)])
    along = (r_out + rng.uniform(0.05, 0.18) * width) if outside else r_in * rng.uniform(0.1, 0.8)
    ref = c + along * direction
    es = exact_set([_shifted_squares(c, k, sign)], [sign * t_mid], eps, lower, upper, reference=ref)
    gap = (along - r_out) if outside else (r_in - along)
    assert es.reference_distance == pytest.approx(gap / width, rel=1e-7)
    nearest = c + (r_out if outside else r_in) * direction
    np.testing.assert_allclose(es.nearest_point, nearest, atol=1e-5 * width)
    assert np.linalg.norm(es.nearest_point - ref) / width == pytest.approx(es.reference_distance, rel=1e-7)

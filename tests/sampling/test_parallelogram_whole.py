"""Two linear observables in two factors: their strict set is the parallelogram where the two bands cross.  Its
area (the fraction), spans (its vertices' extremes) and a reference's distance are closed forms; the bands are
drawn at any angle, of any width, targets of either sign, the parallelogram inside the box.  The vertices lie
where an edge of one band crosses an edge of the other, off the lines the set is cut along: the slicing must
find them."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.sampling.exact import Polynomial, exact_set


@given(seed=st.integers(0, 10_000), signs=st.tuples(st.sampled_from([-1.0, 1.0]), st.sampled_from([-1.0, 1.0])),
       eps=st.sampled_from([0.01, 0.05, 0.1]))
@settings(max_examples=15, deadline=None, derandomize=True)
def test_the_crossing_of_two_bands_is_its_parallelogram(seed, signs, eps):
    rng = np.random.default_rng(seed)
    lower = rng.normal(size=2) * 3
    width = 10.0 ** rng.uniform(-1, 1, 2)
    upper = lower + width
    centre = lower + width * rng.uniform(0.4, 0.6, 2)
    angles = rng.uniform(0, np.pi, 2)
    angles[1] = angles[0] + rng.uniform(0.3, np.pi - 0.3)  # the bands cross at 17 degrees or more
    polys, targets, half = [], [], []
    for k in range(2):
        normal = np.array([np.cos(angles[k]), np.sin(angles[k])]) / width  # unit coordinates' normal, model units
        target = signs[k] * 10.0 ** rng.uniform(0, 2)
        # y_k = target + g_k (x - centre) . normal; the band |y_k - target| <= eps |target| is |(u - uc).n| <= h_k
        g = abs(target) * eps / rng.uniform(0.01, 0.04)
        polys.append(Polynomial(np.array([[0, 0], [1, 0], [0, 1]]),
                                np.array([target - g * centre @ normal, g * normal[0], g * normal[1]])))
        targets.append(target)
        half.append(eps * abs(target) / g)
    es = exact_set(polys, targets, eps, lower, upper)
    n = np.array([[np.cos(a), np.sin(a)] for a in angles])  # normals in unit coordinates
    det = abs(np.linalg.det(n))
    assert es.fraction == pytest.approx(4 * half[0] * half[1] / det, rel=1e-6)
    uc = (centre - lower) / width
    vertices = np.array([uc + np.linalg.solve(n, [s0 * half[0], s1 * half[1]]) for s0 in (-1, 1) for s1 in (-1, 1)])
    assert np.all((vertices > 0) & (vertices < 1))
    want = lower[:, None] + width[:, None] * np.column_stack([vertices.min(axis=0), vertices.max(axis=0)])
    np.testing.assert_allclose(es.model_spans, want, atol=1e-9 * width.max())

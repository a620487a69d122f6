"""Roots of quartics and quintics with well-separated roots in [0, 1] are as accurate as the polynomial can be
evaluated: each within twice eps * sum |c_i| t^i / |p'(t)| of the root it was built from (the error of evaluating p
near t, divided by its slope), the accuracy the companion eigenvalues reach only after their Newton steps.  Over
random roots, scales and signs, many polynomials in one call."""

from __future__ import annotations

import numpy as np
import pytest
from numpy.polynomial import polynomial as P

from demid.sampling.roots import real_roots_unit

EPS = np.finfo(float).eps


@pytest.mark.parametrize("degree, seed", [(4, 0), (4, 1), (5, 0), (5, 2)])
def test_separated_roots_are_found_to_the_accuracy_of_evaluating_the_polynomial(degree, seed):
    rng = np.random.default_rng(seed)
    built, rows = [], []
    while len(rows) < 30:
        t = np.sort(rng.uniform(0.02, 0.98, degree))
        if np.min(np.diff(t)) <= 0.08:
            continue
        built.append(t)
        rows.append(P.polyfromroots(t) * rng.uniform(0.1, 100) * rng.choice([-1, 1]))
    found = np.sort(real_roots_unit(np.array(rows)), axis=1)
    for t, c, got in zip(built, rows, found):
        assert np.all(np.isfinite(got)), (t, got)
        limit = EPS * P.polyval(t, np.abs(c)) / np.abs(P.polyval(t, P.polyder(c)))
        assert np.all(np.abs(got - t) <= 2 * limit), (t, (got - t) / limit)

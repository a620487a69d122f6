"""The grid's feasible fraction and its error estimate over generated annuli of known area (centres, radii,
tolerances and grid sizes varied, coarse grids included): the estimate bounds the true error, as the
estimator promises."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.design import quadratic_terms
from demid.sampling import Domain
from demid.sampling.grid import fraction_with_error
from demid.surrogate import Surrogate

SQUARE = Domain(("a", "b"), (0.0, 0.0), (1.0, 1.0))


def _ring(center) -> Surrogate:
    """y = |x − center|², in the terms' own order."""
    terms = quadratic_terms(2)
    coef = []
    for t in terms:
        powers = tuple(int(p) for p in t)
        coef.append({(0, 0): float(np.sum(np.square(center))), (1, 0): -2 * center[0], (0, 1): -2 * center[1],
                     (2, 0): 1.0, (0, 2): 1.0}.get(powers, 0.0))
    return Surrogate("y", ["a", "b"], terms, np.array(coef), np.zeros((len(terms), len(terms))), 0.0, 10)


@given(cx=st.floats(0.4, 0.6), cy=st.floats(0.4, 0.6), r0=st.floats(0.12, 0.3), eps=st.floats(0.03, 0.4),
       n=st.sampled_from([9, 13, 21, 41]))
@settings(max_examples=15, deadline=None, derandomize=True)
def test_the_reported_error_bounds_the_true_error_of_an_annulus_fraction(cx, cy, r0, eps, n):
    target = r0 ** 2
    exact = np.pi * target * 2 * eps  # pi r0^2 (1 + eps) - pi r0^2 (1 - eps), inside the unit square
    est = fraction_with_error({"y": _ring((cx, cy))}, SQUARE, ["y"], {"y": target}, eps, n)
    assert abs(est.fraction - exact) <= est.error


"""The grid evaluator's fraction and its error estimate do not depend on where the search range starts: the same
annulus over a range shifted by any amount (the range not starting at 0, or negative) gives the same fraction and
the same error estimate as over the unit square."""

from __future__ import annotations

import numpy as np
import pytest

from demid.design import quadratic_terms
from demid.sampling import Domain
from demid.sampling.grid import fraction_with_error
from demid.surrogate import Surrogate


def _ring(center) -> Surrogate:
    """y = |x − center|² in actual units, in the terms' own order."""
    terms = quadratic_terms(2)
    values = {(0, 0): float(np.sum(np.square(center))), (1, 0): -2 * center[0], (0, 1): -2 * center[1],
              (2, 0): 1.0, (0, 2): 1.0}
    coef = [values.get(tuple(int(p) for p in t), 0.0) for t in terms]
    return Surrogate("y", ["a", "b"], terms, np.array(coef), np.zeros((len(terms), len(terms))), 0.0, 10)


@pytest.mark.parametrize("shift", [(2.0, 3.0), (-5.0, 0.5), (10.0, -7.0)])
@pytest.mark.parametrize("n, eps, r0", [(13, 0.2, 0.22), (21, 0.08, 0.22), (13, 0.5, 0.03), (9, 0.6, 0.05)])
def test_a_shifted_range_gives_the_same_fraction_and_error(shift, n, eps, r0):
    """The last two annuli lie inside a cell or two, whose corners all miss the band: those cells are sub-sampled
    at points placed from the range's start and the grid step."""
    centre = np.array([0.47, 0.53])
    target = r0 ** 2
    at_origin = fraction_with_error({"y": _ring(centre)}, Domain(("a", "b"), (0.0, 0.0), (1.0, 1.0)), ["y"],
                                    {"y": target}, eps, n)
    lo = np.array(shift)
    shifted = fraction_with_error({"y": _ring(centre + lo)}, Domain(("a", "b"), tuple(lo), tuple(lo + 1.0)), ["y"],
                                  {"y": target}, eps, n)
    assert shifted.fraction == pytest.approx(at_origin.fraction, rel=1e-6, abs=1e-9)
    assert shifted.error == pytest.approx(at_origin.error, rel=1e-6, abs=1e-9)
    if r0 > 0.1:  # an annulus resolved by the grid: the estimate bounds the true error (not so inside one cell)
        assert abs(shifted.fraction - np.pi * target * 2 * eps) <= shifted.error

"""The reference point is said to lie outside the search range only when it is more than 0.1 % of the
range beyond a bound (the same tolerance as the runs' own range): exactly 0.1 % below is inside, the next
representable value below that is outside.  The position is computed here independently, in actual units."""
from __future__ import annotations

import numpy as np
import pytest

from demid.criticism.edges import extrapolation_warnings
from demid.sampling.domain import Domain

TOL = 1e-3


@pytest.mark.parametrize("lower, upper", [(0.0, 1000.0), (0.0, 1.0), (0.0, 8.0)])
def test_reference_point_beyond_the_search_range_at_the_tolerance(lower, upper):
    domain = Domain(("a", "b"), (lower, 0.0), (upper, 1.0), (False, False))
    runs = np.array([[lower, 0.0], [upper, 1.0], [lower, 1.0], [upper, 0.0]])
    at_tol = lower - TOL * (upper - lower)
    assert (at_tol - lower) / (upper - lower) == -TOL  # exactly at the tolerance, to the last bit
    past = np.nextafter(at_tol, -np.inf)
    for a, beyond in ((at_tol, False), (past, True), (lower, False), (upper + TOL * (upper - lower), False)):
        text = " ".join(extrapolation_warnings(domain, runs, {"a": a, "b": 0.5}))
        assert ("outside the search range" in text) == beyond, (a, text)

"""A stationary point exactly on the box's edge tolerance (1e-9 coded units beyond a bound) is inside; one ulp
further is not.  The surfaces are built so that x_s = -1/2 B^-1 b lands on those doubles exactly (B diagonal with
eigenvalues 1 and 2, powers of two: every step of the computation is exact)."""

import numpy as np
import pytest

from demid.canonical import canonical_analysis

BOXES = [((-1.0, -1.0), (1.0, 1.0)), ((-1.682, -1.414), (1.682, 1.414)), ((0.25, -3.0), (3.0, -0.5))]


def _surface_with_stationary_point(xs, eigen):
    """b and B of b0 + x'b + x'Bx with B = diag(eigen) and stationary point xs: b = -2 B xs."""
    big_b = np.diag(eigen)
    return -2.0 * big_b @ np.asarray(xs, dtype=float), big_b


@pytest.mark.parametrize("lo, hi", BOXES)
@pytest.mark.parametrize("factor", [0, 1])
@pytest.mark.parametrize("side", ["lower", "upper"])
@pytest.mark.parametrize("eigen", [(2.0, 1.0), (-1.0, -2.0), (1.0, -2.0)])
def test_stationary_point_on_the_edge_tolerance_is_inside_and_beyond_it_is_not(lo, hi, factor, side, eigen):
    centre = 0.5 * (np.asarray(lo) + np.asarray(hi))
    edge = lo[factor] - 1e-9 if side == "lower" else hi[factor] + 1e-9
    beyond = np.nextafter(edge, -np.inf if side == "lower" else np.inf)
    for x_f, expected in ((edge, True), (beyond, False)):
        xs = centre.copy()
        xs[factor] = x_f
        b, big_b = _surface_with_stationary_point(xs, eigen)
        c = canonical_analysis(3.0, b, big_b, region_lower=lo, region_upper=hi)
        assert c.stationary_coded[factor] == x_f  # exact: the construction above
        assert c.inside is expected
        kind = {(True, True): "minimum", (False, False): "maximum"}.get(tuple(np.array(eigen) > 0), "saddle point")
        assert c.kind == kind
        assert c.value == pytest.approx(3.0 + xs @ b + xs @ big_b @ xs, rel=1e-12)

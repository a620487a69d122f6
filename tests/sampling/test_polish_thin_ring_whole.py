"""A ring thinner than the grid spacing, on which no node of the 11-grid is admissible: the polished span
starts from the 16 least-violating nodes and reaches the ring's exact extent (centre +- outer radius) on both
factors; from only 2 d = 4 of them one end of this ring stays short by about 0.24."""

from __future__ import annotations

import numpy as np
import pytest

from demid.sampling.domain import Domain
from demid.sampling.grid import admissible_set
from demid.sampling.polish import polish_spans
from demid.surrogate import Surrogate

SQUARE = Domain(("a", "b"), (-1.0, -1.0), (1.0, 1.0))


@pytest.mark.parametrize("cx, cy, r", [(-0.28298078093188733, 0.1315318636960442, 0.30479751885707157)])
def test_a_thin_ring_without_admissible_nodes_is_polished_to_its_extent(cx, cy, r):
    # y = (a - cx)^2 + (b - cy)^2 + 1, target r^2 + 1, relative tolerance 1e-5: a ring of radius r about (cx, cy)
    coefficients = np.array([cx ** 2 + cy ** 2 + 1, -2 * cx, -2 * cy, 1.0, 1.0])
    ring = Surrogate("y", ["a", "b"], [(0, 0), (1, 0), (0, 1), (2, 0), (0, 2)], coefficients, np.eye(5) * 1e-6,
                     0.01, 10)
    target, tolerance = r ** 2 + 1, 1e-5
    aset = admissible_set({"y": ring}, SQUARE, ["y"], {"y": target}, tolerance, 11)
    assert aset.n_admissible_nodes == 0 and not aset.empty
    lower, upper = polish_spans({"y": ring}, SQUARE, ["y"], {"y": target}, tolerance, aset)
    outer = np.sqrt(r ** 2 + tolerance * target)  # the ring's outer radius
    np.testing.assert_allclose(lower, [cx - outer, cy - outer], atol=1e-6)
    np.testing.assert_allclose(upper, [cx + outer, cy + outer], atol=1e-6)

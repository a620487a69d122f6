"""Spans of a three-factor grid set thinner than every sub-grid but the sampled cells': a sheet a = a0 ± 0.001
(between the 16-point sub-grid of the outermost slab, on a point of the 4-point sub-grid of the cells where two
observables are active) cut by a band of b, of either sign of its targets.  No node is admissible and the refinement
of the outermost slab finds nothing, so the spans come from the points the sampled cells hold: each within a
sub-step (step/4) of the exact set's, written out here, not the whole cells' extent."""

from __future__ import annotations

import numpy as np
import pytest

from demid.sampling import Domain
from demid.sampling.grid import admissible_set

from ..helpers import Linear

N = 11  # step 0.1; the sampled cells' sub-grid puts a-points at 0.3375, the slab's 16-point one at 0.3344, 0.3406
EPS = 0.001 / 0.3375  # the sheet's half-width in a


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_a_sheet_between_the_slab_sub_grid_keeps_the_spans_its_sampled_points_give(sign):
    domain = Domain(("a", "b", "c"), (0.0, 0.0, 0.0), (1.0, 1.0, 1.0))
    # y = a (target 0.3375) and w = b + 67 (target 67.45: b within 0.45 ± 0.1997), both of one sign
    fields = {"y": Linear(0.0, [sign, 0, 0]), "w": Linear(67.0 * sign, [0, sign, 0])}
    targets = {"y": 0.3375 * sign, "w": 67.45 * sign}
    exact_lower = np.array([0.3375 - 0.001, 0.45 - 67.45 * EPS, 0.0])
    exact_upper = np.array([0.3375 + 0.001, 0.45 + 67.45 * EPS, 1.0])
    aset = admissible_set(fields, domain, ["y", "w"], targets, EPS, N)
    assert aset.n_admissible_nodes == 0 and aset.fraction > 0
    step = 1.0 / (N - 1)
    assert np.all(aset.lower >= exact_lower - 1e-12) and np.all(aset.upper <= exact_upper + 1e-12)
    np.testing.assert_allclose(aset.lower, exact_lower, atol=step / 4)
    np.testing.assert_allclose(aset.upper, exact_upper, atol=step / 4)

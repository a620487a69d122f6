"""The closest approach of two planes whose targets are met together only beyond the box, against the closed form:
y1 = ±(a + b) with target ±t1 and y2 = ±(b - a) with target ±t2 over the unit square (either sign of each), met
together at b = (t1 + t2) / 2 > 1.  Inside the box the smallest largest relative error lies on the edge b = 1,
where the two errors are equal: a = (t1 - t2) / (t1 + t2), error (t1 - 1 - a) / t1 -- between the start grid's
nodes, and not where the point met outside would be clipped to, so the search must stay inside the box."""

from __future__ import annotations

import numpy as np
import pytest

from demid.sampling import Domain
from demid.sampling.evaluate import closest_approach
from demid.surrogate import Surrogate

SQUARE = Domain(("a", "b"), (0.0, 0.0), (1.0, 1.0))


def _plane(name, coefficients) -> Surrogate:
    return Surrogate(name, ["a", "b"], [(0, 0), (1, 0), (0, 1)], np.asarray(coefficients, dtype=float),
                     np.zeros((3, 3)), 0.0, 5)


@pytest.mark.parametrize("t1, t2, s1, s2, start", [(2.0, 0.6, 1, 1, None), (2.3, 0.4, -1, 1, (0.2, 0.3)),
                                                   (1.8, 0.9, 1, -1, None), (2.1, 0.35, -1, -1, (0.9, 0.1))])
def test_targets_met_beyond_the_box_are_approached_on_its_edge(t1, t2, s1, s2, start):
    surrogates = {"y1": _plane("y1", [0.0, s1, s1]), "y2": _plane("y2", [0.0, -s2, s2])}
    targets = {"y1": s1 * t1, "y2": s2 * t2}
    a = (t1 - t2) / (t1 + t2)
    expected = (t1 - 1 - a) / t1
    assert expected == pytest.approx((a + t2 - 1) / t2, rel=1e-12)  # both errors equal there
    # a brute force over a fine grid agrees (and is never below the closed form)
    g = np.linspace(0.0, 1.0, 1001)
    ga, gb = np.meshgrid(g, g, indexing="ij")
    worst = np.maximum(np.abs(ga + gb - t1) / t1, np.abs(gb - ga - t2) / t2)
    assert expected - 1e-12 <= worst.min() <= expected + 1e-3
    value, point = closest_approach(surrogates, SQUARE, ("y1", "y2"), targets,
                                    None if start is None else np.array([start]))
    assert value == pytest.approx(expected, rel=1e-7)
    np.testing.assert_allclose(point, [a, 1.0], atol=1e-6)

"""An exact surrogate (zero prediction error) classifies every point for certain, whatever the response's scale:
the set probability is 1 inside every band and 0 outside it, down to a hundredth of the band from its edges,
for responses of size 1e-9 and 1e9 alike (the standard error's floor is a fraction of the band, not a number
in the response's units)."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from demid.boundary_runs import classification_error, set_probability
from demid.sampling import Domain

from .test_boundary_runs_whole import _Plane


@pytest.mark.parametrize("scale", [1e-9, 1.0, 1e9])
@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_an_exact_surrogate_classifies_every_point_for_certain_at_any_scale(scale, sign):
    domain = Domain(("a", "b"), (1.0, -1.0), (3.0, 2.0))
    tolerance = 0.05
    targets = {"y": sign * 4.0 * scale, "z": -2.5 * scale}
    # y rises along a, z along b; each meets its target at a = 2, b = 0.5
    surrogates = {"y": _Plane(domain, np.array([sign * 2.0 * scale, 0.0]), sign * 0.0 * scale, 0.0, np.zeros(2)),
                  "z": _Plane(domain, np.array([0.0, 1.0 * scale]), -3.0 * scale, 0.0, np.zeros(2))}
    judged = SimpleNamespace(spec=SimpleNamespace(domain=domain), observables=["y", "z"], targets=targets,
                             surrogates=surrogates, tolerance=tolerance)
    half_a = tolerance * 4.0 / 2.0      # the band of y along a: |2 (a - 2)| <= 0.2
    half_b = tolerance * 2.5 / 1.0      # the band of z along b: |b - 0.5| <= 0.125
    shares = np.array([0.0, 0.5, 0.99, 1.01, 1.5])
    a = 2.0 + np.concatenate([shares, -shares]) * half_a
    b = 0.5 + np.concatenate([shares, -shares]) * half_b
    points = np.array([[x, y] for x in a for y in b])
    expected = ((np.abs(points[:, 0] - 2.0) < half_a) & (np.abs(points[:, 1] - 0.5) < half_b)).astype(float)
    np.testing.assert_array_equal(set_probability(judged, points), expected)
    np.testing.assert_array_equal(set_probability(judged, points, inflation=3.0), expected)
    np.testing.assert_array_equal(classification_error(judged, points), np.zeros(len(points)))

"""Every label demid.design.classify_points gives (centre, factorial, axial, Box-Behnken edge, other) against the
rule written out coordinate by coordinate: a coordinate is at 0 or at +-1 when it is strictly within ``atol`` of
it, and at +-alpha when strictly within ``atol`` times the larger of alpha and 1 (so an axial distance below 1, an
inscribed CCD's, keeps the tolerance of the unit levels); an axial point has every other coordinate at 0, an edge
point two coordinates at +-1 and the rest at 0.

Generated points of two to four factors whose coordinates sit on a level, near it (inside and outside each
tolerance) or between levels, one axial distance or one per factor, from 0.5 to 2; and the tolerances' own edges,
met exactly with binary fractions."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.design import classify_points


def _label_by_the_rule(point, alphas, atol):
    at_zero = [abs(v) < atol for v in point]
    at_one = [abs(abs(v) - 1) < atol for v in point]
    at_alpha = [abs(abs(v) - a) < atol * max(a, 1.0) for v, a in zip(point, alphas)]
    if all(at_zero):
        return "center"
    if all(at_one):
        return "factorial"
    if sum(at_zero) == len(point) - 1 and sum(at_alpha) == 1:
        return "axial"
    if all(z or o for z, o in zip(at_zero, at_one)) and sum(at_one) == 2:
        return "edge"
    return "other"


_OFFSETS = [0.0, 0.0, 0.4, -0.6, 0.9, -1.1, 1.6, -2.5]  # in units of atol


@given(k=st.integers(2, 4), alpha=st.sampled_from([0.5, 0.8, 1.0, 1.41421, 2.0]), per_factor=st.booleans(),
       atol=st.sampled_from([1e-3, 1e-2]), data=st.data())
@settings(max_examples=30, deadline=None, derandomize=True)
def test_every_label_is_the_rule_written_out(k, alpha, per_factor, atol, data):
    rng = np.random.default_rng(data.draw(st.integers(0, 10_000)))
    alphas = alpha * rng.uniform(0.9, 1.1, k) if per_factor else np.full(k, alpha)
    points = []
    for _ in range(12):
        kind = rng.choice(["center", "factorial", "axial", "edge", "any"])
        base = np.zeros(k)
        if kind == "factorial":
            base = rng.choice([-1.0, 1.0], k)
        elif kind == "axial":
            i = rng.integers(k)
            base[i] = rng.choice([-1.0, 1.0]) * alphas[i]
        elif kind == "edge":
            i, j = rng.choice(k, 2, replace=False)
            base[[i, j]] = rng.choice([-1.0, 1.0], 2)
        elif kind == "any":
            base = rng.choice([0.0, 1.0, -1.0, 0.5], k)
        # move one coordinate by a few tolerances (an axial one by its own, scaled tolerance)
        i = rng.integers(k)
        scale = atol * (max(alphas[i], 1.0) if kind == "axial" and base[i] != 0 else 1.0)
        base[i] += rng.choice(_OFFSETS) * scale
        points.append(base)
    points = np.array(points)
    labels = classify_points(points, alphas if per_factor else alpha, atol=atol)
    assert list(labels) == [_label_by_the_rule(p, alphas, atol) for p in points]


A = 2.0 ** -10  # a binary fraction: each edge below is met exactly, without rounding


@pytest.mark.parametrize("point, alpha, label", [
    ((A, 0.0), 2.0, "other"),                      # exactly atol off 0: not at 0
    ((A * 0.5, 0.0), 2.0, "center"),
    ((1.0 + A, 1.0), 2.0, "other"),                # exactly atol off 1
    ((1.0 + A / 2, -1.0), 2.0, "factorial"),
    ((2.0 + 2 * A, 0.0), 2.0, "other"),            # exactly atol * alpha off alpha = 2
    ((2.0 + 1.5 * A, 0.0), 2.0, "axial"),          # inside atol * alpha, outside atol
    ((0.0, -0.5 - 0.75 * A), 0.5, "axial"),        # alpha below 1: within atol, outside atol * alpha
    ((0.0, 0.5 + A), 0.5, "other"),                # exactly atol off alpha = 0.5
    ((1.0, 0.0, -1.0 + A / 2), 1.5, "edge"),
    ((1.0, A, -1.0), 1.5, "other"),                # one coordinate exactly atol off 0
])
def test_the_tolerances_edges(point, alpha, label):
    assert classify_points(np.array([point]), alpha, atol=A)[0] == label

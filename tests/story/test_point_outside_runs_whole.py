"""Whether the recommended point lies outside the region the design runs cover, judged in search units (log10 for a
log-scale factor), against the hull written out here: runs on the axial points of a star (a cross-polytope) about
the middle of the search box, whose hull is |u_1 - 1/2| + ... + |u_k - 1/2| <= r in the box's unit coordinates; over
2-3 factors, linear and log ranges away from the origin, and points inside and outside it, off every bound."""

from __future__ import annotations

import numpy as np
import pytest

from demid.spec import MaterialSpec
from demid.story.recommended import point_on_edge_text

_OUTSIDE = ("⚠ The point lies outside the region the design runs cover (their convex hull): its predictions are the "
            "quadratic's extrapolation, backed by no simulation, so simulate it before relying on it.")


def _spec(rng, k: int):
    factors = {}
    for i in range(k):
        if i == 0 or rng.random() < 0.5:  # a log range of one to three decades, away from 1 (at least one)
            lo = 10.0 ** rng.uniform(-4, 2)
            block = {"lower": lo, "upper": lo * 10.0 ** rng.uniform(1, 3), "scale": "log"}
        else:
            lo = rng.uniform(-50, 50)
            block = {"lower": lo, "upper": lo + rng.uniform(0.5, 40)}
        factors[f"f{i}"] = block
    return MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "custom"}, "factors": factors, "responses": {"y": {"target": 3.0}},
        "scenarios": {"s": {"observables": ["y"], "tolerance": 0.05}}}, grid_points=11)


@pytest.mark.parametrize("seed", range(5))
def test_a_point_is_outside_the_runs_exactly_where_it_leaves_their_hull_in_search_units(seed):
    rng = np.random.default_rng(seed)
    k = int(rng.integers(2, 4))
    spec = _spec(rng, k)
    lo, hi = spec.domain.search_bounds()
    radius = 0.45
    star = np.vstack([0.5 + radius * s * np.eye(k)[i] for i in range(k) for s in (-1.0, 1.0)])
    runs = spec.domain.to_actual(lo + star * (hi - lo))
    seen = set()
    for _ in range(12):
        u = rng.uniform(0.1, 0.9, size=k)
        l1 = float(np.abs(u - 0.5).sum())
        if abs(l1 - radius) < 0.02:
            continue  # clear of the hull's face by more than its tolerance
        point = dict(zip(spec.factor_names, spec.domain.to_actual(lo + u * (hi - lo))[0]))
        outside = l1 > radius
        seen.add(outside)
        assert point_on_edge_text(spec, point, runs, {}, set()) == (_OUTSIDE if outside else "")
    assert seen == {True, False}

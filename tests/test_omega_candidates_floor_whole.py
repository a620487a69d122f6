"""The candidate grid over Omega where its floor of five nodes per axis decides: six factors, whose 4096-point
budget alone would give four nodes per axis (4096 ** (1/6) = 4), get five, on each factor's search range."""

from __future__ import annotations

import itertools

import numpy as np

from demid.boundary_runs import GRID_POINTS_ALL, omega_candidates
from demid.scenario import JudgedScenario
from demid.spec import MaterialSpec


def test_six_factors_get_the_floor_of_five_nodes_per_axis_not_the_budgets_four():
    k = 6
    assert round(GRID_POINTS_ALL ** (1 / k)) == 4
    factors = {f"f{i}": ({"lower": 1e-2, "upper": 100.0, "scale": "log"} if i == 0 else
                         {"lower": -1.0 - i, "upper": 2.0 * i + 0.5}) for i in range(k)}
    spec = MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "custom"}, "factors": factors, "responses": {"y": {"target": -3.0}},
        "scenarios": {"s": {"observables": ["y"], "tolerance": 0.05}}})
    judged = JudgedScenario(spec, spec.scenarios[0], {}, 2.0)
    lo, hi = spec.domain.search_bounds()
    expected = np.array(list(itertools.product(*[np.linspace(a, b, 5) for a, b in zip(lo, hi)])))
    grid = omega_candidates(judged)
    assert grid.shape == (5 ** k, k)
    assert np.array_equal(grid, expected)
    assert (grid[:, 0].min(), grid[:, 0].max()) == (-2.0, 2.0)  # log10 of the first factor's range

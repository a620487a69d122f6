"""plausible_sets called without scenarios judged beforehand: every scenario's plausible set on the n-grid holds
exactly the nodes where each observable meets |ŷ - y*| <= z sqrt(se² + σ²) (σ configured, or the scenario's
tolerance read as the measurement band, ε |y*| / z), written out here from the surrogates' predictions and
standard errors, for two scenarios of different observables and tolerances."""

from __future__ import annotations

import numpy as np
import pandas as pd

from demid.combinations.material import plausible_sets
from demid.design import ccd_points
from demid.spec import MaterialSpec
from demid.surrogate import fit_material

Z, N = 2.0, 31
SCENARIOS = {"y_only": (("y",), 0.04), "both": (("y", "w"), 0.08)}
SIGMA = {"y": 0.3, "w": None}


def _study():
    rng = np.random.default_rng(11)
    coded = ccd_points(2, 1.41421, 4)
    lower, upper = np.array([0.1, 2.0]), np.array([0.9, 18.0])
    actual = (lower + upper) / 2 + coded * (upper - lower) / (2 * 1.41421)
    table = pd.DataFrame(actual, columns=["a", "b"])
    table.insert(0, "run", np.arange(1, len(table) + 1))
    table["y"] = 10 + 2 * coded[:, 0] - coded[:, 1] + 0.5 * coded[:, 0] ** 2 + rng.normal(0, 0.2, len(table))
    table["w"] = 20 + 1.5 * coded[:, 1] + 0.8 * coded[:, 0] * coded[:, 1] + rng.normal(0, 0.3, len(table))
    table["status"] = "ok"
    spec = MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "ccd", "alpha": 1.41421, "center_runs": 4},
        "factors": {"a": {"lower": 0.1, "upper": 0.9}, "b": {"lower": 2.0, "upper": 18.0}},
        "responses": {"y": {"target": 10.5, "sigma": SIGMA["y"]}, "w": {"target": 20.8}},
        "scenarios": {name: {"observables": list(obs), "tolerance": tol} for name, (obs, tol) in SCENARIOS.items()}})
    surrogates = {f.response: f.surrogate() for f in fit_material(table, spec)}
    return spec, surrogates


def test_unjudged_plausible_sets_hold_the_nodes_within_every_band():
    spec, surrogates = _study()
    sets = plausible_sets(surrogates, spec, z=Z, n=N)
    assert set(sets) == set(SCENARIOS)
    nodes = spec.domain.grid(N)
    for name, (observables, tolerance) in SCENARIOS.items():
        aset = sets[name]
        assert tuple(aset.observables) == observables and aset.tolerance == tolerance
        inside = np.ones(len(nodes), dtype=bool)
        margin = np.full(len(nodes), np.inf)
        for o in observables:
            target = spec.targets[o]
            sigma = SIGMA[o] if SIGMA[o] is not None else tolerance * abs(target) / Z
            half = Z * np.sqrt(surrogates[o].se_mean(nodes) ** 2 + sigma ** 2)
            gap = half - np.abs(surrogates[o].predict(nodes) - target)
            inside &= gap >= 0
            margin = np.minimum(margin, np.abs(gap))
        clear = margin > 1e-9
        mask = np.asarray(aset.mask).ravel()
        assert 0 < inside.sum() < len(nodes)  # a set with a boundary, for the comparison to mean something
        np.testing.assert_array_equal(mask[clear], inside[clear])
        assert aset.n_admissible_nodes == int(mask.sum())
        assert aset.node_fraction == inside.sum() / len(nodes)

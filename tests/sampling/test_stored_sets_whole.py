"""The stored strict sets of one and three factors (the two-factor study is tests/sampling/test_stored_sets.py): a
scenario's state is one row per factor, so a set of one factor has a single row to read each number from, and a
set of three has three rows carrying the same fraction, error and distance.  Every stored number read back equals a
fresh evaluation, over targets of either sign."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from demid.admissibility import evaluate_scenarios
from demid.sampling import evaluate_set
from demid.sampling.stored import STATE_COLUMNS, set_state_frame, stored_strict_sets
from demid.scenario import judged_scenarios
from demid.spec import MaterialSpec
from demid.surrogate import fit_response

from ..helpers import make_ccd_table


def _material(dim: int, sign: float):
    names = [f"x{i + 1}" for i in range(dim)]
    lower, upper = [0.1, 1.0, -2.0][:dim], [0.9, 11.0, 2.0][:dim]

    def responses(x):
        base = 100 + 20 * x[:, 0] + 10 * x[:, 0] ** 2 + sum(0.5 * x[:, i] for i in range(1, dim))
        return {"y1": sign * base, "y2": 80 + 5 * x[:, 0] - 0.2 * x[:, -1] ** 2}

    material = {
        "data": "m.csv", "design": {"type": "ccd", "alpha": 1.41421, "center_runs": 5},
        "factors": {n: {"lower": lo, "upper": hi} for n, lo, hi in zip(names, lower, upper)},
        "responses": {"y1": {"target": sign * 115.0}, "y2": {"target": 84.0}},
        "scenarios": {"y1_only": {"observables": ["y1"], "tolerance": 0.02},
                      "both": {"observables": ["y1", "y2"], "tolerance": 0.04}},
        "reference_point": {n: lo + 0.1 * (hi - lo) for n, lo, hi in zip(names, lower, upper)},
    }
    table = make_ccd_table(responses, lower, upper, noise=0.2, seed=dim)
    spec = MaterialSpec.from_material("m", material, grid_points=21)
    surrogates = {r: fit_response(table, names, r).surrogate() for r in ("y1", "y2")}
    frame, sets = evaluate_scenarios(surrogates, spec)
    return spec, surrogates, frame.join(set_state_frame(sets)), sets


@pytest.mark.parametrize("dim, sign", [(1, 1.0), (1, -1.0), (3, -1.0)])
def test_stored_sets_of_one_and_three_factors_equal_a_fresh_evaluation(dim, sign):
    spec, surrogates, frame, sets = _material(dim, sign)
    state = set_state_frame(sets)
    assert list(state.columns) == STATE_COLUMNS and len(state) == dim * len(sets)
    stored = stored_strict_sets(frame, judged_scenarios(spec, surrogates, 2.0), reference=True)
    assert list(stored) == ["y1_only", "both"]
    for scen in spec.scenarios:
        fresh = evaluate_set(surrogates, spec.domain, scen.observables, spec.targets, scen.tolerance, 21,
                             reference=spec.reference_point)
        got = stored[scen.name]
        assert got.fraction == fresh.fraction and got.fraction_error == fresh.fraction_error
        np.testing.assert_array_equal(got.lower, fresh.lower)
        np.testing.assert_array_equal(got.upper, fresh.upper)
        assert got.exact.reference_distance == fresh.exact.reference_distance
        np.testing.assert_array_equal(got.exact.nearest_point, fresh.exact.nearest_point)
        assert got.best_error == sets[scen.name].best_error and got.tolerance == scen.tolerance
        assert got.at_bound == fresh.at_bound and len(got.at_bound) == dim


@pytest.mark.parametrize("dim", [1, 3])
def test_a_planted_state_is_read_back_from_a_scenarios_rows(dim):
    spec, surrogates, frame, _ = _material(dim, 1.0)
    planted = frame.copy()
    rows = planted["scenario"] == "both"
    planted.loc[rows, "exact_fraction"] = 0.321
    planted.loc[rows, "exact_fraction_error"] = 0.004
    planted.loc[rows, "reference_distance"] = 0.75
    got = stored_strict_sets(planted, judged_scenarios(spec, surrogates, 2.0), reference=True)["both"]
    assert (got.fraction, got.fraction_error, got.exact.reference_distance) == (0.321, 0.004, 0.75)
    without = stored_strict_sets(planted.drop(columns=["method"]), judged_scenarios(spec, surrogates, 2.0))
    assert without == {}

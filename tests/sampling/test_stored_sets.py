"""One set, one number: the strict sets the admissibility step stores are the sets the later steps use.

The uncertainty and criticism steps rebuild each exact set from the scenarios table instead of
evaluating it again; the rebuilt set must carry exactly the stored numbers (a planted change in the
table shows up, so nothing is recomputed) and equal a fresh evaluation bit for bit.
"""

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

MATERIAL = {
    "data": "m.csv",
    "design": {"type": "ccd", "alpha": 1.41421, "center_runs": 5},
    "factors": {"x1": {"lower": 0.1, "upper": 0.9}, "x2": {"lower": 1.0, "upper": 11.0}},
    "responses": {"y1": {"target": 115.0}, "y2": {"target": 95.0}},
    "scenarios": {"y1_only": {"observables": ["y1"], "tolerance": 0.02},
                  "both": {"observables": ["y1", "y2"], "tolerance": 0.03}},
    "reference_point": {"x1": 0.2, "x2": 2.0},
}


@pytest.fixture(scope="module", params=[0, 1])
def material(request):
    def responses(x):
        a, b = x[:, 0], x[:, 1]
        return {"y1": 100 + 20 * a - 2 * b + 10 * a ** 2 + 0.5 * a * b, "y2": 80 + 5 * a + 3 * b - 0.1 * b ** 2}

    table = make_ccd_table(responses, [0.1, 1.0], [0.9, 11.0], noise=0.3, seed=request.param)
    spec = MaterialSpec.from_material("m", MATERIAL, grid_points=101)
    surrogates = {r: fit_response(table, ["x1", "x2"], r).surrogate() for r in ("y1", "y2")}
    frame, sets = evaluate_scenarios(surrogates, spec)
    return spec, surrogates, frame.join(set_state_frame(sets)), sets


def test_rebuilt_sets_equal_a_fresh_evaluation(material):
    spec, surrogates, frame, _ = material
    stored = stored_strict_sets(frame, judged_scenarios(spec, surrogates, 2.0), reference=True)
    assert set(stored) == {"y1_only", "both"}
    for scen in spec.scenarios:
        fresh = evaluate_set(surrogates, spec.domain, scen.observables, spec.targets, scen.tolerance, 31,
                             reference=spec.reference_point)
        got = stored[scen.name]
        assert got.fraction == fresh.fraction and got.fraction_error == fresh.fraction_error
        assert np.array_equal(got.lower, fresh.lower) and np.array_equal(got.upper, fresh.upper)
        assert got.exact.reference_distance == fresh.exact.reference_distance
        assert np.array_equal(got.exact.nearest_point, fresh.exact.nearest_point)
        assert got.method == fresh.method
        assert got.at_bound == fresh.at_bound and len(got.at_bound) == spec.domain.dim  # level 2 reads it


def test_rebuilt_sets_carry_the_stored_numbers_not_new_ones(material):
    spec, surrogates, frame, sets = material
    planted = frame.copy()
    rows = planted["scenario"] == "both"
    planted.loc[rows, "exact_fraction"] = 0.123
    planted.loc[rows, "unit_upper"] = 0.5
    planted.loc[rows, "reference_distance"] = 0.25
    got = stored_strict_sets(planted, judged_scenarios(spec, surrogates, 2.0), reference=True)["both"]
    assert got.fraction == 0.123 and got.exact.fraction == 0.123
    assert got.exact.reference_distance == 0.25
    lo, hi = spec.domain.search_bounds()
    np.testing.assert_allclose(got.upper, lo + 0.5 * (hi - lo))  # linear factors: unit -> actual
    assert got.fraction != sets["both"].fraction


def test_a_table_without_state_or_for_another_tolerance_gives_no_stored_set(material):
    spec, surrogates, frame, _ = material
    assert stored_strict_sets(frame.drop(columns=STATE_COLUMNS), judged_scenarios(spec, surrogates, 2.0)) == {}
    other = frame.copy()
    other.loc[other["scenario"] == "both", "tolerance"] = 0.05
    assert set(stored_strict_sets(other, judged_scenarios(spec, surrogates, 2.0))) == {"y1_only"}


def test_rebuilt_sets_table_rows_are_the_stored_sets_every_column(material):
    """Every column the identifiability table shows for a set (fraction, spans, best error, fraction error,
    at-bound) as the admissibility step evaluated it; the grid's node counts are not stored (NaN and 0)."""
    spec, surrogates, frame, sets = material
    stored = stored_strict_sets(frame, judged_scenarios(spec, surrogates, 2.0), reference=True)
    for scen in spec.scenarios:
        got, evaluated = stored[scen.name], sets[scen.name]
        node_columns = ["node_fraction_pct", "n_admissible_nodes"]
        pd.testing.assert_frame_equal(got.to_frame().drop(columns=node_columns),
                                      evaluated.to_frame().drop(columns=node_columns), check_exact=True)
        assert np.isnan(got.node_fraction) and (got.n_nodes, got.n_admissible_nodes, got.n_refined_cells) == (0, 0, 0)
        for name in ("observables", "tolerance", "factors", "best_error", "empty"):
            assert getattr(got, name) == getattr(evaluated, name), name


def test_a_stored_set_of_zero_fraction_is_empty(material):
    """An empty strict set stays empty when rebuilt: the later steps' 'no admissible parameters' reads it."""
    spec, surrogates, frame, _ = material
    planted = frame.copy()
    planted.loc[planted["scenario"] == "both", "exact_fraction"] = 0.0
    got = stored_strict_sets(planted, judged_scenarios(spec, surrogates, 2.0))
    assert got["both"].empty and not got["y1_only"].empty

"""The paper comparison's tolerance rows read each scenario's own tolerance, whatever the number of factor rows
the scenario has in the identifiability table (one factor included), and report every column of the row."""

import math

import pandas as pd
import pytest

from demid.paper import paper_comparison


def _identifiability(scenarios):
    rows = []
    for scenario, (tolerance, factors) in scenarios.items():
        for factor in factors:
            rows.append({"material": "m", "scenario": scenario, "observables": "y", "tolerance": tolerance,
                         "feasible_fraction_pct": 1.0, "factor": factor, "lower": 0.1, "upper": 0.2, "width": 0.1})
    return pd.DataFrame(rows)


@pytest.mark.parametrize("scenarios", [
    {"one": (0.03, ["x"])},
    {"one": (0.03, ["x"]), "three": (0.05, ["x", "y", "z"])},
    {"two": (0.2, ["y", "x"]), "one": (0.015, ["z"])},
])
def test_each_scenarios_tolerance_row_is_its_own(scenarios):
    fit = pd.DataFrame({"material": ["m"], "response": ["y"], "r2": [0.9], "rmse": [1.0]})
    published = {"tolerances": {"m": {name: tol for name, (tol, _) in scenarios.items()}}}
    table = paper_comparison(published, fit, _identifiability(scenarios), {}).set_index("quantity")
    assert len(table) == len(scenarios)
    for name, (tolerance, _) in scenarios.items():
        row = table.loc[f"tolerance ε {name}"]
        assert (row["material"], row["published"], row["reproduced"]) == ("m", tolerance, tolerance)
        assert row["abs_diff"] == 0.0 and row["rel_diff"] == 0.0
        assert bool(row["pass"]) and bool(row["printed_agrees"])


def test_a_tolerance_of_a_scenario_the_study_lacks_is_nan_and_fails():
    fit = pd.DataFrame({"material": ["m"], "response": ["y"], "r2": [0.9], "rmse": [1.0]})
    published = {"tolerances": {"m": {"absent": 0.02}}}
    row = paper_comparison(published, fit, _identifiability({"one": (0.02, ["x"])}), {}).iloc[0]
    assert math.isnan(row["reproduced"]) and math.isnan(row["abs_diff"]) and not bool(row["pass"])

"""tables/model_extensions.csv against the rows written out here, over generated studies: 2-4 materials, some
extending another (or one not in the study), 1-3 scenarios each shared or not and listed in any order, 1-3
observables per scenario with surrogate Q² rows present, missing or undefined, level 2 with or without a best
error: one row per extending material and shared scenario in config order, the added factors in the extension's
order, each number the table reads from its source."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
from hypothesis import Phase, given, settings, strategies as st

from demid.spec import MaterialSpec
from demid.story.extensions import MODEL_EXTENSION_COLUMNS, model_extensions


@settings(max_examples=25, deadline=None, derandomize=True, phases=(Phase.explicit, Phase.generate))
@given(seed=st.integers(0, 100_000), count=st.integers(2, 4))
def test_each_extension_row_reads_both_materials_numbers(seed, count):
    rng = np.random.default_rng(seed)
    observables = ["y0", "y1", "y2"]
    all_scenarios = ["s0", "s1", "s2"]
    specs, extends, criticism, ident_rows, fit_rows, scenario_obs = {}, {}, {}, [], [], {}
    names = [f"m{i}" for i in range(count)]
    for i, name in enumerate(names):
        factors = {f"f{j}": {"lower": 0.0, "upper": 1.0} for j in rng.permutation(5)[:int(rng.integers(1, 4))]}
        chosen = [all_scenarios[j] for j in rng.permutation(3)[:int(rng.integers(1, 4))]]
        scenarios = {}
        for s in chosen:
            obs = sorted(rng.choice(observables, int(rng.integers(1, 4)), replace=False))
            scenarios[s] = {"observables": obs, "tolerance": 0.05}
            scenario_obs[(name, s)] = obs
        specs[name] = MaterialSpec.from_material(name, {
            "data": "x.csv", "design": {"type": "custom"}, "factors": factors,
            "responses": {o: {"target": float(rng.uniform(1, 9))} for o in observables}, "scenarios": scenarios})
        extends[name] = (str(rng.choice(names[:i] + ["elsewhere"])) if i and rng.uniform() < 0.8 else "")
        best = rng.choice([None, float(rng.uniform(0, 0.5))])
        criticism[name] = {"level2": {} if best is None else {"best_max_error": best}}
        for s in chosen:
            fraction = float(rng.choice([0.0, rng.uniform(0, 100)]))
            ident_rows += [{"material": name, "scenario": s, "factor": f, "feasible_fraction_pct": fraction}
                           for f in factors]
        for o in observables:
            if rng.uniform() < 0.85:
                fit_rows.append({"material": name, "response": o, "q2": float(rng.choice([np.nan, rng.uniform(-1, 1)]))})
    identifiability = pd.DataFrame(ident_rows)  # as the pipeline writes it: materials and scenarios in config order
    surrogate_fit = pd.DataFrame(fit_rows, columns=["material", "response", "q2"])

    table = model_extensions(specs, extends, criticism, identifiability, surrogate_fit)
    assert list(table.columns) == MODEL_EXTENSION_COLUMNS

    def fraction(material, scenario):
        rows = identifiability[(identifiability["material"] == material) & (identifiability["scenario"] == scenario)]
        return float(rows["feasible_fraction_pct"].iloc[0]) if len(rows) else None

    def lowest_q2(material, obs):
        rows = surrogate_fit[(surrogate_fit["material"] == material) & surrogate_fit["response"].isin(obs)]
        if set(rows["response"]) != set(obs) or rows["q2"].isna().any():
            return math.nan
        return float(rows["q2"].min())

    def best_error(material):
        value = criticism[material]["level2"].get("best_max_error")
        return math.nan if value is None else float(value)

    expected = []
    for name, spec in specs.items():
        base = extends[name]
        if base not in specs:
            continue
        for sc in spec.scenarios:
            if fraction(base, sc.name) is None or fraction(name, sc.name) is None:
                continue
            expected.append({
                "material": name, "extends": base,
                "added_factors": "+".join(f for f in spec.factor_names if f not in specs[base].factor_names),
                "best_error_before": best_error(base), "best_error_after": best_error(name),
                "feasible_fraction_before_pct": fraction(base, sc.name),
                "feasible_fraction_after_pct": fraction(name, sc.name), "scenario": sc.name,
                "surrogate_q2_before": lowest_q2(base, scenario_obs[(base, sc.name)]),
                "surrogate_q2_after": lowest_q2(name, scenario_obs[(name, sc.name)])})
    got = table.to_dict("records")
    assert len(got) == len(expected)
    for row, want in zip(got, expected):
        for key, value in want.items():
            if isinstance(value, float) and math.isnan(value):
                assert math.isnan(row[key]), (key, row, want)
            else:
                assert row[key] == value, (key, row, want)

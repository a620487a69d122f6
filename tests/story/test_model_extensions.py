"""A material that ``extends`` another: tables/model_extensions.csv reads level 2's best-point error and
identifiability's admissible fraction of both (one quantity, one number), and the report says the gain."""

from __future__ import annotations

import copy

import numpy as np
import pandas as pd
import pytest

from demid.config import check_semantics, validate_schema
from demid.errors import InputError
from demid.spec import MaterialSpec
from demid.story.extensions import MODEL_EXTENSION_COLUMNS, extension_sentence, model_extensions


def _material(factors: dict, **extra) -> dict:
    return {"data": "x.csv", "design": {"type": "custom"}, "factors": factors,
            "responses": {"theta": {"target": 24.0, "label": "θ", "unit": "°"}},
            "scenarios": {"aor": {"observables": ["theta"], "tolerance": 0.04, "label": "AoR ±4 %"}}, **extra}


BASE = _material({"mu_s": {"lower": 0.1, "upper": 0.9, "label": "μ_s"}, "e": {"lower": 0.2, "upper": 0.8}},
                 label="No rolling")
EXTENDED = _material({"mu_s": {"lower": 0.1, "upper": 0.9, "label": "μ_s"},
                      "mu_r": {"lower": 0.0, "upper": 0.3, "label": "μ_r"}}, label="Rolling", extends="base")


def _identifiability(rows):
    return pd.DataFrame([{"material": m, "scenario": s, "feasible_fraction_pct": f, "factor": x}
                         for m, s, f in rows for x in ("a", "b")])


def test_the_table_reads_both_materials_numbers_and_names_the_added_factors():
    specs = {"base": MaterialSpec.from_material("base", BASE), "ext": MaterialSpec.from_material("ext", EXTENDED)}
    criticism = {"base": {"level2": {"best_max_error": 0.2367}}, "ext": {"level2": {"best_max_error": 0.0}}}
    ident = _identifiability([("base", "aor", 0.0), ("ext", "aor", 38.97), ("ext", "only_ext", 50.0)])
    table = model_extensions(specs, {"base": "", "ext": "base"}, criticism, ident)
    assert list(table.columns) == MODEL_EXTENSION_COLUMNS
    # one row: the only scenario both have; the extended material's own scenario has nothing to compare with
    q2 = ["surrogate_q2_before", "surrogate_q2_after"]
    assert table.drop(columns=q2).to_dict("records") == [{
        "material": "ext", "extends": "base", "added_factors": "mu_r", "best_error_before": 0.2367,
        "best_error_after": 0.0, "feasible_fraction_before_pct": 0.0, "feasible_fraction_after_pct": 38.97,
        "scenario": "aor"}]
    assert table[q2].isna().all(axis=None)  # no surrogate_fit given: no Q², and the sentence says nothing of it
    text = extension_sentence(table.iloc[0].to_dict(), {"base": "No rolling", "ext": "Rolling"},
                              {"mu_r": "μ_r"}, "AoR ±4 %")
    assert text == ("Adding μ_r to the model of No rolling (Rolling): the best point's largest error falls from "
                    "23.7 % to 0 %; the admissible set of *AoR ±4 %* grows from empty to 39 % of Ω.")
    # no material extends another: an empty table with the columns
    none = model_extensions(specs, {}, criticism, ident)
    assert list(none.columns) == MODEL_EXTENSION_COLUMNS and none.empty


def _surrogate_fit(rows):
    return pd.DataFrame([{"material": m, "response": r, "q2": q} for m, r, q in rows])


def test_a_set_read_off_a_surrogate_that_does_not_predict_says_so_beside_its_share():
    """The Kratos heap's 11-run tables (examples/dem_heap/data): the extended model's set (39 % of Ω) read off an
    angle surrogate with Q² = -0.30, the base's empty set off one with Q² = -1.98; each share carries its Q², and the sentence says
    such a set is not yet the answer. A surrogate that predicts (Q² 0.81 here) adds nothing."""
    specs = {"base": MaterialSpec.from_material("base", BASE), "ext": MaterialSpec.from_material("ext", EXTENDED)}
    criticism = {"base": {"level2": {"best_max_error": 0.2367}}, "ext": {"level2": {"best_max_error": 0.0}}}
    ident = _identifiability([("base", "aor", 0.0), ("ext", "aor", 38.97)])
    fit = _surrogate_fit([("base", "theta", -1.977), ("ext", "theta", -0.3008), ("ext", "height", 0.9)])
    table = model_extensions(specs, {"ext": "base"}, criticism, ident, fit)
    # the lowest Q² of the scenario's observables (theta only: the height is not in the scenario)
    assert table.loc[0, "surrogate_q2_before"] == -1.977 and table.loc[0, "surrogate_q2_after"] == -0.3008
    text = extension_sentence(table.iloc[0].to_dict(), {"base": "No rolling", "ext": "Rolling"}, {"mu_r": "μ_r"},
                              "AoR ±4 %")
    # a best point that meets the target up to rounding (1.5e-16) is not printed as "1.48e-14 %"
    rounding = dict(table.iloc[0].to_dict(), best_error_after=1.4803e-16)
    assert "falls from 23.7 % to < 0.01 %;" in extension_sentence(rounding, {"base": "No rolling", "ext": "Rolling"},
                                                                  {"mu_r": "μ_r"}, "AoR ±4 %")
    assert ("grows from empty (surrogate Q² = -1.98 < 0.5) to 39 % of Ω (surrogate Q² = -0.30 < 0.5). A set "
            "read off a surrogate whose leave-one-out Q² is below 0.5 is what that surrogate says, not yet the "
            "answer") in text
    # between 0 and 0.5 the surrogate is not "does not predict" for the criticism, but still not the answer
    weak = dict(table.iloc[0].to_dict(), surrogate_q2_before=0.81, surrogate_q2_after=0.31)
    text = extension_sentence(weak, {"base": "No rolling", "ext": "Rolling"}, {"mu_r": "μ_r"}, "AoR ±4 %")
    assert "from empty to 39 % of Ω (surrogate Q² = 0.31 < 0.5). A set read off" in text
    # both predict: the sentence is the plain gain; a Q² the report's row leaves blank ("") says nothing
    for q2_after in (0.5, ""):
        good = dict(table.iloc[0].to_dict(), surrogate_q2_before=0.81, surrogate_q2_after=q2_after)
        assert extension_sentence(good, {"base": "No rolling", "ext": "Rolling"}, {"mu_r": "μ_r"},
                                  "AoR ±4 %").endswith("grows from empty to 39 % of Ω.")


def test_a_level2_without_targets_gives_nan_not_a_number_made_up():
    specs = {"base": MaterialSpec.from_material("base", BASE), "ext": MaterialSpec.from_material("ext", EXTENDED)}
    table = model_extensions(specs, {"ext": "base"}, {"base": {"level2": None}, "ext": {}},
                             _identifiability([("base", "aor", 5.0), ("ext", "aor", 10.0)]))
    assert np.isnan(table.loc[0, "best_error_before"]) and np.isnan(table.loc[0, "best_error_after"])


@pytest.mark.parametrize("other", ["nothing", "ext"])
def test_extends_must_name_another_material(tmp_path, other):
    (tmp_path / "x.csv").write_text("run\n")
    ext = copy.deepcopy(EXTENDED)
    ext["extends"] = other
    config = validate_schema({"materials": {"base": copy.deepcopy(BASE), "ext": ext}})
    with pytest.raises(InputError, match=rf"materials\.ext\.extends: '{other}' is not another material"):
        check_semantics(config, source="config.yaml", base_dir=tmp_path)


def test_the_data_dictionary_describes_the_table_columns():
    from demid.report.columns import TABLE_COLUMNS, columns_table

    assert TABLE_COLUMNS["model_extensions"] == MODEL_EXTENSION_COLUMNS
    rows = columns_table({})
    described = rows[rows["table"] == "model_extensions.csv"].set_index("column")
    assert list(described.index) == MODEL_EXTENSION_COLUMNS
    assert described.loc["feasible_fraction_after_pct", "unit"] == "% of Ω"


@pytest.mark.parametrize("before, after, verb, grow, shares", [
    (0.5, 0.8, "falls", "grows", ("0.5 % of Ω", "0.8 % of Ω")),      # shares below 1 % are shares, not empty
    (0.0, 0.3, "falls", "grows", ("empty", "0.3 % of Ω")),
    (12.5, 12.5, "falls", "does not grow", ("12.5 % of Ω", "12.5 % of Ω")),
])
def test_an_extension_sentence_quotes_each_share_of_omega_and_which_way_it_moved(before, after, verb, grow, shares):
    row = {"material": "ext", "extends": "base", "added_factors": "mu_r+e", "best_error_before": 0.1,
           "best_error_after": 0.05, "feasible_fraction_before_pct": before, "feasible_fraction_after_pct": after}
    text = extension_sentence(row, {}, {"mu_r": "μ_r"}, "S")
    assert text.startswith("Adding μ_r, e to the model of base (ext): the best point's largest error falls from "
                           "10 % to 5 %")
    assert f"the admissible set of *S* {grow} from {shares[0]} to {shares[1]}." in text


def test_a_material_extending_one_not_in_the_study_gives_no_row():
    specs = {"ext": MaterialSpec.from_material("ext", EXTENDED)}
    table = model_extensions(specs, {"ext": "base"}, {"ext": {}}, _identifiability([("ext", "aor", 10.0)]))
    assert table.empty and list(table.columns) == MODEL_EXTENSION_COLUMNS


def test_rows_follow_the_scenarios_config_order_not_their_names():
    """Two scenarios both materials have, configured as 'zeta' then 'alpha': the table's rows (and so the
    report's sentences) come in that order, each with its own fractions."""
    scenarios = {"zeta": {"observables": ["theta"], "tolerance": 0.04}, "alpha": {"observables": ["theta"],
                                                                                  "tolerance": 0.1}}
    specs = {"base": MaterialSpec.from_material("base", {**BASE, "scenarios": scenarios}),
             "ext": MaterialSpec.from_material("ext", {**EXTENDED, "scenarios": scenarios})}
    ident = _identifiability([("base", "zeta", 1.0), ("base", "alpha", 20.0), ("ext", "zeta", 3.0),
                              ("ext", "alpha", 40.0)])
    table = model_extensions(specs, {"ext": "base"}, {}, ident)
    assert table["scenario"].tolist() == ["zeta", "alpha"]
    assert table["feasible_fraction_before_pct"].tolist() == [1.0, 20.0]
    assert table["feasible_fraction_after_pct"].tolist() == [3.0, 40.0]

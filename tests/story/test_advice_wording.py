"""Advice says what a defect touches: a surrogate that does not predict is named for the sets or the Pareto front
that use it, and level 2's tolerance in the recalibrate advice is each observable's own."""

from __future__ import annotations

import pandas as pd
import pytest

from demid.spec import MaterialSpec
from demid.story import material_advice


def _spec(**extra) -> MaterialSpec:
    material = {"data": "x.csv", "design": {"type": "custom"},
                "factors": {"a": {"lower": 0.0, "upper": 1.0}, "b": {"lower": 0.0, "upper": 1.0}},
                "responses": {"D": {"target": 100.0}, "S": {"unit": "-"}},
                "scenarios": {"d": {"observables": ["D"], "tolerance": 0.05}}, **extra}
    return MaterialSpec.from_material("m", material, grid_points=51)


NO_VERDICTS = pd.DataFrame(columns=["scenario", "factor", "verdict"])


@pytest.mark.parametrize("response, pareto, says", [
    ("D", None, "the sets that use it are not to be trusted"),
    ("S", {"error_of": "D", "minimise": "S", "max_error": 0.05}, "the Pareto front that uses it is indicative only"),
    ("S", None, "do not use it to judge parameter sets"),
])
def test_a_surrogate_that_does_not_predict_is_named_for_what_uses_it(response, pareto, says):
    spec = _spec(**({"pareto": pareto} if pareto else {}))
    criticism = {"level1": {response: {"verdict": "does_not_predict"}}}
    (item,) = [i for i in material_advice(spec, NO_VERDICTS, criticism=criticism) if i.kind == "recalibrate"]
    assert item.observable == response and item.text.endswith(says + ".")


def test_recalibrate_advice_names_each_observables_own_tolerance():
    spec = _spec()
    level2 = {"feasible": False, "tolerance": 0.05, "bottleneck": "D", "observables": ["D"],
              "tolerances": {"D": 0.002}}
    (item,) = [i for i in material_advice(spec, NO_VERDICTS, criticism={"level2": level2}) if i.kind == "recalibrate"]
    assert "within their own tolerances (D 0.20 %)" in item.text
    level2["tolerances"] = {"D": 0.05}
    (item,) = [i for i in material_advice(spec, NO_VERDICTS, criticism={"level2": level2}) if i.kind == "recalibrate"]
    assert "within 5 %" in item.text


@pytest.mark.parametrize("target, says", [
    (0.6, "0.6 lies outside every simulated value (5 to 60) by more than a factor of 3; ×10 → 6 lies inside"),
    (6000.0, "6000 lies farther from every simulated value (5 to 60) than the simulated range itself; ÷100 → 60 lies "
             "inside"),
])
def test_check_target_says_why_the_target_is_implausible(target, says):
    from demid.data import implausible_targets

    spec = MaterialSpec.from_material("m", {**_spec().material_config(), "responses": {"D": {"target": target}}})
    table = pd.DataFrame({"D": [5.0, 12.0, 30.0, 47.0, 60.0]})
    advice = material_advice(spec, NO_VERDICTS, implausible=implausible_targets(table, spec.targets))
    (item,) = [i for i in advice if i.kind == "check_target"]
    assert says in item.text and "config key materials.m.responses.D.target" in item.text
    assert not [i for i in advice if i.kind == "widen"]


def test_a_factor_called_like_an_english_word_is_labelled_only_where_it_stands_for_the_factor():
    from demid.story.words import labelled

    spec = MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "custom"},
        "factors": {"a": {"lower": 0.0, "upper": 1.0, "label": "a_1"}, "mu_r": {"lower": 0.0, "upper": 1.0,
                                                                              "label": "μ_r"}},
        "responses": {"y": {"target": 1.0, "label": "Y"}}, "scenarios": {"s": {"observables": ["y"], "tolerance": 0.02}}})
    text = ("The closest point (a=0.1, mu_r=0.3) misses y by 3 %, so a discrepancy (bias) in y explains it; "
            "a wider range of a. It levels off (a ≈ 2), evidence of a bias.")
    assert labelled(text, spec) == ("The closest point (a_1=0.1, μ_r=0.3) misses Y by 3 %, so a discrepancy (bias) in "
                                    "Y explains it; a wider range of a_1. It levels off (a_1 ≈ 2), evidence of a bias.")

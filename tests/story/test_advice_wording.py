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


# --------------------------------------------------------------------------- advice on a surrogate that does not predict
def _reach_at_upper_bound(observable: str = "D") -> dict:
    """D at the best point 90.1234 against a target of 100, gaining 12.3456 per unit a at the upper bound: a
    quadratic that levels off before the band, so widening is not advised."""
    from demid.criticism.reach import Reach

    return Reach(factor="a", side="upper", observable=observable, value=90.1234, target=100.0, band_edge=95.0,
                 slope=12.3456, curvature=-30.0, straight_extension=0.4, quadratic_extension=float("inf"),
                 levels_off_extension=0.4115, levels_off_value=92.66, straight_factor_value=1.4,
                 quadratic_factor_value=float("nan"), levels_off_factor_value=1.4115, widen=False).to_json()


def _bound_advice(verdict: str) -> str:
    spec = _spec()
    level2 = {"feasible": False, "tolerance": 0.05, "observables": ["D"], "unmoved": [],
              "best_point_at_bound": {"a": "upper", "b": "none"}, "reach": [_reach_at_upper_bound()]}
    criticism = {"level1": {"D": {"verdict": verdict}}, "level2": level2}
    (item,) = [i for i in material_advice(spec, NO_VERDICTS, criticism=criticism) if i.factor == "a"]
    assert item.kind == "recalibrate" and item.bound == "upper"
    return item.text


def _numbers(text: str) -> list[str]:
    import re

    return re.findall(r"\d+(?:\.\d+)?", text.replace("Q² < 0", ""))


def test_advice_on_a_bound_read_off_a_surrogate_that_does_not_predict_says_so_to_one_digit():
    # a predicting surrogate: its slope (12.35) and what D misses (9.877) to four digits, a verdict on widening
    trusted = _bound_advice("adequate")
    assert trusted.startswith("Do not widen a for D = 100") and "12.35" in trusted and "9.877" in trusted
    # Q² < 0: its leave-one-out error exceeds the runs' spread; the numbers to one significant digit (12.3456 ->
    # 10, 9.8766 -> 10), said to be no evidence, and no verdict on widening
    text = _bound_advice("does_not_predict")
    assert "cannot be judged" in text and "the surrogate of D does not predict left-out runs (Q² < 0)" in text
    assert "about 10 per unit a, about 10 short of the target" in text, text
    assert not text.startswith("Do not widen") and "Refit or resimulate D first" in text
    assert all(len(n.replace(".", "").strip("0")) <= 1 for n in _numbers(text)), _numbers(text)


def test_a_measurement_ranked_on_a_surrogate_that_does_not_predict_is_quoted_roughly():
    spec = _spec(responses={"D": {"target": 100.0}, "S": {"target": 5.0}})
    ranking = pd.DataFrame({"observables": ["D", "S", "D+S"], "n_observables": [1, 1, 2],
                            "best_subset": ["(none)", "(none)", "D"], "information_gain_bits": [2.0, 0.5, 3.2345],
                            "gain_vs_best_subset_bits": [2.0, 0.5, 1.2345], "feasible_fraction_pct": [20.0, 60.0, 3.456],
                            "targets_reachable": [True, True, True]})
    add = [i for i in material_advice(spec, NO_VERDICTS, ranking=ranking) if i.kind == "add_observable"]
    assert add[0].text == ("Measure S as well: it adds 1.23 bits of information and leaves 3.46 % of the domain "
                           "admissible.")
    criticism = {"level1": {"S": {"verdict": "does_not_predict"}}}
    add = [i for i in material_advice(spec, NO_VERDICTS, ranking=ranking, criticism=criticism)
           if i.kind == "add_observable"]
    assert add[0].text == ("Measure S as well: by the surrogates it adds about 1 bit of information and leaves about "
                           "3 % of the domain admissible, but the surrogate of S does not predict left-out runs "
                           "(Q² < 0), so these numbers are rough.")


def test_the_ranking_in_words_on_a_surrogate_that_does_not_predict_says_so_to_one_digit():
    spec = _spec(responses={"D": {"target": 100.0}, "S": {"target": 5.0}})
    ranking = pd.DataFrame({"observables": ["D+S", "D", "S"], "n_observables": [2, 1, 1],
                            "best_subset": ["D", "(none)", "(none)"], "information_gain_bits": [3.2345, 2.0123, 0.5],
                            "gain_vs_best_subset_bits": [1.2222, 2.0123, 0.5],
                            "feasible_fraction_pct": [3.456, 20.0, 60.0]})

    def walk(level1):
        return [i.text for i in material_advice(spec, NO_VERDICTS, ranking=ranking, criticism={"level1": level1})
                if i.kind == "measurement_order"]

    assert walk({})[1] == ("From D, adding S gains 1.22 bits (2.01 -> 3.23) and shrinks the admissible fraction by "
                           "82.7 % (20 % -> 3.46 %).")
    rough = walk({"S": {"verdict": "does_not_predict"}})
    assert rough[0] == ("The ranking rests on surrogates of which the surrogate of S does not predict left-out runs "
                        "(Q² < 0): its gains and fractions are rough, given to one significant digit.")
    # 1.2222 -> 1, 2.0123 -> 2, 3.2345 -> 3, 100 (1 - 3.456 / 20) = 82.72 -> 80, 3.456 -> 3
    assert rough[2] == ("From D, adding S gains 1 bits (2 -> 3) and shrinks the admissible fraction by 80 % "
                        "(20 % -> 3 %).")


def test_advice_read_back_from_its_table_keeps_each_item_and_its_next_step():
    """tables/advice.csv read back (every cell a string, an empty one NaN) gives the same items; no table, or an
    empty one, gives no advice; the next step is the first decision among the kinds the summary gives, the
    others of those kinds follow in their order."""
    from demid.story import AdviceItem, StudyAdvice

    items = [AdviceItem("m", "add_observable", "", "", "S", "Measure S.", False),
             AdviceItem("m", "widen", "a", "upper", "", "Widen a.", True),
             AdviceItem("n", "stop", "", "", "", "Stop.", True),
             AdviceItem("m", "measurement_order", "", "", "", "The order.", False),
             AdviceItem("m", "next_runs", "", "", "", "Run nine more.", False)]
    table = StudyAdvice(items).to_frame()
    read = StudyAdvice.from_frame(table.astype(str).replace({"": float("nan")}))
    assert read.items == items
    assert StudyAdvice.from_frame(None).items == [] and StudyAdvice.from_frame(table.iloc[0:0]).items == []
    assert read.next_step("m") == ("Widen a.", ["Measure S.", "Run nine more."])
    assert read.next_step("n") == ("Stop.", [])
    assert read.texts("m", kinds=("measurement_order", "widen")) == ["Widen a.", "The order."]
    assert read.texts("n") == ["Stop."]


@pytest.mark.parametrize("unit, text", [("", "–"), ("-", "–"), (" - ", "–"), ("J m^-2", "J m⁻²"), ("m^{1.5}", "m¹·⁵"),
                                        ("kg m^-3 s^2", "kg m⁻³ s²"), ("Pa", "Pa")])
def test_a_unit_in_running_text_has_superscript_powers_and_a_dash_when_dimensionless(unit, text):
    from demid.story.words import unit_text

    assert unit_text(unit) == text


def test_level2s_own_tolerances_are_read_back_in_the_config_order_of_its_observables():
    """JSON sorts its keys (d10 before d5, a before z): the observables' own order is restored."""
    from demid.story.words import level2_own_tolerances

    level2 = {"tolerance": 0.05, "observables": ["z", "d5", "d10"], "tolerances": {"d10": 0.05, "d5": 0.02, "z": 0.1}}
    assert list(level2_own_tolerances(level2).items()) == [("z", 0.1), ("d5", 0.02), ("d10", 0.05)]
    # without the observables (an older result) the keys come in natural order
    older = {"tolerance": 0.05, "tolerances": {"d10": 0.05, "d5": 0.02}}
    assert list(level2_own_tolerances(older)) == ["d5", "d10"]
    assert level2_own_tolerances({"tolerance": 0.05, "observables": ["a"], "tolerances": {"a": 0.05}}) is None


def test_a_material_without_scenarios_is_not_told_that_every_observable_is_used():
    spec = _spec(scenarios={})
    ranking = pd.DataFrame([{"observables": "D", "n_observables": 1, "best_subset": "(none)",
                             "information_gain_bits": 2.0, "gain_vs_best_subset_bits": 2.0,
                             "feasible_fraction_pct": 10.0, "targets_reachable": True}])
    for given in (None, ranking):
        advice = material_advice(spec, NO_VERDICTS, ranking=given, criticism={"level2": {"feasible": True}})
        assert [i for i in advice if i.kind != "measurement_order"] == []


def test_a_rough_reach_in_degrees_is_written_against_its_number_and_other_units_after_a_space():
    for unit, written in (("°", "about 10° per unit a, about 10° short of the target"),
                          ("mm", "about 10 mm per unit a, about 10 mm short of the target")):
        spec = _spec(responses={"D": {"target": 100.0, "unit": unit}, "S": {"unit": "-"}})
        level2 = {"feasible": False, "tolerance": 0.05, "observables": ["D"], "unmoved": [],
                  "best_point_at_bound": {"a": "upper", "b": "none"}, "reach": [_reach_at_upper_bound()]}
        criticism = {"level1": {"D": {"verdict": "does_not_predict"}}, "level2": level2}
        (item,) = [i for i in material_advice(spec, NO_VERDICTS, criticism=criticism) if i.factor == "a"]
        assert written in item.text, item.text


def _level2_at_upper_bound_of_a(feasible: bool, unmoved: list) -> dict:
    return {"feasible": feasible, "tolerance": 0.05, "observables": ["D"], "unmoved": unmoved,
            "best_point_at_bound": {"a": "upper", "b": "none"}, "widen": {"a": ["upper"]}, "reach": []}


def test_the_best_point_on_a_bound_is_a_reason_to_widen_only_when_no_point_meets_every_target():
    spec = _spec()
    advice = material_advice(spec, NO_VERDICTS, criticism={"level2": _level2_at_upper_bound_of_a(False, [])})
    (widen,) = [i for i in advice if i.kind == "widen"]
    assert (widen.factor, widen.bound) == ("a", "upper")
    assert widen.text.endswith("no point meets every target and the best point lies on it.")
    advice = material_advice(spec, NO_VERDICTS, criticism={"level2": _level2_at_upper_bound_of_a(True, [])})
    assert [i for i in advice if i.factor] == []


def test_no_range_is_widened_for_an_observable_that_no_factor_moves():
    advice = material_advice(_spec(), NO_VERDICTS, criticism={"level2": _level2_at_upper_bound_of_a(False, ["D"])})
    assert [i for i in advice if i.kind == "widen"] == []


def test_a_response_neither_in_a_set_nor_in_the_pareto_front_is_not_said_to_be_used_by_the_front():
    spec = _spec(responses={"D": {"target": 100.0}, "S": {"unit": "-"}, "T": {"unit": "-"}},
                 pareto={"error_of": "D", "minimise": "S", "max_error": 0.05})
    criticism = {"level1": {"T": {"verdict": "does_not_predict"}}}
    (item,) = [i for i in material_advice(spec, NO_VERDICTS, criticism=criticism) if i.kind == "recalibrate"]
    assert item.observable == "T" and item.text.endswith("so do not use it to judge parameter sets.")


def test_the_ranking_is_called_rough_only_for_a_surrogate_it_rests_on():
    spec = _spec()
    ranking = pd.DataFrame({"observables": ["D"], "n_observables": [1], "best_subset": ["(none)"],
                            "information_gain_bits": [2.0], "gain_vs_best_subset_bits": [2.0],
                            "feasible_fraction_pct": [20.0], "targets_reachable": [True]})

    def walk(weak):
        return [i.text for i in material_advice(spec, NO_VERDICTS, ranking=ranking,
                                                criticism={"level1": {weak: {"verdict": "does_not_predict"}}})
                if i.kind == "measurement_order"]

    assert not any(t.startswith("The ranking rests on") for t in walk("S"))
    assert walk("D")[0].startswith("The ranking rests on surrogates of which the surrogate of D does not predict")

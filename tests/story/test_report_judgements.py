"""Judgements the report used to make while printing, now the story's: whether the reference point meets its
targets (level 2's own judgement first), the one-line answer per material, which surrogates do not predict, and
where the recommended point stands against the design runs."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from demid.spec import MaterialSpec
from demid.story.recommended import HULL_TOLERANCE, point_on_edge_text
from demid.story.verdicts import material_answer, reference_within, unpredictive_responses


@pytest.mark.parametrize("level2, within", [
    ({"reference_max_error": 0.015, "tolerance": 0.02}, True),   # results without the recorded judgement
    ({"reference_max_error": 0.02, "tolerance": 0.02}, True),    # on the tolerance is within it
    ({"reference_max_error": 0.025, "tolerance": 0.02}, False),
    # an observable judged against its own, wider tolerance: level 2's judgement stands, not the scenario's
    ({"reference_max_error": 0.03, "tolerance": 0.02, "reference_within": True}, True),
    ({"reference_max_error": 0.01, "tolerance": 0.02, "reference_within": False}, False),
])
def test_the_reference_point_is_judged_by_level_2_or_else_by_its_largest_error(level2, within):
    assert reference_within(level2) is within


def test_the_answer_takes_the_fullest_scenario_and_sorts_its_factors_by_verdict():
    spec = MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "ccd", "alpha": 1.0, "center_runs": 1},
        "factors": {f: {"lower": 0.0, "upper": 1.0} for f in ("a", "b", "c", "d")},
        "responses": {"y": {"target": 1.0}, "z": {"target": 2.0}},
        "scenarios": {"y_only": {"observables": ["y"], "tolerance": 0.02},
                      "both": {"observables": ["y", "z"], "tolerance": 0.02}}}, grid_points=11)
    verdicts = pd.DataFrame({
        "scenario": ["y_only"] * 4 + ["both"] * 4, "factor": list("abcd") * 2,
        "verdict": ["identified"] * 4 + ["bounded", "identified", "unresolved alone; identified in combination "
                                         "with d", "cut by the search range (upper bound)"]})
    answer = material_answer(verdicts, spec)
    assert answer.scenario.name == "both"
    assert answer.identified == ["b"] and answer.in_combination == ["c"]
    assert answer.not_identified == [("a", "bounded"), ("d", "cut by the search range (upper bound)")]
    assert material_answer(verdicts.iloc[:0], spec) is None and material_answer(None, spec) is None


def test_only_a_surrogate_judged_not_to_predict_is_unpredictive():
    level1 = {"y": {"verdict": "does_not_predict"}, "z": {"verdict": "adequate"}, "w": {"verdict": "defect"},
              "v": {"messages": []}}
    assert unpredictive_responses(level1) == ["y"]
    assert unpredictive_responses({}) == [] and unpredictive_responses(None) == []


def _square_spec() -> MaterialSpec:
    material = {"data": "x.csv", "design": {"type": "ccd", "alpha": 1.0, "center_runs": 1},
                "factors": {"a": {"lower": 0.0, "upper": 1.0, "label": "a"},
                            "b": {"lower": 0.0, "upper": 10.0, "label": "b"}},
                "responses": {"y": {"target": 0.5, "label": "y"}},
                "scenarios": {"s": {"observables": ["y"], "tolerance": 0.02}}}
    return MaterialSpec.from_material("m", material, grid_points=11)


def test_a_point_just_past_the_runs_is_outside_them_by_more_than_the_hull_slack():
    """Runs on the triangle a + b/10 <= 0.8 (in fractions of each range): a point past its long side by less
    than the slack per factor counts as covered, one past it by ten times the slack does not."""
    spec = _square_spec()
    runs = np.array([[0.1, 1.0], [0.7, 1.0], [0.1, 7.0]])
    step = HULL_TOLERANCE / 2
    inside = {"a": 0.4 + step, "b": 10 * (0.4 + step)}
    outside = {"a": 0.4 + 10 * HULL_TOLERANCE, "b": 10 * (0.4 + 10 * HULL_TOLERANCE)}
    assert "outside the region the design runs cover" not in point_on_edge_text(spec, inside, runs, {}, set())
    assert "outside the region the design runs cover" in point_on_edge_text(spec, outside, runs, {}, set())

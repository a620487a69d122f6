"""Judgements the report used to make while printing, now the story's: whether the reference point meets its
targets (level 2's own judgement first), and where the recommended point stands against the design runs."""

from __future__ import annotations

import numpy as np
import pytest

from demid.spec import MaterialSpec
from demid.story.recommended import HULL_TOLERANCE, point_on_edge_text
from demid.story.verdicts import reference_within


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

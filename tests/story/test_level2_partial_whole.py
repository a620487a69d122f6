"""A material's advice when its level-2 entry holds only part of the criticism file's keys (a criticism written by
hand or cut down, as the tests and older results give it): without its feasibility verdict level 2 is read as no
miss by every piece of advice, as the report's summary reads it, so the add-observable advice still names the
observable with the largest gain and quotes its numbers, the same items as with a level 2 that meets every target;
with an explicit miss the add-observable advice goes and the recalibrate advice comes first."""

from __future__ import annotations

import re

import pandas as pd
import pytest

from demid.spec import MaterialSpec
from demid.story.advice import material_advice


def _spec() -> MaterialSpec:
    material = {"data": "x.csv", "design": {"type": "custom"},
                "factors": {"a": {"lower": 0.0, "upper": 1.0, "label": "A"},
                            "b": {"lower": 0.0, "upper": 1.0, "label": "B"}},
                "responses": {"y1": {"target": 1.0, "label": "Y one"}, "y2": {"target": -2.0, "label": "Y two"},
                              "y3": {"target": 3.0, "label": "Y three"}},
                "scenarios": {"s1": {"observables": ["y1"], "tolerance": 0.05}}}
    return MaterialSpec.from_material("m", material, grid_points=21)


def _ranking() -> pd.DataFrame:
    rows = [("y1", 1, "(none)", 1.0, 40.0), ("y2", 1, "(none)", 0.5, 60.0), ("y3", 1, "(none)", 0.7, 50.0),
            ("y1+y2", 2, "y1", 0.83, 12.5), ("y1+y3", 2, "y1", 2.47, 3.25), ("y2+y3", 2, "y2", 1.2, 20.0),
            ("y1+y2+y3", 3, "y1+y3", 0.4, 2.0)]
    return pd.DataFrame([{"observables": o, "n_observables": n, "best_subset": b, "gain_vs_best_subset_bits": g,
                          "information_gain_bits": g, "feasible_fraction_pct": f, "targets_reachable": True}
                         for o, n, b, g, f in rows])


_VERDICTS = pd.DataFrame([{"scenario": "s1", "factor": f, "verdict": "unresolved"} for f in ("a", "b")])


@pytest.mark.parametrize("level2", [
    {"observables": ["y1"], "tolerance": 0.05},
    {"observables": ["y1"], "tolerance": 0.05, "best_max_error": 0.01, "bottleneck": "y1"},
    {"best_max_error": 0.2},
])
def test_a_level2_without_its_verdict_leaves_the_add_observable_advice_as_a_met_one(level2):
    spec = _spec()
    items = material_advice(spec, _VERDICTS, ranking=_ranking(), criticism={"level2": level2})
    met = material_advice(spec, _VERDICTS, ranking=_ranking(),
                          criticism={"level2": {**level2, "feasible": True}})
    assert [(i.kind, i.observable, i.text, i.decision) for i in items] == [
        (i.kind, i.observable, i.text, i.decision) for i in met]
    added = [i for i in items if i.kind == "add_observable"]
    assert [i.observable for i in added] == ["y3"]  # the largest gain over y1: 2.47 bits
    said = re.fullmatch(r"Measure Y three as well: it adds ([\d.]+) bits of information and leaves ([\d.]+) % of "
                        r"the domain admissible\.", added[0].text)
    assert said and float(said.group(1)) == 2.47 and float(said.group(2)) == 3.25
    assert added[0].decision  # the next step: nothing else is advised


def test_a_level2_that_misses_a_target_drops_the_add_observable_advice():
    spec = _spec()
    level2 = {"observables": ["y1"], "tolerance": 0.05, "feasible": False, "best_max_error": 0.2,
              "bottleneck": "y1", "best_errors": {"y1": 0.2}}
    items = material_advice(spec, _VERDICTS, ranking=_ranking(), criticism={"level2": level2})
    assert not [i for i in items if i.kind == "add_observable"]
    assert items[0].kind == "recalibrate" and items[0].decision
    assert "No parameter set meets every target within 5 %" in items[0].text

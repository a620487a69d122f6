"""The scenario the next wave refocuses on by default, over generated studies with scenarios of different
sizes: the one with the most observables, ties broken by the smallest tolerance, then the config order."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from demid.next_wave import refocus_scenario
from demid.spec import MaterialSpec

NAMES = ["y1", "y2", "y3", "y4"]


@st.composite
def scenario_sets(draw):
    count = draw(st.integers(1, 4))
    scenarios = {}
    for k in range(count):
        observables = draw(st.lists(st.sampled_from(NAMES), min_size=1, max_size=4, unique=True))
        scenarios[f"s{k}"] = {"observables": observables, "tolerance": draw(st.sampled_from([0.02, 0.05, 0.1]))}
    return scenarios


@given(scenario_sets())
@settings(max_examples=40, deadline=None, derandomize=True)
def test_default_refocus_is_the_scenario_with_most_observables(scenarios):
    material = {"data": "x.csv", "design": {"type": "custom"},
                "factors": {"a": {"lower": 0.0, "upper": 1.0}, "b": {"lower": 0.0, "upper": 1.0}},
                "responses": {n: {"target": 1.0 + i} for i, n in enumerate(NAMES)}, "scenarios": scenarios}
    spec = MaterialSpec.from_material("m", material, grid_points=11)
    chosen = refocus_scenario(spec)
    most = max(len(s["observables"]) for s in scenarios.values())
    assert len(scenarios[chosen]["observables"]) == most
    tied = [name for name, s in scenarios.items() if len(s["observables"]) == most]
    tightest = min(scenarios[name]["tolerance"] for name in tied)
    assert scenarios[chosen]["tolerance"] == tightest
    assert chosen == next(name for name in tied if scenarios[name]["tolerance"] == tightest)

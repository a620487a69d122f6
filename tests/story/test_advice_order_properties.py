"""Which advice is the next step, over generated advice lists (the priority rule written out here), and the numbers
the widen and check-target advice quote (bounds, physical limits, units, targets, simulated ranges), each parsed
back, for one to three factors cut on either or both sides by one to three scenarios."""

from __future__ import annotations

import re

import pandas as pd
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.spec import MaterialSpec
from demid.story import AdviceItem, material_advice
from demid.story.advice import GENERIC_ADD_OBSERVABLE, PRIORITY, decided

_KINDS = [*PRIORITY, "measurement_order"]


@given(kinds=st.lists(st.sampled_from(_KINDS + ["generic"]), min_size=1, max_size=9))
@settings(max_examples=80, deadline=None, derandomize=True)
def test_the_next_step_is_the_first_advice_by_priority_and_the_generic_line_only_when_alone(kinds):
    items = [AdviceItem("m", "add_observable" if k == "generic" else k, "", "", "",
                        GENERIC_ADD_OBSERVABLE if k == "generic" else f"advice {n}") for n, k in enumerate(kinds)]
    out = decided(items)
    steps = [i for i in items if i.kind in PRIORITY]
    specific = [i for i in steps if i.text != GENERIC_ADD_OBSERVABLE]
    kept = specific if specific else steps
    # the priority rule written out: by kind in PRIORITY's order, in the given order within a kind
    expected = [i for kind in PRIORITY for i in kept if i.kind == kind]
    expected += [i for i in items if i.kind not in PRIORITY]
    assert [(i.kind, i.text) for i in out] == [(i.kind, i.text) for i in expected]
    assert [i.decision for i in out] == [bool(kept) and n == 0 for n in range(len(out))]


def _spec(k: int, units: list[str], limits: list[tuple], targets=(100.0,)) -> MaterialSpec:
    factors = {}
    for i in range(k):
        block = {"lower": 0.25 * (i + 1), "upper": 12.5 * (i + 1), "unit": units[i]}
        lo, hi = limits[i]
        if lo is not None or hi is not None:
            block["limits"] = {**({"lower": lo} if lo is not None else {}), **({"upper": hi} if hi is not None else {})}
        factors[f"f{i}"] = block
    material = {"data": "x.csv", "design": {"type": "custom"}, "factors": factors,
                "responses": {f"y{j}": {"target": t, "unit": "kg m^-3"} for j, t in enumerate(targets)},
                "scenarios": {f"s{j}": {"observables": ["y0"], "tolerance": 0.05, "label": f"Scenario {j}"}
                              for j in range(3)}}
    return MaterialSpec.from_material("m", material, grid_points=11)


@given(k=st.integers(1, 3), cuts=st.lists(st.tuples(st.integers(0, 2), st.integers(0, 2),
                                                     st.sampled_from(["lower", "upper", "lower and upper"])),
                                           min_size=1, max_size=6),
       units=st.lists(st.sampled_from(["-", "Pa", "J m^-2"]), min_size=3, max_size=3),
       limited=st.lists(st.booleans(), min_size=3, max_size=3))
@settings(max_examples=40, deadline=None, derandomize=True)
def test_widen_advice_names_each_cut_side_once_with_its_bound_and_limit(k, cuts, units, limited):
    limits = [(0.0, 20.0 * (i + 1)) if limited[i] else (None, None) for i in range(3)]
    spec = _spec(k, units, limits)
    rows = [{"scenario": f"s{s}", "factor": f"f{f % k}", "verdict": f"cut by the search range ({side} bound)"}
            for s, f, side in cuts]
    rows.append({"scenario": "s0", "factor": "f0", "verdict": "identified"})
    widen = [i for i in material_advice(spec, pd.DataFrame(rows)) if i.kind == "widen"]
    expected, by_factor = {}, {}
    for s, f, side in cuts:
        by_factor.setdefault(f"f{f % k}", set()).add(f"Scenario {s}")
        for one in side.split(" and "):
            expected.setdefault((f"f{f % k}", one), set()).add(f"Scenario {s}")
    # one item per factor and side, in the config's factor order, lower before upper
    assert [(i.factor, i.bound) for i in widen] == sorted(expected, key=lambda t: (int(t[0][1:]), t[1] != "lower"))
    for item in widen:
        i = int(item.factor[1:])
        unit = {"-": "", "Pa": " Pa", "J m^-2": " J m⁻²"}[units[i]]
        bound = 0.25 * (i + 1) if item.bound == "lower" else 12.5 * (i + 1)
        said = re.search(rf"beyond its {item.bound} bound \(([\d.e+-]+){re.escape(unit)}\)", item.text)
        assert said and float(said.group(1)) == pytest.approx(bound), item.text
        if limited[i]:
            limit = 0.0 if item.bound == "lower" else 20.0 * (i + 1)
            way = "down" if item.bound == "lower" else "up"
            reach = re.search(rf", {way} to its physical limit ([\d.e+-]+){re.escape(unit)},", item.text)
            assert reach and float(reach.group(1)) == pytest.approx(limit), item.text
        else:
            assert "physical limit" not in item.text
        # every scenario whose set this side cuts is named, and none that does not cut the factor
        named = set(re.findall(r"the plausible set of \*(Scenario \d)\*", item.text))
        assert expected[(item.factor, item.bound)] <= named <= by_factor[item.factor], item.text


@pytest.mark.parametrize("target, lo, hi, far, factor", [
    (1234.5678, 10.0, 20.5, True, None), (-0.00123456, -9.87654e-3, -5.0e-3, False, None),
    (7.5e6, 7.4, 7.6, False, 1e-6)])
def test_check_target_advice_quotes_the_target_and_the_simulated_range(target, lo, hi, far, factor):
    spec = _spec(1, ["-"], [(None, None)], targets=(target,))
    found = {"lo": lo, "hi": hi, "far": far, "factor": factor, "value": target}
    if factor is not None:
        found.update(repaired=target * factor)
    items = material_advice(spec, pd.DataFrame(columns=["scenario", "factor", "verdict"]), implausible={"y0": found})
    (item,) = [i for i in items if i.kind == "check_target"]
    said = re.search(r": ([-\d.e+]+) lies .*\(([-\d.e+]+) to ([-\d.e+]+)\)", item.text)
    assert said, item.text
    assert float(said.group(1)) == pytest.approx(target, rel=5e-6)
    assert float(said.group(2)) == pytest.approx(lo, rel=5e-4) and float(said.group(3)) == pytest.approx(hi, rel=5e-4)
    assert item.decision and item.observable == "y0" and "config key materials.m.responses.y0.target" in item.text
    assert "No widening of the search range" in item.text
    if factor is not None:  # the repair quotes the repaired target
        repaired = re.search(r"÷([\d.e+]+) → ([-\d.e+]+) lies inside", item.text)
        assert repaired and float(repaired.group(1)) == pytest.approx(1 / factor)
        assert float(repaired.group(2)) == pytest.approx(target * factor, rel=5e-6)

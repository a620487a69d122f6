"""The check-target advice (demid/story/advice.py) over generated studies of 2-4 observables: one item per target
far outside every simulated value (named by its config key, with the target and the simulated range quoted), then
one per observable the surrogate cannot bring to its target anywhere in the search range (the ranking's
single-observable rows with ``targets_reachable`` False, as a table read back from CSV writes them too), each named
once, in the ranking's order; a target in both lists gets the first item only.  And such a target is the next step,
before every other kind of advice."""

from __future__ import annotations

import re

import numpy as np
import pandas as pd
import pytest
from hypothesis import Phase, given, settings, strategies as st

from demid.spec import MaterialSpec
from demid.story.advice import material_advice

_CANNOT = ("Check the target of {label} and the simulation of it: the surrogate cannot meet it anywhere in the "
           "search range within the tolerance. That is a discrepancy between simulation and experiment, not "
           "information; observable sets with it are ranked last and get no information gain.")


def _spec(names, targets):
    return MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "custom"},
        "factors": {"a": {"lower": 0.0, "upper": 1.0}, "b": {"lower": -2.0, "upper": 3.0}},
        "responses": {o: {"target": t, "label": f"L{o}"} for o, t in zip(names, targets)},
        "scenarios": {"all": {"observables": list(names), "tolerance": 0.05}}}, grid_points=11)


@settings(max_examples=30, deadline=None, derandomize=True, phases=(Phase.explicit, Phase.generate))
@given(count=st.integers(2, 4), data=st.data())
def test_each_target_out_of_reach_or_far_off_is_named_once_and_first(count, data):
    names = [f"y{j}" for j in range(count)]
    targets = [data.draw(st.sampled_from([-37.5, -0.02, 4.0, 1250.0])) for _ in names]
    spec = _spec(names, targets)
    reachable = {o: data.draw(st.booleans()) for o in names}
    far_off = [o for o in names if data.draw(st.booleans())]
    as_text = data.draw(st.booleans())  # a ranking read back from CSV: the flags as text
    order = data.draw(st.permutations(names))
    rows = [{"observables": o, "n_observables": 1, "targets_reachable": reachable[o]} for o in order]
    rows.append({"observables": "+".join(names), "n_observables": count, "targets_reachable": all(reachable.values())})
    ranking = pd.DataFrame(rows).assign(information_gain_bits=1.0, feasible_fraction_pct=10.0,
                                        best_subset="(none)", gain_vs_best_subset_bits=1.0)
    if as_text:
        ranking["targets_reachable"] = ranking["targets_reachable"].map({True: "True", False: "False"})
    implausible = {o: {"far": True, "lo": 1.0, "hi": 2.0, "factor": None} for o in far_off}

    items = material_advice(spec, pd.DataFrame(columns=["scenario", "factor", "verdict"]), ranking=ranking,
                            implausible=implausible)
    checks = [i for i in items if i.kind == "check_target"]
    expected = far_off + [o for o in order if not reachable[o] and o not in far_off]
    assert [i.observable for i in checks] == expected
    for item in checks:
        o = item.observable
        if o in far_off:
            target = dict(zip(names, targets))[o]
            head = re.match(rf"Check the target of L{o} \(config key materials\.m\.responses\.{o}\.target\): "
                            r"(\S+) lies farther from every simulated value \(1 to 2\)", item.text)
            assert head and float(head.group(1)) == pytest.approx(target, rel=1e-6), item.text
        else:
            assert item.text == _CANNOT.format(label=f"L{o}")
    if checks:
        assert items[0].kind == "check_target" and items[0].decision
        assert [i.decision for i in items].count(True) == 1


def test_without_the_reachability_column_only_far_targets_are_named():
    names = ["p", "q"]
    spec = _spec(names, [2.0, -3.0])
    ranking = pd.DataFrame({"observables": ["p", "q", "p+q"], "n_observables": [1, 1, 2],
                            "information_gain_bits": [1.0, 1.0, 2.0], "feasible_fraction_pct": [5.0, 5.0, 1.0],
                            "best_subset": ["(none)", "(none)", "p"], "gain_vs_best_subset_bits": [1.0, 1.0, 1.0]})
    items = material_advice(spec, pd.DataFrame(columns=["scenario", "factor", "verdict"]), ranking=ranking,
                            implausible={})
    assert not [i for i in items if i.kind == "check_target"]
    assert np.isfinite(ranking["information_gain_bits"]).all()

"""The recalibrate advice over generated criticism: one item per response whose sets rest on a surrogate that does
not predict (the quadratic's verdict, unless kriging judged the sets with Q² >= 0), named for what uses it (the
sets, else the Pareto front, else nothing), and one for an infeasible level 2 naming its bottleneck unless its
target is checked already; labels in the text, in the order of the level-1 entries."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from demid.spec import MaterialSpec
from demid.story.advice import _recalibrate

_RESPONSES = ["D", "S", "T"]
_KRIGING = st.sampled_from([None, -0.4, 0.0, 0.7])


def _spec(pareto: bool) -> MaterialSpec:
    material = {"data": "x.csv", "design": {"type": "custom"},
                "factors": {"a": {"lower": 0.0, "upper": 1.0}, "b": {"lower": 0.0, "upper": 1.0}},
                "responses": {"D": {"target": 100.0, "label": "diameter"}, "S": {"unit": "-", "label": "spread"},
                              "T": {"target": -3.0}},
                "scenarios": {"d": {"observables": ["D"], "tolerance": 0.05},
                              "t": {"observables": ["D", "T"], "tolerance": 0.1}},
                **({"pareto": {"error_of": "D", "minimise": "S", "max_error": 0.05}} if pareto else {})}
    return MaterialSpec.from_material("m", material, grid_points=51)


@given(verdicts=st.lists(st.sampled_from(["does_not_predict", "adequate", None]), min_size=3, max_size=3),
       kriging=st.lists(_KRIGING, min_size=3, max_size=3), order=st.permutations(_RESPONSES),
       pareto=st.booleans(), feasible=st.sampled_from([None, True, False]),
       bottleneck=st.sampled_from([None, "D", "T"]), checked=st.sets(st.sampled_from(_RESPONSES)))
@settings(max_examples=80, deadline=None, derandomize=True)
def test_recalibrate_advice_names_each_unpredictive_surrogate_for_what_uses_it_and_an_infeasible_match(
        verdicts, kriging, order, pareto, feasible, bottleneck, checked):
    spec = _spec(pareto)
    labels = {"D": "diameter", "S": "spread", "T": "T"}
    level1 = {}
    for r, verdict, q2 in zip(order, verdicts, kriging):
        entry = {} if verdict is None else {"verdict": verdict}
        if q2 is not None:
            entry["sets_surrogate"] = {"surrogate": "kriging", "q2": q2}
        level1[r] = entry
    level2 = {} if feasible is None else {"feasible": feasible, "tolerance": 0.05, "bottleneck": bottleneck}
    items = _recalibrate(spec, level1, level2, checked)

    expected = []
    for r, entry in level1.items():
        kriging_predicts = "sets_surrogate" in entry and entry["sets_surrogate"]["q2"] >= 0
        if entry.get("verdict") == "does_not_predict" and not kriging_predicts:
            uses = ("the sets that use it are not to be trusted" if r in ("D", "T") else
                    "the Pareto front that uses it is indicative only" if pareto and r == "S" else
                    "do not use it to judge parameter sets")
            expected.append((r, f"Refit or resimulate {labels[r]}: its surrogate does not predict left-out runs "
                                f"(Q² < 0), so {uses}."))
    if feasible is False and bottleneck not in checked:
        which = (f"the target and the simulation of {labels[bottleneck]}, the observable that limits the best match"
                 if bottleneck else "the targets and their simulation")
        expected.append((bottleneck or "", f"No parameter set meets every target within 5 %: settle that first. "
                                           f"Check {which}."))
    assert [(i.observable, i.text) for i in items] == expected
    assert all(i.kind == "recalibrate" and i.material == "m" for i in items)

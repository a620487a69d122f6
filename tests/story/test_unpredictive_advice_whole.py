"""A material's advice where one, two or three surrogates do not predict left-out runs (level 1's verdict
``does_not_predict``): each such response gets its own recalibrate item, the ranking's caveat names them all in
config order with the grammar of their number (two is already plural), and the add-observable advice built on one
of them quotes its numbers to one digit with the same clause.  The sentences are written out here from the rule."""

from __future__ import annotations

from itertools import combinations

import pandas as pd
import pytest

from demid.spec import MaterialSpec
from demid.story.advice import material_advice

NAMES = ["y0", "y1", "y2", "y3"]


def _spec():
    responses = {o: {"target": 10.0 + i, "label": f"Y{i}"} for i, o in enumerate(NAMES)}
    return MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "custom"},
        "factors": {"a": {"lower": 0.0, "upper": 1.0}, "b": {"lower": 0.0, "upper": 1.0}},
        "responses": responses, "scenarios": {"full": {"observables": ["y0"], "tolerance": 0.05}}}, grid_points=21)


def _ranking():
    rows = []
    for size in range(1, len(NAMES) + 1):
        for s in combinations(NAMES, size):
            rows.append({"observables": "+".join(s), "n_observables": size,
                         "information_gain_bits": 1.5 * size + 0.1 * len("".join(s)),
                         "feasible_fraction_pct": 40.0 / size,
                         "best_subset": "y0" if size == 2 and s[0] == "y0" else "+".join(s[:-1]) or "(none)",
                         # y3 adds most to y0
                         "gain_vs_best_subset_bits": 2.25 if s == ("y0", "y3") else 0.5,
                         "targets_reachable": True})
    return pd.DataFrame(rows)


def _clause(labels: list[str]) -> str:
    many = len(labels) > 1
    return (f"the surrogate{'s' if many else ''} of {', '.join(labels)} {'do' if many else 'does'} not predict "
            "left-out runs (Q² < 0)")


@pytest.mark.parametrize("weak", [["y1"], ["y3", "y1"], ["y2", "y0", "y3"]])
def test_each_surrogate_that_does_not_predict_is_named_with_the_grammar_of_its_number(weak):
    spec = _spec()
    level1 = {o: {"verdict": "does_not_predict" if o in weak else "adequate"} for o in NAMES}
    items = material_advice(spec, pd.DataFrame(columns=["scenario", "factor", "verdict"]), ranking=_ranking(),
                            criticism={"level1": level1})
    in_order = [o for o in NAMES if o in weak]
    labels = [f"Y{o[1:]}" for o in in_order]

    recalibrate = [i for i in items if i.kind == "recalibrate"]
    assert [i.observable for i in recalibrate] == in_order
    for item, o, label in zip(recalibrate, in_order, labels):
        uses = "the sets that use it are not to be trusted" if o == "y0" else "do not use it to judge parameter sets"
        assert item.text == (f"Refit or resimulate {label}: its surrogate does not predict left-out runs (Q² < 0), "
                             f"so {uses}.")

    caveat = [i.text for i in items if i.kind == "measurement_order"][0]
    assert caveat == (f"The ranking rests on surrogates of which {_clause(labels)}: its gains and fractions are "
                      "rough, given to one significant digit.")

    added = [i for i in items if i.kind == "add_observable"]
    assert [i.observable for i in added] == ["y3"]
    weak_in_set = [f"Y{o[1:]}" for o in ("y0", "y3") if o in weak]
    if weak_in_set:
        assert added[0].text == (f"Measure Y3 as well: by the surrogates it adds about 2 bits of information and "
                                 f"leaves about 20 % of the domain admissible, but {_clause(weak_in_set)}, so these "
                                 "numbers are rough.")
    else:
        assert added[0].text == ("Measure Y3 as well: it adds 2.25 bits of information and leaves 20 % of the domain "
                                 "admissible.")

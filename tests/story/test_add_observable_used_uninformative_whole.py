"""The add-observable advice when an observable already measured is uninformative on its own (its band covers its
whole simulated range): only the observable to be added is judged, so the advice still names the informative,
reachable one that gains most over the set in use, with its gain and fraction, never the generic line; an added
observable that is itself uninformative is still passed over.  Generated studies of 3-4 observables, 1-3 in use."""

from __future__ import annotations

import re

import numpy as np
import pandas as pd
import pytest

from tests.story.test_advice_whole import _ranking, _study
from demid.story.advice import GENERIC_ADD_OBSERVABLE, material_advice


@pytest.mark.parametrize("seed, count, used_size", [(1, 3, 1), (2, 3, 2), (3, 4, 2), (4, 4, 3), (5, 4, 1)])
def test_a_used_uninformative_observable_does_not_hide_the_measurement_to_add(seed, count, used_size):
    rng = np.random.default_rng(seed)
    spec, names, used = _study(rng, 2, count, used_size)
    extra = [o for o in names if o not in used]
    ranking = _ranking(rng, names, used, unreachable=set())
    uninformative = {used[-1]: "band covers it"}
    if len(extra) > 1:
        uninformative[extra[0]] = "band covers it"  # an uninformative one to add is still passed over
    level2 = {"feasible": True, "tolerance": 0.05, "best_max_error": 0.01, "observables": list(used),
              "bottleneck": used[0]}
    verdicts = pd.DataFrame([{"scenario": "full", "factor": spec.factors[0].name, "verdict": "unresolved"}])
    items = material_advice(spec, verdicts, ranking=ranking, criticism={"level2": level2}, uninformative=uninformative)
    grow = ranking[(ranking["best_subset"] == "+".join(used)) & (ranking["n_observables"] == len(used) + 1)]
    candidates = [(row["gain_vs_best_subset_bits"], row["feasible_fraction_pct"], o)
                  for _, row in grow.iterrows() for o in row["observables"].split("+")
                  if o not in used and o not in uninformative]
    gain, fraction, named = max(candidates)
    added = [i for i in items if i.kind == "add_observable"]
    assert [i.observable for i in added] == [named] and added[0].text != GENERIC_ADD_OBSERVABLE
    said = re.fullmatch(rf"Measure Y{named[1:]} as well: it adds ([\d.]+) bits of information and leaves "
                        r"([\d.e+-]+) % of the domain admissible\.", added[0].text)
    assert said, added[0].text
    assert said.group(1) == f"{gain:.2f}" and float(said.group(2)) == pytest.approx(fraction, rel=5e-3)

"""The runs that would decide between candidate causes (criticism.discrimination.discriminating_runs), whole, against
the documented greedy rule written out in the test over the candidate grid: the i-th run (made i runs after the
last) goes where the pairs' progress -- each pair's separation over its target (target_separation of its AICc gap),
capped at 1, summed, plus a thousandth of the least-separated pair's -- is largest (to nine decimals; a point not
yet chosen before one already chosen, then the first in grid order); the runs stop once every pair reaches its
target, at most MAX_RUNS.  Two to four candidates (drift, steps, the plain surface, a cubic term), with and
without AICc gaps, with candidates of one kind not separated from each other; every field of every run."""

from __future__ import annotations

from itertools import combinations

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from demid.criticism.discrimination import (MAX_RUNS, candidate_grid, discriminating_runs, joint_separation,
                                            prediction_parts, target_separation)
from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm, json_number
from demid.design import parse_term
from demid.run_purposes import DECIDE
from tests.generators import FACTORS, ccd_table


def _form(name: str, runs: int) -> ModelForm:
    return {"drift": ModelForm(drift=True), "step": ModelForm(step=runs // 2), "step+1": ModelForm(step=runs // 2 + 1),
            "plain": ModelForm(), "cubic": ModelForm(extra_terms=(parse_term("mu_r^3", FACTORS[2]),))}[name]


def _greedy(data, models, labels, aiccs, kinds):
    points = candidate_grid(data)
    pairs = [(a, b) for a, b in combinations(range(len(models)), 2) if kinds is None or kinds[a] != kinds[b]]
    if len(models) < 2 or not pairs:
        return []
    target = np.array([target_separation(abs(aiccs[a] - aiccs[b]) if aiccs else 0.0) for a, b in pairs])
    chosen = []  # (point index, per model (mean, jac row, noise), separations of the pairs)
    for later in range(1, MAX_RUNS + 1):
        parts = [prediction_parts(m, points, later) for m in models]
        sep = np.empty((len(points), len(pairs)))
        for j, (a, b) in enumerate(pairs):
            sep[:, j] = joint_separation([c[1][a] for c in chosen], [c[1][b] for c in chosen], parts[a], parts[b])
        ratio = sep / target
        gain = np.round(np.minimum(ratio, 1.0).sum(axis=1) + 1e-3 * ratio.min(axis=1), 9)
        taken = {c[0] for c in chosen}
        best = min(range(len(points)), key=lambda i: (-gain[i], i in taken, i))
        chosen.append((best, [(p[0][best], p[1][best], p[2][best]) for p in parts], sep[best]))
        if np.all(sep[best] >= target):
            break
    out = []
    for i, of_model, sep_i in chosen:
        run = data.point_dict(points[i])
        run["purpose"] = DECIDE
        run["expected"] = {label: json_number(p[0]) for label, p in zip(labels, of_model)}
        run["separation"] = json_number(float(np.min(sep_i)))
        out.append(run)
    return out


@given(seed=st.integers(0, 5000), size=st.sampled_from([8.0, 25.0, 60.0]),
       labels=st.lists(st.sampled_from(["drift", "step", "step+1", "plain", "cubic"]), min_size=2, max_size=4,
                       unique=True),
       gaps=st.booleans(), grouped=st.booleans())
@example(seed=3, size=25.0, labels=["drift", "plain", "step"], gaps=True, grouped=False)  # the better one first
@example(seed=4, size=8.0, labels=["plain", "drift"], gaps=True, grouped=False)
@settings(max_examples=8, deadline=None, derandomize=True)
def test_every_deciding_run_is_the_greedy_rules(seed, size, labels, gaps, grouped):
    table, _ = ccd_table(seed, 2, "drift", size)
    data, _ = prepare_data(table, FACTORS[2], "y", None, ())
    models = [Model(data, _form(name, len(table))) for name in labels]
    aiccs = [float(m.aicc) for m in models] if gaps else None
    # the two steps as one kind (terms aliased on these runs): separated from the others, not from each other
    kinds = [("step" if name.startswith("step") else name) for name in labels] if grouped else None
    got = discriminating_runs(data, models, labels, aiccs, kinds)
    want = _greedy(data, models, labels, aiccs, kinds)
    assert [{k: v for k, v in r.items() if k not in ("expected", "separation")} for r in got] == \
        [{k: v for k, v in r.items() if k not in ("expected", "separation")} for r in want]
    for g, w in zip(got, want):
        assert g["expected"].keys() == w["expected"].keys()
        for label in labels:
            assert g["expected"][label] == pytest.approx(w["expected"][label], rel=1e-9, abs=1e-12)
        assert g["separation"] == pytest.approx(w["separation"], rel=1e-9, abs=1e-12)


def test_a_single_candidate_or_a_single_kind_needs_no_runs():
    table, _ = ccd_table(1, 2, "drift", 20.0)
    data, _ = prepare_data(table, FACTORS[2], "y", None, ())
    step, step1 = (Model(data, _form(name, len(table))) for name in ("step", "step+1"))
    assert discriminating_runs(data, [step], ["step"]) == []
    assert discriminating_runs(data, [step, step1], ["a", "b"], kinds=["step", "step"]) == []
    assert len(discriminating_runs(data, [step, step1], ["a", "b"])) >= 1

"""Deciding runs over generated drifting tables with 1-3 candidate causes (a drift, steps, the plain surface, a
cubic term): the runs stop at the first run after which every pair of candidates is separated to its target (the
reported separation is the least-separated pair's), and not before; one candidate needs no runs."""

from __future__ import annotations

import numpy as np
from hypothesis import example, given, settings
from hypothesis import strategies as st

from demid.criticism import discrimination
from demid.criticism.discrimination import MAX_RUNS, joint_separation, prediction_parts, target_separation
from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm
from demid.design import parse_term
from tests.generators import FACTORS, ccd_table


def _candidate(name: str, runs: int) -> ModelForm:
    """A drift, steps at three change-points (two of them next to each other), the plain surface, a cubic term."""
    return {"drift": ModelForm(drift=True), "step": ModelForm(step=runs // 2), "step+1": ModelForm(step=runs // 2 + 1),
            "step-3": ModelForm(step=runs // 2 - 3), "plain": ModelForm(),
            "cubic": ModelForm(extra_terms=(parse_term("mu_r^3", FACTORS[2]),))}[name]


@given(seed=st.integers(0, 10_000), size=st.floats(10.0, 60.0),
       labels=st.lists(st.sampled_from(["drift", "step", "step+1", "step-3", "plain", "cubic"]), min_size=1,
                       max_size=3, unique=True))
@example(seed=0, size=60.0, labels=["drift", "step", "step+1"])  # drift-step decided by one run, the steps not
@settings(max_examples=10, deadline=None, derandomize=True)
def test_deciding_runs_separate_every_pair_of_candidates(seed, size, labels):
    table, _ = ccd_table(seed, 2, "drift", size)
    data, _ = prepare_data(table, FACTORS[2], "y", None, ())
    models = [Model(data, _candidate(name, len(table))) for name in labels]
    count = len(models)
    runs = discrimination.discriminating_runs(data, models, labels)
    if count == 1:
        assert runs == []
        return
    assert 1 <= len(runs) <= MAX_RUNS
    target = target_separation(0.0)
    # each pair's separation by all the runs, recomputed from the runs' points and each model's predictions
    points = data.coding.to_coded(np.array([[r[f] for f in FACTORS[2]] for r in runs]))
    pair_separations = []
    for a in range(count):
        for b in range(a + 1, count):
            parts = [prediction_parts(models[m], points[i:i + 1], later=i + 1) for m in (a, b)
                     for i in range(len(runs))]
            chosen_a = [(p[0][0], p[1][0], p[2][0]) for p in parts[:len(runs)]]
            chosen_b = [(p[0][0], p[1][0], p[2][0]) for p in parts[len(runs):]]
            last_a, last_b = parts[len(runs) - 1], parts[-1]
            pair_separations.append(float(joint_separation(chosen_a[:-1], chosen_b[:-1], last_a, last_b)[0]))
    # the reported separation is written to a few significant digits
    assert abs(runs[-1]["separation"] - min(pair_separations)) <= 1e-3 * max(1.0, min(pair_separations))
    if len(runs) < MAX_RUNS:
        assert min(pair_separations) >= target  # stopped: every pair is decided
    # fewest runs: before the last, some pair was still short of its target
    assert all(r["separation"] < target for r in runs[:-1])
    assert all(set(r["expected"]) == set(labels) for r in runs)

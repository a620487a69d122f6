"""Deciding runs over generated tables with 1-3 candidate causes: the runs stop at the first run after which
every pair of candidates is separated to its target (the reported separation is the least-separated pair's), and
not before; one candidate needs no runs."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.criticism import discrimination
from demid.criticism.discrimination import MAX_RUNS, _joint_separation, _prediction_parts, target_separation
from demid.criticism.level1 import _prepare
from demid.criticism.models import _Model, _Spec
from demid.design import parse_term
from tests.generators import FACTORS, ccd_table

CANDIDATE_TERMS = [(), ("mu_r^3",), ("gamma^3",), ("mu_r^2:gamma",)]


@given(seed=st.integers(0, 10_000), size=st.floats(0.0, 8.0), count=st.integers(1, 3),
       first=st.integers(0, 3))
@settings(max_examples=10, deadline=None, derandomize=True)
def test_deciding_runs_separate_every_pair_of_candidates(seed, size, count, first):
    table, _ = ccd_table(seed, 2, "term", size, term="mu_r^3")
    data, _ = _prepare(table, FACTORS[2], "y", None, ())
    specs = [CANDIDATE_TERMS[(first + i) % len(CANDIDATE_TERMS)] for i in range(count)]
    models = [_Model(data, _Spec(extra_terms=tuple(parse_term(t, FACTORS[2]) for t in terms))) for terms in specs]
    labels = ["+".join(terms) or "quadratic" for terms in specs]
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
            parts = [_prediction_parts(models[m], points[i:i + 1], later=i + 1) for m in (a, b)
                     for i in range(len(runs))]
            chosen_a = [(p[0][0], p[1][0], p[2][0]) for p in parts[:len(runs)]]
            chosen_b = [(p[0][0], p[1][0], p[2][0]) for p in parts[len(runs):]]
            last_a, last_b = parts[len(runs) - 1], parts[-1]
            pair_separations.append(float(_joint_separation(chosen_a[:-1], chosen_b[:-1], last_a, last_b)[0]))
    # the reported separation is written to a few significant digits
    assert abs(runs[-1]["separation"] - min(pair_separations)) <= 1e-3 * max(1.0, min(pair_separations))
    if len(runs) < MAX_RUNS:
        assert min(pair_separations) >= target  # stopped: every pair is decided
    # fewest runs: before the last, some pair was still short of its target
    assert all(r["separation"] < target for r in runs[:-1])
    assert all(set(r["expected"]) == set(labels) for r in runs)

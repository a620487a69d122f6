"""Outputs of the loop's helpers against computations written here, over generated inputs: the criticism's runs
for the next wave (several responses proposing the same points, replicates, purposes in any order: each point made
as often as the response that asks for it most, the deciding runs first, in the order proposed), the boundary
batch when every score is nil (distance alone decides: the farthest-point sequence, 1-4 factors, with or without
a spacing length), the spacing rule in closed form, and which level-1 entries learn that kriging judged their
sets (only kriging rows, only responses the criticism has, each with its own Q²)."""

from __future__ import annotations

import json
from collections import Counter

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid import run_purposes
from demid.boundary_runs import SPACING_FACTOR, greedy_batch, spacing
from demid.kriging import KIND, QUADRATIC
from demid.surrogate_choice import SETS_SURROGATE_KEY, mark_criticism
from demid.wave_runs import deciding_runs

_PURPOSES = [run_purposes.DECIDE, run_purposes.CONFIRM]


@given(seed=st.integers(0, 10_000), responses=st.integers(1, 3), points=st.integers(1, 4),
       requests=st.integers(1, 8))
@settings(max_examples=60, deadline=None, derandomize=True)
def test_criticism_runs_are_made_as_often_as_the_response_that_asks_most_deciding_ones_first(seed, responses,
                                                                                            points, requests):
    rng = np.random.default_rng(seed)
    factors = ["a", "b"]
    pool = [{"a": float(rng.integers(-2, 3)), "b": float(rng.integers(0, 5)) / 4} for _ in range(points)]
    purpose_of = {k: _PURPOSES[int(rng.integers(0, 2))] for k in range(points)}
    rows, asked = [], []
    for r in range(responses):
        runs = []
        for _ in range(int(rng.integers(0, requests + 1))):
            k = int(rng.integers(0, points))
            runs.append({**pool[k], "purpose": purpose_of[k]})
            asked.append((r, k))
        rows.append({"response": f"y{r}", "discriminating_runs": json.dumps(runs) if runs else ""})
    got = deciding_runs(pd.DataFrame(rows), factors)
    keys = {k: (pool[k]["a"], pool[k]["b"]) for k in range(points)}
    # the same point twice in the pool is one point: its requests add up per response
    per_response = Counter((r, keys[k]) for r, k in asked)
    expected = Counter()
    for (r, key), count in per_response.items():
        expected[key] = max(expected[key], count)
    assert Counter((run["a"], run["b"]) for run in got) == expected
    assert len(got) == sum(expected.values())
    purposes = [run["purpose"] for run in got]
    assert purposes == sorted(purposes, key=lambda p: p != run_purposes.DECIDE)
    for run in got:
        assert set(run) == {"a", "b", "response", "purpose"} and run["response"] in {r["response"] for r in rows}


def _farthest_points(candidates: np.ndarray, existing: np.ndarray, count: int) -> list[int]:
    chosen: list[int] = []
    for _ in range(count):
        pts = np.vstack([existing, candidates[chosen]]) if len(existing) or chosen else np.zeros((0, 2))
        if len(pts):
            dist = np.array([min(np.linalg.norm(c - p) for p in pts) for c in candidates])
        else:
            dist = np.ones(len(candidates))
        dist[chosen] = -1.0
        chosen.append(int(np.argmax(dist)))  # the first of equal distances
    return chosen


@given(seed=st.integers(0, 10_000), k=st.integers(1, 4), earlier=st.integers(1, 3), count=st.integers(1, 5),
       with_length=st.booleans())
@settings(max_examples=40, deadline=None, derandomize=True)
def test_with_every_score_nil_distance_alone_decides_the_batch(seed, k, earlier, count, with_length):
    rng = np.random.default_rng(seed)
    candidates = rng.uniform(0.0, 1.0, (30, k))
    existing = rng.uniform(0.0, 1.0, (earlier, k))
    # a length below every distance between points: the space-filling factor is 1 for every candidate
    length = 1e-6 if with_length else None
    got = greedy_batch(np.zeros(len(candidates)), candidates, existing, count, length)
    assert got == _farthest_points(candidates, existing, count)


@pytest.mark.parametrize("n_runs, k, expected", [(16, 2, 0.125), (64, 3, 0.125), (81, 4, 1 / 6), (10, 1, 0.05),
                                                 (0, 2, 0.5), (1, 3, 0.5)])
def test_the_spacing_is_half_that_of_a_space_filling_design(n_runs, k, expected):
    assert SPACING_FACTOR == 0.5
    assert spacing(n_runs, k) == pytest.approx(expected, rel=1e-12)


@given(kinds=st.lists(st.tuples(st.sampled_from([KIND, QUADRATIC]), st.booleans(), st.floats(-1.0, 1.0)),
                      min_size=1, max_size=4))
@settings(max_examples=40, deadline=None, derandomize=True)
def test_only_kriging_judged_responses_of_the_criticism_are_marked_with_their_q2(kinds):
    rows, level1 = [], {}
    for i, (kind, criticised, q2) in enumerate(kinds):
        rows.append({"response": f"y{i}", "surrogate": kind, "q2": 0.3, "q2_kriging": q2})
        if criticised:
            level1[f"y{i}"] = {"verdict": "does_not_predict"}
    summary = {"level1": level1}
    mark_criticism(summary, pd.DataFrame(rows))
    for i, (kind, criticised, q2) in enumerate(kinds):
        if not criticised:
            assert f"y{i}" not in summary["level1"]
            continue
        entry = summary["level1"][f"y{i}"]
        if kind == KIND:
            assert entry[SETS_SURROGATE_KEY] == {"surrogate": KIND, "q2": q2}
        else:
            assert SETS_SURROGATE_KEY not in entry


@pytest.mark.parametrize("k", [1, 2, 3, 4])
def test_kriging_fits_from_three_runs_beyond_its_quadratic_trend_up_to_its_largest_table(k):
    from types import SimpleNamespace

    from demid.surrogate_choice import KRIGING_MAX_RUNS, kriging_fits

    trend = (k + 1) * (k + 2) // 2  # the full quadratic in k factors
    spec = SimpleNamespace(dim=k)
    assert [kriging_fits(n, spec) for n in (trend + 2, trend + 3)] == [False, True]
    assert [kriging_fits(n, spec) for n in (KRIGING_MAX_RUNS, KRIGING_MAX_RUNS + 1)] == [True, False]


@given(q2_quadratic=st.sampled_from([-3.0, -1.0, 0.0, 0.5, 0.75]), share=st.sampled_from([0.25, 0.5, 1.0, 2.0]))
@settings(max_examples=30, deadline=None, derandomize=True)
def test_kriging_is_preferred_when_its_unexplained_share_is_at_most_half_the_quadratics(q2_quadratic, share):
    from demid.surrogate_choice import CHOICE_PRESS_RATIO, prefers_kriging

    assert CHOICE_PRESS_RATIO == 0.5
    # 1 - Q²_kriging = share * 0.5 * (1 - Q²_quadratic), exact in binary for these values: at most half is kriging
    # where the quadratic shows no lack of fit (p 0.5); where it misfits the margin is 0.8 (test_surrogate_choice_rule)
    q2_kriging = 1.0 - share * 0.5 * (1.0 - q2_quadratic)
    assert prefers_kriging(q2_quadratic, q2_kriging, 0.5) == (share <= 1.0)
    assert prefers_kriging(float("nan"), q2_kriging) and not prefers_kriging(q2_quadratic, float("nan"))

"""The boundary runs' greedy batch over generated candidates, scores of any scale (1e-8 to 1e8), 1-4 factors,
with and without earlier runs and a spacing length: each pick is the candidate with the largest score times its
space-filling factor (min(1, d / length), or d), d its distance to the nearest earlier or chosen point, written
out here with no rounding on candidates whose values are well apart."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.boundary_runs import NIL_SCORE, TIE_BREAK, greedy_batch


def _picks(score, candidates, existing, count, length):
    """The documented greedy rule, pick by pick, and the smallest relative gap between a pick's value and the
    runner-up's (a near tie may go either way under round-off)."""
    score = score + NIL_SCORE * max(score.max(), 1e-300) + 1e-300
    dist = np.array([min((np.linalg.norm(c - e) for e in existing), default=np.sqrt(len(c))) for c in candidates])
    chosen, gap = [], np.inf
    for _ in range(count):
        factor = dist if length is None else np.minimum(1.0, dist / length)
        value = score * factor + TIE_BREAK * dist
        value[chosen] = -np.inf
        order = np.argsort(-value, kind="stable")
        gap = min(gap, (value[order[0]] - value[order[1]]) / value[order[0]])
        chosen.append(int(order[0]))
        dist = np.minimum(dist, np.linalg.norm(candidates - candidates[order[0]], axis=1))
    return chosen, gap


@given(k=st.integers(1, 4), seed=st.integers(0, 10_000), scale=st.sampled_from([1e-8, 1e-3, 1.0, 1e8]),
       earlier=st.integers(0, 3), count=st.integers(1, 4), length=st.sampled_from([None, 0.05, 0.3]))
@settings(max_examples=60, deadline=None, derandomize=True)
def test_each_pick_is_the_largest_score_times_its_space_filling_factor(k, seed, scale, earlier, count, length):
    rng = np.random.default_rng(seed)
    candidates = rng.uniform(0.0, 1.0, (40, k))
    existing = rng.uniform(0.0, 1.0, (earlier, k))
    score = scale * rng.uniform(0.0, 1.0, 40) ** 3
    expected, gap = _picks(score, candidates, existing, count, length)
    if gap < 1e-6:  # a near tie: the rule allows either pick
        return
    assert greedy_batch(score, candidates, existing, count, length) == expected


def test_a_quarter_of_the_runs_explore_by_default_and_the_count_given_otherwise():
    """The kinds of a wave's runs: round(count / 4) explore by default, the rest are placed on the boundary;
    an explicit ``explore`` is kept (up to the count); the runs are distinct points of the search range."""
    from demid.boundary_runs import EXPLORE_SHARE, boundary_runs
    from demid.scenario import JudgedScenario
    from demid.spec import MaterialSpec
    from demid.surrogate import fit_response
    from tests.helpers import make_ccd_table

    table = make_ccd_table(lambda x: {"y": 10 + 4 * x[:, 0] + 2 * x[:, 1]}, [0.0, 0.0], [1.0, 1.0], noise=0.05,
                           seed=4).rename(columns={"x1": "a", "x2": "b"})
    spec = MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "custom"},
        "factors": {"a": {"lower": 0.0, "upper": 1.0}, "b": {"lower": 0.0, "upper": 1.0}},
        "responses": {"y": {"target": 13.0}}, "scenarios": {"s": {"observables": ["y"], "tolerance": 0.02}}},
        grid_points=41)
    judged = JudgedScenario(spec, spec.scenarios[0], {"y": fit_response(table, ["a", "b"], "y").surrogate()}, 2.0)
    earlier = table[["a", "b"]].to_numpy(dtype=float)
    assert EXPLORE_SHARE == 0.25
    for count in (1, 2, 3, 5, 6, 9, 12):
        runs, kinds = boundary_runs(judged, earlier, count)
        explore = int(round(count / 4))
        assert kinds == ["boundary"] * (count - explore) + ["explore"] * explore
        assert runs.shape == (count, 2) and len({tuple(r) for r in runs}) == count
        assert np.all((runs >= 0.0) & (runs <= 1.0))
    runs, kinds = boundary_runs(judged, earlier, 5, explore=7)
    assert kinds == ["explore"] * 5
    runs, kinds = boundary_runs(judged, earlier, 6, explore=2)
    assert kinds == ["boundary"] * 4 + ["explore"] * 2


def test_the_omega_waves_reason_counts_each_kind_of_run_it_placed():
    """A wave placed over the whole search range: every count its reason quotes (runs deciding between causes,
    on the boundary, exploring, separating aliased terms) is the number of runs of that purpose in the wave, for
    counts 8-12 with and without deciding runs and aliased terms."""
    import json
    import re

    import pandas as pd

    from demid.next_wave import PURPOSE_DECIDE, plan_next_wave
    from demid.spec import MaterialSpec
    from tests.test_boundary_runs import _linear, _study

    table, spec, surrogates, plausible = _study(_linear)
    separated = 0
    for count, deciding, aliased in [(8, 0, False), (9, 2, True), (10, 0, True), (12, 1, False), (11, 3, True)]:
        spec = MaterialSpec.from_material("m", {**spec.material_config(),
                                                "next_runs": {"count": count, "scenario": "", "margin": 0.1}})
        rows = [{"response": "y", "cause": "ambiguous", "detail": "outlier (3);step (9)", "aliases": "",
                 "discriminating_runs": json.dumps([{"a": 0.2, "b": 0.7, "purpose": PURPOSE_DECIDE}] * deciding)}]
        if aliased:
            rows.append({"response": "y", "cause": "missing_term", "aliases": "a^3;a:b^2", "detail": "",
                         "discriminating_runs": "[]"})
        wave = plan_next_wave("m", table, surrogates, spec, plausible, pd.DataFrame(rows), z=2.0,
                              analysed_over_omega=True)
        purposes = wave.runs["purpose"].tolist()
        assert len(purposes) == count
        said = {"decide": re.search(r"; first (\d+) run\(s\) to decide between causes", wave.reason),
                "boundary": re.search(r"; (\d+) where the classification of the set is most uncertain", wave.reason),
                "explore": re.search(r", (\d+) where the surrogate is least certain", wave.reason),
                "separate": re.search(r", (\d+) to separate aliased terms the criticism found", wave.reason)}
        counted = {"decide": purposes.count(PURPOSE_DECIDE),
                   "boundary": sum("classification of the set is most uncertain" in p for p in purposes),
                   "explore": sum("surrogate is least certain" in p for p in purposes),
                   "separate": sum(p.startswith("separate aliased terms") for p in purposes)}
        for kind, match in said.items():
            assert (int(match[1]) if match else 0) == counted[kind], (kind, wave.reason)
        assert counted["decide"] == deciding and sum(counted.values()) == count
        assert counted["separate"] <= int(aliased)
        separated += counted["separate"]
    assert separated >= 1  # a separating run was placed (where the count leaves room for it)


def test_the_candidate_grid_over_omega_has_its_documented_size_and_spans_the_search_range():
    """41 nodes per axis up to two factors, else the k-th root of 4096 (at least 5): 16 in three factors, 8 in
    four, 5 from five on; each axis from the search range's lower to its upper end (log10 for a log factor)."""
    import itertools

    from demid.boundary_runs import omega_candidates
    from demid.scenario import JudgedScenario
    from demid.spec import MaterialSpec

    for k, n in [(1, 41), (2, 41), (3, 16), (4, 8), (5, 5)]:
        factors = {f"f{i}": ({"lower": 1e-3, "upper": 10.0, "scale": "log"} if i == 0 else
                             {"lower": -2.0 - i, "upper": 5.0 * i + 1.0}) for i in range(k)}
        spec = MaterialSpec.from_material("m", {
            "data": "x.csv", "design": {"type": "custom"}, "factors": factors, "responses": {"y": {"target": 1.0}},
            "scenarios": {"s": {"observables": ["y"], "tolerance": 0.05}}})
        judged = JudgedScenario(spec, spec.scenarios[0], {}, 2.0)
        lo, hi = spec.domain.search_bounds()
        expected = np.array(list(itertools.product(*[np.linspace(a, b, n) for a, b in zip(lo, hi)])))
        assert np.array_equal(omega_candidates(judged), expected)

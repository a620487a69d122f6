"""The next wave's box and tables, every number against a computation written here over generated inputs: the
plausible spans widened by the margin and clipped to the range (1-3 factors, log scales, ranges away from the
origin, spans at or past the range's ends, an empty set), the planned box read from a plausible frame in any row
order, the plausible grid points of a box (its documented size, the judged set's members), the proposals' table
(rounded to ten digits, a run on the box's edge kept inside, the predictions) and the long tables of several
materials."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.next_wave import (NextWave, _runs_frame, next_box, planned_box, plausible_points, refocus_scenario,
                             tabulate_waves)
from demid.sampling import Domain

_FAST = settings(max_examples=25, deadline=None, derandomize=True)


def _domain(k, seed, log_mask):
    rng = np.random.default_rng(seed)
    lower = rng.uniform(-3.0, 2.0, k)
    upper = lower + rng.uniform(0.5, 4.0, k)
    log = tuple(bool(log_mask >> i & 1) for i in range(k))
    to_actual = lambda v: np.where(np.array(log), 10 ** v, v)  # noqa: E731
    return Domain(tuple(f"f{i}" for i in range(k)), tuple(to_actual(lower)), tuple(to_actual(upper)), log), \
        lower, upper, to_actual, rng


@_FAST
@given(k=st.integers(1, 3), seed=st.integers(0, 10_000), log_mask=st.integers(0, 7),
       margin=st.sampled_from([0.0, 0.05, 0.1, 0.3]))
def test_the_next_box_is_the_plausible_span_widened_by_the_margin_and_clipped(k, seed, log_mask, margin):
    domain, lower, upper, to_actual, rng = _domain(k, seed, log_mask)
    width = upper - lower
    a = lower + rng.uniform(-0.1, 0.9, k) * width  # spans may start before the range and end past it
    b = np.minimum(a + rng.uniform(0.0, 0.6, k) * width, upper + 0.05 * width)
    lo, hi = next_box(domain, to_actual(a), to_actual(b), margin)
    assert lo == pytest.approx(np.maximum(lower, a - margin * width), rel=1e-12, abs=1e-12)
    assert hi == pytest.approx(np.minimum(upper, b + margin * width), rel=1e-12, abs=1e-12)
    nan = np.full(k, np.nan)
    for empty in (nan, np.where(np.arange(k) == 0, np.nan, to_actual(a))):
        kept_lo, kept_hi = next_box(domain, empty, nan, margin)
        assert kept_lo == pytest.approx(lower, rel=1e-12) and kept_hi == pytest.approx(upper, rel=1e-12)


def _spec(domain, margin, scenario_names=("s",)):
    scenarios = [SimpleNamespace(name=n, observables=["y"] * (i + 1), tolerance=0.05)
                 for i, n in enumerate(scenario_names)]
    return SimpleNamespace(domain=domain, factor_names=list(domain.factors), scenarios=scenarios,
                           next_runs=SimpleNamespace(scenario=None, margin=margin))


@_FAST
@given(k=st.integers(1, 3), seed=st.integers(0, 10_000), log_mask=st.integers(0, 7), fraction=st.sampled_from(
    [0.0, 1e-9, 12.5]), margin=st.sampled_from([0.0, 0.1]), nan_factor=st.booleans())
def test_the_planned_box_reads_the_refocus_scenarios_rows_in_any_order(k, seed, log_mask, fraction, margin,
                                                                       nan_factor):
    domain, lower, upper, to_actual, rng = _domain(k, seed, log_mask)
    width = upper - lower
    a = lower + rng.uniform(0.1, 0.5, k) * width
    b = a + rng.uniform(0.0, 0.4, k) * width
    spec = _spec(domain, margin, ("one", "two"))  # the refocus scenario: "two", the most observables
    rows = [{"scenario": "two", "factor": f"f{i}", "robust_fraction_pct": fraction,
             "robust_lower": np.nan if nan_factor and i == k - 1 else float(to_actual(a)[i]),
             "robust_upper": float(to_actual(b)[i])} for i in range(k)]
    rows += [{"scenario": "one", "factor": f"f{i}", "robust_fraction_pct": 50.0, "robust_lower": float(to_actual(lower)[i]),
              "robust_upper": float(to_actual(upper)[i])} for i in range(k)]
    frame = pd.DataFrame(rows[::-1])
    lo, hi, empty = planned_box(spec, frame)
    assert empty is (fraction == 0.0 or nan_factor)
    if nan_factor:
        assert lo == pytest.approx(lower, rel=1e-12) and hi == pytest.approx(upper, rel=1e-12)
    else:
        assert lo == pytest.approx(np.maximum(lower, a - margin * width), rel=1e-12, abs=1e-12)
        assert hi == pytest.approx(np.minimum(upper, b + margin * width), rel=1e-12, abs=1e-12)


@pytest.mark.parametrize("k, per_axis", [(1, 41), (2, 41), (3, 16), (4, 8), (6, 5)])
def test_the_plausible_points_are_the_boxs_grid_points_in_the_set(k, per_axis):
    domain, lower, upper, to_actual, rng = _domain(k, k, (1 << k) - 2)
    lo = lower + 0.2 * (upper - lower)
    hi = upper - 0.1 * (upper - lower)
    centre = rng.uniform(lo, hi)
    seen = []

    def contains(points):
        seen.append(len(points))
        search = np.column_stack([np.log10(points[:, i]) if lg else points[:, i] for i, lg in enumerate(domain.log)])
        return np.sum(((search - centre) / (hi - lo)) ** 2, axis=1) <= 0.3 ** 2

    judged = SimpleNamespace(spec=SimpleNamespace(domain=domain), contains=contains)
    got = plausible_points(judged, lo, hi)
    axes = [np.linspace(a, b, per_axis) for a, b in zip(lo, hi)]
    grid = np.array(np.meshgrid(*axes, indexing="ij")).reshape(k, -1).T
    inside = np.sum(((grid - centre) / (hi - lo)) ** 2, axis=1) <= 0.3 ** 2
    assert seen == [per_axis ** k]
    assert got == pytest.approx(grid[inside], rel=1e-12, abs=1e-12)


class _Linear:
    def __init__(self, coef, offset):
        self.coef, self.offset = np.asarray(coef), offset

    def predict(self, points):
        return self.offset + np.asarray(points) @ self.coef


@given(seed=st.integers(0, 10_000), n=st.integers(1, 6), k=st.integers(1, 3))
@settings(max_examples=20, deadline=None, derandomize=True)
def test_the_proposals_table_rounds_each_run_to_ten_digits_inside_its_box_and_predicts_it(seed, n, k):
    rng = np.random.default_rng(seed)
    lower = rng.uniform(-5, 5, k) + 1 / 3
    upper = lower + rng.uniform(0.1, 10, k) + 1 / 7
    points = lower + rng.uniform(0, 1, (n, k)) * (upper - lower)
    points[0] = lower  # on the box's edges: rounding must not move them out
    if n > 1:
        points[1] = upper
    if n > 2:
        points[2, 0] = upper[0] + 1.0  # a criticism run outside the box: rounded, not clamped
    factors = [f"f{i}" for i in range(k)]
    spec = SimpleNamespace(factor_names=factors)
    surrogates = {"y": _Linear(rng.normal(size=k), 2.0), "z": _Linear(rng.normal(size=k), -1.0)}
    purposes = [f"p{i}" for i in range(n)]
    runs = _runs_frame("m", spec, points, purposes, lower, upper, surrogates)
    assert list(runs.columns) == ["material", "proposal", *factors, "purpose", "predicted_y", "predicted_z"]
    assert list(runs["proposal"]) == list(range(1, n + 1)) and set(runs["material"]) == {"m"}
    assert list(runs["purpose"]) == purposes
    for i, f in enumerate(factors):
        for r in range(n):
            rounded = float(f"{points[r, i]:.10g}")
            inside = lower[i] <= points[r, i] <= upper[i]
            expected = min(max(rounded, lower[i]), upper[i]) if inside else rounded
            assert runs[f].iloc[r] == expected
            assert abs(runs[f].iloc[r] - points[r, i]) <= 1e-9 * max(abs(points[r, i]), 1e-300)
    for name, sur in surrogates.items():
        assert runs[f"predicted_{name}"].to_numpy() == pytest.approx(sur.predict(points), rel=1e-12, abs=1e-12)


def test_the_long_tables_hold_every_materials_rows_and_the_union_of_their_columns():
    first = NextWave(pd.DataFrame({"material": "m1", "factor": ["a"], "lower": [0.0], "upper": [1.0]}),
                     pd.DataFrame({"material": "m1", "proposal": [1, 2], "a": [0.1, 0.2], "purpose": ["x", "y"],
                                   "predicted_y": [1.0, 2.0]}), "r1")
    second = NextWave(pd.DataFrame({"material": "m2", "factor": ["b", "a"], "lower": [2.0, 3.0], "upper": [4.0, 5.0]}),
                      pd.DataFrame({"material": "m2", "proposal": [1], "b": [2.5], "a": [3.5], "purpose": ["z"],
                                    "predicted_w": [7.0]}), "r2")
    specs = {"m1": SimpleNamespace(factor_names=["a"]), "m2": SimpleNamespace(factor_names=["b", "a"])}
    domain, runs, reasons = tabulate_waves(specs, {"m1": first, "m2": second})
    assert domain.to_dict("list") == {"material": ["m1", "m2", "m2"], "factor": ["a", "b", "a"],
                                      "lower": [0.0, 2.0, 3.0], "upper": [1.0, 4.0, 5.0]}
    assert list(runs.columns) == ["material", "proposal", "a", "b", "purpose", "predicted_y", "predicted_w"]
    assert runs["a"].tolist() == [0.1, 0.2, 3.5] and runs["proposal"].tolist() == [1, 2, 1]
    assert np.isnan(runs["b"].iloc[0]) and runs["b"].iloc[2] == 2.5
    assert np.isnan(runs["predicted_w"].iloc[0]) and runs["predicted_w"].iloc[2] == 7.0
    assert reasons == {"m1": "r1", "m2": "r2"}
    domain, runs, reasons = tabulate_waves(specs, {})
    assert list(domain.columns) == ["material", "factor", "lower", "upper"] and not len(domain)
    assert list(runs.columns) == ["material", "proposal", "a", "b", "purpose"] and not len(runs) and reasons == {}


@pytest.mark.parametrize("named, expected", [(None, "b"), ("", "b"), ("c", "c"), ("a", "a")])
def test_a_named_refocus_scenario_is_used_and_otherwise_the_most_observables_then_the_smallest_tolerance(named,
                                                                                                     expected):
    scenarios = [SimpleNamespace(name="a", observables=["y"], tolerance=0.01),
                 SimpleNamespace(name="c", observables=["y", "z"], tolerance=0.1),
                 SimpleNamespace(name="b", observables=["z", "y"], tolerance=0.05)]
    spec = SimpleNamespace(scenarios=scenarios, next_runs=SimpleNamespace(scenario=named))
    assert refocus_scenario(spec) == expected
    assert refocus_scenario(SimpleNamespace(scenarios=scenarios, next_runs=None)) == "b"

"""The runs a wave owes, every output against computations written here over generated inputs: how many
coefficients of a box's quadratic the earlier runs leave undetermined (generic points, replicates of a few points,
points on a line: the rank known in closed form), how many design runs a wave keeps against the criticism's runs
(1-4 factors, boxes away from the origin), the box's support share, the criticism's runs kept in the next box
(clamped onto a bound within the rounding, counted out beyond it, linear and log factors), the alias sets named by
missing-term findings, the reason's clause for the criticism's runs and the D-optimal augmentation's determinant
against every candidate tried by brute force."""

from __future__ import annotations

import json
from itertools import product

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid import run_purposes
from demid.io import as_stored
from demid.sampling import Domain
from demid.wave_runs import (aliased_findings, box_support_count, candidate_points, criticism_runs_in_box,
                             d_optimal_augment, deciding_reason, deciding_runs, design_count, full_rank)

_FAST = settings(max_examples=25, deadline=None, derandomize=True)


def _coefficients(k: int) -> int:
    return (k + 1) * (k + 2) // 2


def _quadratic_rows(x: np.ndarray) -> np.ndarray:
    k = x.shape[1]
    cols = [np.ones(len(x))] + [x[:, i] for i in range(k)] + [x[:, i] * x[:, j] for i in range(k) for j in range(i, k)]
    return np.column_stack(cols)


def _points(kind: str, m: int, k: int, rng) -> tuple[np.ndarray, int]:
    """Coded points and their quadratic's rank, known without demid: m generic points have rank min(m, p);
    replicates of m generic points the same; m points on a line through the centre rank min(m, 3)."""
    p = _coefficients(k)
    if kind == "generic":
        return rng.uniform(-1, 1, (m, k)), min(m, p)
    if kind == "replicated":
        base = rng.uniform(-1, 1, (m, k))
        return np.vstack([base, base[: max(1, m // 2)]]), min(m, p)
    direction = rng.normal(size=k)
    t = rng.uniform(-0.5, 0.5, m)
    return t[:, None] * direction / np.abs(direction).max(), min(m, 3)


@_FAST
@given(k=st.integers(1, 4), m=st.integers(0, 17), kind=st.sampled_from(["generic", "replicated", "line"]),
       seed=st.integers(0, 10_000), count=st.integers(1, 20), deciding=st.integers(0, 25))
def test_a_wave_keeps_the_design_runs_its_boxs_quadratic_is_short_of(k, m, kind, seed, count, deciding):
    rng = np.random.default_rng(seed)
    coded, rank = _points(kind, m, k, rng)
    if m:
        assert np.linalg.matrix_rank(_quadratic_rows(coded)) == rank  # the closed form, checked by numpy
        assert full_rank(coded, k) == _coefficients(k) - rank
    lo = rng.uniform(-100.0, 100.0, k)
    hi = lo + rng.uniform(0.01, 50.0, k)
    earlier = (lo + hi) / 2 + coded * (hi - lo) / 2 if m else np.empty((0, k))
    short = _coefficients(k) - rank if m else _coefficients(k)
    assert design_count(count, deciding, earlier, lo, hi) == max(count - deciding, min(short, count))


@pytest.mark.parametrize("count, default, third", [(0, 0, 0), (1, 0, 0), (2, 0, 1), (3, 1, 1), (4, 1, 1), (5, 1, 2),
                                                   (6, 2, 2), (9, 2, 3), (10, 2, 3), (14, 4, 5), (30, 8, 10)])
def test_the_box_support_share_is_a_quarter_rounded_half_to_even(count, default, third):
    assert box_support_count(count) == default
    assert box_support_count(count, 1 / 3) == third
    assert box_support_count(count, 0.0) == 0 and box_support_count(count, 1.0) == count


@pytest.mark.parametrize("k, levels", [(1, 5), (2, 5), (3, 5), (4, 3), (5, 3)])
def test_the_boxs_grid_is_every_combination_of_its_levels(k, levels):
    grid = candidate_points(k)
    values = np.linspace(-1.0, 1.0, levels)
    assert grid.shape == (levels ** k, k)
    assert sorted(map(tuple, grid)) == sorted(product(values, repeat=k))


@_FAST
@given(k=st.integers(1, 3), log_mask=st.integers(0, 7), seed=st.integers(0, 10_000), n=st.integers(1, 8))
def test_criticism_runs_within_the_rounding_are_put_on_the_bound_and_the_others_counted_out(k, log_mask, seed, n):
    rng = np.random.default_rng(seed)
    log = tuple(bool(log_mask >> i & 1) for i in range(k))
    lower = rng.uniform(-2.0, 1.0, k)
    upper = lower + rng.uniform(1.0, 3.0, k)
    factors = [f"f{i}" for i in range(k)]
    domain = Domain(tuple(factors), tuple(10 ** a if lg else a for a, lg in zip(lower, log)),
                    tuple(10 ** b if lg else b for b, lg in zip(upper, log)), log)
    width = upper - lower
    lo = lower + rng.uniform(0.1, 0.3, k) * width
    hi = upper - rng.uniform(0.1, 0.3, k) * width
    # per run and factor: inside, just outside (within a thousandth of the range), or well outside
    where = rng.integers(0, 5, (n, k))
    offsets = {0: lambda i: lo[i] + rng.uniform(0, 1) * (hi[i] - lo[i]), 1: lambda i: lo[i] - 0.0009 * width[i],
               2: lambda i: hi[i] + 0.0009 * width[i], 3: lambda i: lo[i] - 0.0011 * width[i],
               4: lambda i: hi[i] + 0.0011 * width[i]}
    search = np.array([[offsets[int(where[r, i])](i) for i in range(k)] for r in range(n)])
    actual = np.where(np.array(log), 10 ** search, search)
    runs = [{**{f: float(actual[r, i]) for i, f in enumerate(factors)}, "response": f"y{r}", "purpose": "p"}
            for r in range(n)]
    kept, left_out = criticism_runs_in_box(runs, factors, domain, lo, hi)
    usable = [r for r in range(n) if np.all(where[r] <= 2)]
    assert left_out == n - len(usable)
    assert [run["response"] for run in kept] == [f"y{r}" for r in usable]
    for run, r in zip(kept, usable):
        for i, f in enumerate(factors):
            bound = {1: lo[i], 2: hi[i]}.get(int(where[r, i]))
            expected = actual[r, i] if bound is None else (10 ** bound if log[i] else bound)
            assert run[f] == pytest.approx(expected, rel=1e-12, abs=1e-12)
        assert run["purpose"] == "p"
    assert criticism_runs_in_box([], factors, domain, lo, hi) == ([], 0)


def test_a_criticism_run_outside_by_exactly_the_rounding_is_kept_on_the_bound_and_one_beyond_is_counted_out():
    """'No more than the rounding' outside includes exactly the rounding: a thousandth of the range [0, 1000] is
    exactly 1, so -1 and 1001 are on the bounds 0 and 1000, and the next floats beyond are left out."""
    domain = Domain(("a", "b"), (0.0, 0.0), (1000.0, 1000.0))
    lo, hi = np.array([0.0, 200.0]), np.array([500.0, 1000.0])
    runs = [{"a": -1.0, "b": 300.0, "response": "y0"}, {"a": 250.0, "b": 1001.0, "response": "y1"},
            {"a": float(np.nextafter(-1.0, -2.0)), "b": 300.0, "response": "y2"},
            {"a": 250.0, "b": float(np.nextafter(1001.0, 1002.0)), "response": "y3"}]
    kept, left_out = criticism_runs_in_box(runs, ["a", "b"], domain, lo, hi)
    assert kept == [{"a": 0.0, "b": 300.0, "response": "y0"}, {"a": 250.0, "b": 1000.0, "response": "y1"}]
    assert left_out == 2


def test_a_criticism_run_exactly_on_a_log_factors_box_bound_keeps_its_written_value():
    """A run on the box's bound is inside it: its value is the one the criticism wrote, not the bound raised back
    from log10 units (10 ** log10(2e6) is not 2e6 in floating point)."""
    domain = Domain(("k",), (2e6,), (5e7,), (True,))
    lo, hi = np.log10([2e6]), np.log10([3e6])
    assert 10 ** lo[0] != 2e6 and 10 ** hi[0] != 3e6
    runs = [{"k": 2e6, "response": "y0"}, {"k": 3e6, "response": "y1"}]
    kept, left_out = criticism_runs_in_box(runs, ["k"], domain, lo, hi)
    assert kept == runs and left_out == 0


def test_alias_sets_are_read_from_missing_term_findings_with_the_responses_naming_them():
    findings = pd.DataFrame({
        "response": ["y1", "y2", "y3", "y4", "y5"],
        "cause": ["missing_term", "missing_term", "outlier", "missing_term", "missing_term"],
        "aliases": ["a^3;a:b^2", "a^3;a:b^2", "a^3;b^3", "b^3", "a^2:b;;b^3"]})
    assert aliased_findings(findings, ["a", "b"]) == [(((3, 0), (1, 2)), ["y1", "y2"]), (((2, 1), (0, 3)), ["y5"])]
    assert aliased_findings(None, ["a"]) == [] and aliased_findings(findings.drop(columns="cause"), ["a", "b"]) == []
    assert aliased_findings(findings.iloc[:0], ["a", "b"]) == []


@pytest.mark.parametrize("decide, confirm", [(0, 0), (1, 0), (0, 2), (3, 1), (2, 4)])
def test_the_reason_counts_the_criticisms_runs_by_purpose_with_their_responses_in_order(decide, confirm):
    runs = ([{"response": f"y{i % 2}", "purpose": run_purposes.DECIDE} for i in range(decide)]
            + [{"response": f"z{2 - i % 3}", "purpose": run_purposes.CONFIRM} for i in range(confirm)])
    text = deciding_reason(runs[::-1] if decide and confirm else runs)
    parts = []
    if decide:
        names = ", ".join(dict.fromkeys(f"y{i % 2}" for i in (range(decide - 1, -1, -1) if confirm else range(decide))))
        parts.append(f"{decide} run(s) to decide between causes the criticism cannot tell apart ({names})")
    if confirm:
        seq = range(confirm - 1, -1, -1) if decide else range(confirm)
        names = ", ".join(dict.fromkeys(f"z{2 - i % 3}" for i in seq))
        parts.append(f"{confirm} run(s) to confirm or correct a cause the criticism named ({names})")
    assert text == ("; first " + ", then ".join(parts) if parts else "")


def test_a_findings_table_without_runs_asks_for_none():
    assert deciding_runs(None, ["a"]) == [] and deciding_runs(pd.DataFrame({"response": ["y"]}), ["a"]) == []
    frame = pd.DataFrame({"response": ["y"], "discriminating_runs": [""]})
    assert deciding_runs(frame, ["a"]) == []


def test_rows_without_runs_in_a_stored_findings_table_are_skipped():
    """The criticism writes its runs on the one row they serve; the other rows of the stored findings (read back
    from parquet) have no value there, and the next wave reads the runs of that one row only."""
    rows = [{"response": "y", "cause": "drift", "discriminating_runs": json.dumps(
                [{"a": 0.5, "purpose": run_purposes.CONFIRM}, {"a": -1.0, "purpose": run_purposes.DECIDE}])},
            {"response": "y", "cause": "outlier"}, {"response": "z", "cause": "unexplained"}]
    stored = as_stored(pd.DataFrame(rows))
    assert deciding_runs(stored, ["a"]) == [{"a": -1.0, "response": "y", "purpose": run_purposes.DECIDE},
                                            {"a": 0.5, "response": "y", "purpose": run_purposes.CONFIRM}]


@given(k=st.integers(1, 2), earlier=st.integers(0, 8), count=st.integers(1, 4), seed=st.integers(0, 10_000))
@settings(max_examples=10, deadline=None, derandomize=True)
def test_each_augmenting_run_is_a_candidate_of_largest_determinant_gain(k, earlier, count, seed):
    rng = np.random.default_rng(seed)
    existing = rng.uniform(-1, 1, (earlier, k))
    cands = candidate_points(k)
    chosen = d_optimal_augment(existing, count, k)
    assert chosen.shape == (count, k)
    design = list(existing)
    p = _coefficients(k)
    for point in chosen:
        assert any(np.array_equal(point, c) for c in cands)
        info = _quadratic_rows(np.array(design).reshape(-1, k)).T @ _quadratic_rows(np.array(design).reshape(-1, k))
        info = info + 1e-9 * np.eye(p)
        dets = [np.linalg.slogdet(info + np.outer(f, f))[1] for f in _quadratic_rows(cands)]
        unused = [d for c, d in zip(cands, dets) if not any(np.array_equal(c, q) for q in design)]
        best = max(unused) if unused else max(dets)
        gained = np.linalg.slogdet(info + np.outer(*[_quadratic_rows(point[None, :])[0]] * 2))[1]
        assert gained >= best - 1e-6
        design.append(point)


@pytest.mark.parametrize("n, digits", [(20, 8), (60, 10), (200, 10)])
def test_runs_on_a_conic_as_a_sheet_prints_them_leave_its_quadratic_one_coefficient_short(n, digits):
    """Runs on a circle written to 8-10 significant digits (as the run sheets write them) lie off it only by the
    printing: their quadratic is determined by round-off alone, so they count as one coefficient short and a wave
    keeps a design run for it; moved off the circle by a thousandth they determine it."""
    rng = np.random.default_rng(n)
    t = rng.uniform(0.0, 2 * np.pi, n)
    circle = np.column_stack([0.2 + 0.6 * np.cos(t), -0.1 + 0.6 * np.sin(t)])
    printed = np.vectorize(lambda v: float(f"{v:.{digits}g}"))(circle)
    assert full_rank(printed, 2) == 1
    lo, hi = np.array([-1.0, -1.0]), np.array([1.0, 1.0])
    assert design_count(9, 9, printed, lo, hi) == 1
    off = circle * (1.0 + 1e-3 * rng.standard_normal((n, 1)))
    assert full_rank(off, 2) == 0 and design_count(9, 9, off, lo, hi) == 0


@pytest.mark.parametrize("off, short", [(0.0, 1), (3e-8, 1), (1e-7, 0), (1e-6, 0)])
def test_the_box_codes_earlier_runs_to_its_own_minus_one_to_one_before_judging_them(off, short):
    """Earlier runs near a circle of radius 0.6 in the box's coded units ([-1, 1] over the box), off it by ``off``
    of the half-width: the wave keeps a design run for the quadratic's missing coefficient exactly when the runs in
    those units are one short -- on the circle, and 3e-8 off (the smallest singular value of their quadratic's rows
    0.7 of the rank tolerance, 1e-8 per run), they are; 1e-7 off (over twice the tolerance) they determine it."""
    lo, hi = np.array([50.0, 100.0]), np.array([70.0, 140.0])
    n = 12
    t = 2 * np.pi * np.arange(n) / n
    r = 0.6 + off * (-1.0) ** np.arange(n)
    coded = np.column_stack([r * np.cos(t), r * np.sin(t)])
    actual = (lo + hi) / 2 + coded * (hi - lo) / 2
    ratio = np.linalg.svd(_quadratic_rows(coded), compute_uv=False).min() / (1e-8 * n)
    assert (ratio <= 1) == bool(short) and not 0.8 < ratio < 1.25
    assert full_rank(coded, 2) == short
    assert design_count(5, 5, actual, lo, hi) == short

"""A proposed run as the findings print it (criticism.models.Data.point_dict), over 2-4 factors of ranges from
1e-3 to 1e4 wide, signed or starting at exactly 0, linear or log: a linear factor to the nearest multiple of
10^(floor(log10(range)) - 3) (four digits of its design range), then to 4 significant digits; a log factor to 4
significant digits of its own; a point of a next wave's box grid to 6 significant digits, a value within 1e-9 of
the range from 0 printed as 0; never -0.  The ranges are read off the table here, not from the coding."""
from __future__ import annotations

import dataclasses
import math

import numpy as np
import pandas as pd
from hypothesis import given, settings, strategies as st

from demid.criticism.level1 import prepare_data


def _expected(v: float, lo: float, hi: float, log: bool, on_grid: bool) -> float:
    if on_grid:
        return float(f"{0.0 if abs(v) < 1e-9 * (hi - lo) else v:.6g}") + 0.0
    if log:
        return float(f"{v:.4g}") + 0.0
    step = 10.0 ** (math.floor(math.log10(hi - lo)) - 3)
    return float(f"{round(v / step) * step:.4g}") + 0.0


@settings(max_examples=12, deadline=None, derandomize=True)
@given(k=st.integers(2, 4), seed=st.integers(0, 10 ** 6), on_grid=st.booleans())
def test_a_proposed_runs_printed_values(k, seed, on_grid):
    rng = np.random.default_rng(seed)
    n = 3 * (k + 1) * (k + 2) // 2
    columns, ranges, logs = {}, [], []
    for j in range(k):
        log = bool(rng.random() < 0.3)
        if log:
            lo = 10.0 ** rng.uniform(-3, 1)
            hi = lo * 10.0 ** rng.uniform(0.5, 3)
        else:
            width = 10.0 ** rng.uniform(-3, 4)
            lo = 0.0 if rng.random() < 0.3 else float(rng.choice([-1.0, 1.0])) * 10.0 ** rng.uniform(-3, 4)
            hi = lo + width
        inner = np.exp(rng.uniform(np.log(lo), np.log(hi), n - 2)) if log else rng.uniform(lo, hi, n - 2)
        columns[f"f{j}"] = np.concatenate([[lo, hi], inner])
        ranges.append((lo, hi))
        logs.append(log)
    factors = list(columns)
    x = np.column_stack(list(columns.values()))
    table = pd.DataFrame({"run": np.arange(1, n + 1), **columns, "y": rng.standard_normal(n)})
    log_factors = tuple(f for f, log in zip(factors, logs) if log)
    data, _ = prepare_data(table, factors, "y", 1.0, log_factors)
    if on_grid:
        data = dataclasses.replace(data, run_candidates=np.zeros((1, k)))
    points = np.vstack([-np.ones(k), np.ones(k), rng.uniform(-1.0, 1.0, (4, k))])
    for p in points:
        got = data.point_dict(p)
        v = data.to_actual(p)[0]
        assert list(got) == factors
        for j, f in enumerate(factors):
            lo, hi = ranges[j]
            want = _expected(float(v[j]), lo, hi, logs[j], on_grid)
            assert got[f] == want and math.copysign(1.0, got[f]) == math.copysign(1.0, want), (f, got[f], want)
            if p[j] == -1 and lo == 0.0:
                assert got[f] == 0.0 and math.copysign(1.0, got[f]) == 1.0  # the lower bound 0 reads 0
    assert np.allclose(x.min(axis=0), [r[0] for r in ranges]) and np.allclose(x.max(axis=0), [r[1] for r in ranges])


def test_on_the_grid_a_value_within_1e_9_of_the_range_from_0_reads_0():
    """A factor 0..10^4 wide: 5e-8 from its lower bound 0 is round-off of the coding's round trip (below 1e-9 of
    the range) and reads 0; 5 reads 5."""
    n = 12
    rng = np.random.default_rng(0)
    table = pd.DataFrame({"run": np.arange(1, n + 1), "a": np.r_[0.0, 1e4, rng.uniform(0, 1e4, n - 2)],
                          "b": np.r_[1.0, 2.0, rng.uniform(1, 2, n - 2)], "y": rng.standard_normal(n)})
    data, _ = prepare_data(table, ["a", "b"], "y", 1.0, ())
    data = dataclasses.replace(data, run_candidates=np.zeros((1, 2)))
    for a, printed in ((5e-8, 0.0), (5.0, 5.0)):
        got = data.point_dict(np.array([-1.0 + 2 * a / 1e4, 0.0]))
        assert got["a"] == printed and got["b"] == 1.5

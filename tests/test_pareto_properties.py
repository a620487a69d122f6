"""The Pareto analysis's whole output (front rows with their factor values, error and objective; the per-factor
intervals under the error cap; the one-CSV frame) over generated grids, against a brute-force front written here:
1-3 factors, targets of either sign, objectives of either sign with ties, and an error cap equal to one of the
grid's errors (the boundary of "below the cap")."""

from __future__ import annotations

import numpy as np
import pandas as pd
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.pareto import pareto_analysis

SETTINGS = settings(max_examples=12, deadline=None, derandomize=True)


def _brute_front(error: np.ndarray, objective: np.ndarray) -> list[int]:
    """Indices not dominated by any other point (no worse in both, better in one); of exact duplicates the first;
    sorted by error, then objective, then index."""
    kept = []
    for i in range(len(error)):
        dominated = any((error[j] <= error[i] and objective[j] <= objective[i]
                         and (error[j] < error[i] or objective[j] < objective[i]))
                        or (j < i and error[j] == error[i] and objective[j] == objective[i])
                        for j in range(len(error)) if j != i)
        if not dominated:
            kept.append(i)
    return sorted(kept, key=lambda i: (error[i], objective[i], i))


@given(k=st.integers(1, 3), n=st.integers(2, 40), seed=st.integers(0, 10_000),
       target=st.sampled_from([-2.5, -0.4, 0.4, 3.0]), cap_rank=st.integers(0, 39))
@SETTINGS
def test_whole_pareto_output_matches_a_brute_force_front(k, n, seed, target, cap_rank):
    rng = np.random.default_rng(seed)
    factors = [f"x{i}" for i in range(k)]
    grid = pd.DataFrame(rng.integers(-3, 4, size=(n, k)).astype(float) * 0.5, columns=factors)
    # responses on a coarse lattice so that errors and objectives tie; the objective takes either sign
    grid["y"] = target + np.abs(target) * rng.integers(-4, 5, size=n) / 4.0
    grid["z"] = rng.integers(-5, 6, size=n).astype(float) * 1.5
    error = np.abs(grid["y"].to_numpy() - target) / abs(target)
    objective = grid["z"].to_numpy()
    max_error = float(np.sort(error)[min(cap_rank, n - 1)])

    result = pareto_analysis(grid, factors, "y", target, "z", max_error)

    expected = _brute_front(error, objective)
    front = result.front
    assert list(front.columns) == [*factors, "error", "objective"]
    np.testing.assert_array_equal(front[factors].to_numpy(), grid[factors].to_numpy()[expected])
    np.testing.assert_allclose(front["error"].to_numpy(), error[expected], rtol=1e-12, atol=0)
    np.testing.assert_array_equal(front["objective"].to_numpy(), objective[expected])
    assert (result.factors, result.error_of, result.minimise) == (factors, "y", "z")
    assert result.max_error == max_error and type(result.max_error) is float

    below = [i for i in expected if error[i] < max_error]  # strictly below the cap
    intervals = result.intervals
    assert list(intervals.columns) == ["factor", "lower", "upper", "n_points"]
    assert list(intervals["factor"]) == factors
    assert list(intervals["n_points"]) == [len(below)] * k
    for row, f in zip(intervals.itertuples(), factors):
        values = grid[f].to_numpy()[below]
        if below:
            assert (row.lower, row.upper) == (values.min(), values.max())
        else:
            assert np.isnan(row.lower) and np.isnan(row.upper)

    table = result.to_frame()
    # the CSV's columns: the row kind first, then the front's, then the intervals'
    assert list(table.columns) == ["kind", *factors, "error", "objective", "factor", "lower", "upper", "n_points"]
    assert list(table["kind"]) == ["front"] * len(expected) + ["interval"] * k
    pd.testing.assert_frame_equal(table.iloc[len(expected):][["factor", "lower", "upper", "n_points"]]
                                  .reset_index(drop=True), intervals, check_dtype=False)
    pd.testing.assert_frame_equal(table.iloc[:len(expected)].drop(columns="kind").dropna(axis=1, how="all")
                                  .reset_index(drop=True), front, check_dtype=False)

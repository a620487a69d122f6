"""What level 1 (criticism.level1.criticize) gives when called as the command line and a library user call it, with
its defaults: family-wise p-values from 1999 null draws (each a whole number of 1/2000ths, the observed table counted
with the draws), the same numbers as an explicit seed 0 (a report's p-values do not change between runs), and a
table typed by hand, not simulated: a run named an outlier gets a run that would confirm it, not replicates of it.
An 11-run three-level factorial with two centre runs, one of them 30 standard deviations off."""
from __future__ import annotations

from functools import lru_cache

import numpy as np
import pandas as pd

from demid.criticism.level1 import criticize


@lru_cache(maxsize=1)
def _table() -> pd.DataFrame:
    rng = np.random.default_rng(0)
    points = [(a, b) for a in (-1.0, 0.0, 1.0) for b in (-1.0, 0.0, 1.0)] + [(0.0, 0.0)] * 2
    a, b = np.array(points).T
    y = 5.0 + a - 2.0 * b + 0.5 * a * b + rng.normal(scale=0.1, size=len(a))
    y[4] += 3.0  # the first centre run
    return pd.DataFrame({"run": rng.permutation(len(a)) + 1, "a": a, "b": b, "y": y})


@lru_cache(maxsize=1)
def _default():
    return criticize(_table(), ["a", "b"], "y")


def _p_values(result) -> list[float]:
    return [e["p_family"] for e in result.catalogue] + [f.p_value for f in result.findings]


def test_family_p_values_are_counts_over_1999_null_draws_and_the_observed_table():
    counts = np.array(_p_values(_default())) * 2000
    np.testing.assert_allclose(counts, np.round(counts), atol=1e-6)
    assert np.all(counts >= 1)


def test_a_hand_typed_tables_outlier_gets_a_confirming_run_not_replicates():
    result = _default()
    assert [f.cause for f in result.findings] == ["outlier"]
    assert result.discriminating_runs
    assert not any("replicate_of" in r for r in result.discriminating_runs)


def test_without_a_seed_the_numbers_are_those_of_seed_0():
    seeded = criticize(_table(), ["a", "b"], "y", seed=0)
    assert _p_values(seeded) == _p_values(_default())
    assert seeded.summary == _default().summary

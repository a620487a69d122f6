"""The transcription check's refit engine on a large table: pure error without the n x n replicate-group
projection, and the same numbers as that projection."""

from __future__ import annotations

import tracemalloc

import numpy as np
import pytest

from demid.design import Coding, quadratic_terms, replicate_groups
from demid.transcription.engine import DesignFit, evaluate_designs


def _design(n: int, seed: int = 0):
    """n runs of two factors on a 40 x 40 grid (so some replicate), and a response."""
    rng = np.random.default_rng(seed)
    coded = np.round(rng.integers(0, 40, (n, 2)) / 19.5 - 1, 6)
    y = 5 + coded[:, 0] - coded[:, 1] ** 2 + 0.1 * rng.standard_normal(n)
    return coded, y


def _pure_error_by_groups(coded, y):
    """Independent: squared deviations from each replicate group's mean, group by group."""
    groups = replicate_groups(coded)
    return sum(float(np.sum((y[groups == g] - y[groups == g].mean()) ** 2)) for g in np.unique(groups))


def test_pure_error_of_5000_runs_without_an_n_by_n_matrix():
    n = 5000
    coded, y = _design(n)
    coding = Coding(["a", "b"], np.zeros(2), np.ones(2))
    tracemalloc.start()
    try:
        fit = DesignFit(coded, quadratic_terms(2), coding, need_actual=False)
        out = fit.evaluate(np.column_stack([y, y[::-1]]), {})
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < 0.25 * n * n * 8, f"peak {peak / 1e6:.0f} MB: an n x n float array is {n * n * 8 / 1e6:.0f} MB"
    assert out["ss_pure_error"][0] == pytest.approx(_pure_error_by_groups(coded, y), rel=1e-10)
    assert out["ss_pure_error"][1] == pytest.approx(_pure_error_by_groups(coded, y[::-1]), rel=1e-10)


def test_repaired_designs_of_many_runs_have_the_pure_error_of_their_groups():
    coded, y = _design(600, seed=2)
    moved = coded.copy()
    moved[7, 0] = coded[8, 0]  # one cell repaired onto another run's level: the groups change
    out = evaluate_designs(np.stack([coded, moved]), y, quadratic_terms(2), None, {})
    for i, c in enumerate((coded, moved)):
        assert out["ss_pure_error"][i] == pytest.approx(_pure_error_by_groups(c, y), rel=1e-10)
        assert out["_df_pe"][i] == len(y) - len(np.unique(replicate_groups(c)))

"""The run column is read for a sort by a response whatever its numbers' span: labels from 1.0 to 2.0 in
quarter steps (a span of exactly 1) sorted by a response are found sorted (Spearman 1, scipy's), a constant
run column never."""
from __future__ import annotations

import numpy as np
import pytest
from scipy import stats

from demid.criticism.run_order import assess_run_order


@pytest.mark.parametrize("start, step", [(1.0, 0.25), (0.0, 0.2), (5.0, 0.5)])
def test_run_labels_of_any_span_sorted_by_a_response_are_found(start, step):
    runs = start + step * np.arange(6)
    y = np.array([2.0, 2.5, 3.1, 4.0, 4.2, 6.0])
    coded = np.random.default_rng(1).uniform(-1, 1, (6, 2))
    out = assess_run_order(runs, coded, {"y": y})
    rho = stats.spearmanr(runs, y).statistic
    assert (out.drift_tested, out.reason, out.response) == (False, "sorted_by_response", "y")
    assert out.correlation == pytest.approx(rho) and rho == pytest.approx(1.0)


def test_a_constant_run_column_follows_no_response():
    out = assess_run_order(np.full(6, 3.0), np.random.default_rng(1).uniform(-1, 1, (6, 2)),
                           {"y": np.arange(6.0)})
    assert out.reason != "sorted_by_response" and out.response is None

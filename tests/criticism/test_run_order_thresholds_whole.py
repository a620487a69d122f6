"""The run order's two thresholds met exactly (criticism.run_order): a run column whose Spearman correlation with a
response is exactly 0.9 (11 runs, sum of squared rank differences 22 = n(n²-1)/60), either sign, is sorted by it;
one whose rank correlation with the design's standard order is exactly 0.95 (a three-factor CCD with one centre
run, 15 runs, sum of squared rank differences 28 = n(n²-1)/120) is that standard order; one more swap of
neighbours is neither.  Each correlation is computed here with scipy and the numbers the message quotes read back."""

from __future__ import annotations

import re

import numpy as np
import pytest
from scipy import stats

from demid.criticism.run_order import (SORTED_CORRELATION, STANDARD_ORDER_CORRELATION, _standard_keys,
                                       assess_run_order, standard_order_correlation)
from demid.design import ccd_points

#: Ranks 0..10 at Spearman 0.9 with 0..10 (exactly, in floating point too).
_AT_09 = np.array([1, 3, 0, 4, 2, 7, 5, 6, 9, 8, 10])
#: Ranks 0..14 at 0.95 with 0..14.
_AT_095 = np.array([0, 1, 2, 3, 4, 5, 6, 8, 10, 7, 12, 9, 13, 14, 11])


@pytest.mark.parametrize("sign", [1.0, -1.0])
@pytest.mark.parametrize("start,step", [(1, 1), (101, 3)])
def test_a_run_column_at_exactly_the_sorted_correlation_follows_the_response(sign, start, step):
    runs = start + step * np.arange(11.0)
    y = sign * (2.5 + 0.75 * _AT_09)
    rho = float(stats.spearmanr(runs, y)[0])
    assert abs(rho) == SORTED_CORRELATION
    coded = np.random.default_rng(0).uniform(-1, 1, (11, 2))
    out = assess_run_order(runs, coded, {"other": np.full(11, 4.0), "y": y})
    assert (out.drift_tested, out.reason, out.response, out.correlation) == (False, "sorted_by_response", "y", rho)
    quoted = re.search(r"Spearman rank correlation of run and y ([+-][\d.]+)\)", out.message)
    assert float(quoted.group(1)) == pytest.approx(rho, abs=0.005)
    # two more neighbours swapped: 0.873, not sorted
    y2 = y.copy()
    y2[[9, 10]] = y2[[10, 9]]
    assert abs(float(stats.spearmanr(runs, y2)[0])) < SORTED_CORRELATION
    assert assess_run_order(runs, coded, {"y": y2}).reason != "sorted_by_response"


def _ccd_runs(ranks: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """A three-factor CCD with one centre run and run numbers at ``ranks`` of its standard order (factorial
    points in Yates order, then axial, then the centre)."""
    coded = ccd_points(3, 1.68179, 1)
    key = next(_standard_keys(np.round(coded, 6)))
    standard = np.lexsort(key.T[::-1])  # rows in standard order
    runs = np.empty(len(coded))
    runs[standard] = ranks + 1.0
    return coded, runs


def test_a_run_column_at_exactly_the_standard_order_correlation_is_that_order():
    coded, runs = _ccd_runs(_AT_095)
    in_order = np.empty(len(coded))
    in_order[np.lexsort(next(_standard_keys(np.round(coded, 6))).T[::-1])] = np.arange(len(coded))
    assert float(stats.spearmanr(runs, in_order)[0]) == pytest.approx(STANDARD_ORDER_CORRELATION, abs=1e-12)
    rho = standard_order_correlation(runs, coded)
    assert rho == STANDARD_ORDER_CORRELATION
    out = assess_run_order(runs, coded, {})
    assert (out.drift_tested, out.reason, out.correlation) == (False, "standard_order", rho)
    assert "(rank correlation 0.95: " in out.message
    assert out.to_json()["rank_correlation"] == 0.95
    # one more pair of neighbours swapped: below the threshold, the order is believed
    further = _AT_095.copy()
    further[[0, 1]] = further[[1, 0]]
    coded, runs = _ccd_runs(further)
    assert standard_order_correlation(runs, coded) < STANDARD_ORDER_CORRELATION
    out = assess_run_order(runs, coded, {})
    assert (out.drift_tested, out.reason, out.message) == (True, "", "")

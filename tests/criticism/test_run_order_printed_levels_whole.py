"""A table in standard order whose levels are printed to 7 significant digits, so that replicates of a point
differ in the seventh decimal of their coded values (0.9999997 and 1.0000003): they are one point, listed in run
order, and the run column reproduces the standard order exactly (rank correlation 1, as scipy computes it
against the standard order written out), 2-3 factors, each point twice."""
from __future__ import annotations

import itertools

import numpy as np
import pytest
from scipy import stats

from demid.criticism.run_order import assess_run_order, standard_order_correlation


@pytest.mark.parametrize("k", [2, 3])
def test_replicates_differing_in_the_seventh_decimal_are_one_point(k):
    # Yates order: first factor varying fastest; each point twice, one after the other
    points = np.array([p[::-1] for p in itertools.product((-1.0, 1.0), repeat=k)])
    coded = np.repeat(points, 2, axis=0)
    coded[0::2] += 3e-7  # the first replicate printed a little high, the second a little low
    coded[1::2] -= 3e-7
    runs = np.arange(1.0, len(coded) + 1)
    standard_position = np.arange(len(coded))  # the table is written in that order
    assert float(stats.spearmanr(runs, standard_position)[0]) == 1.0
    assert standard_order_correlation(runs, coded) == pytest.approx(1.0, abs=1e-12)
    out = assess_run_order(runs, coded, {})
    assert (out.drift_tested, out.reason) == (False, "standard_order")
    assert out.to_json()["rank_correlation"] == 1.0
    assert "(rank correlation 1.00: " in out.message

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


@pytest.mark.parametrize("pair", [(0.100001, 0.100004), (-0.500004, -0.500002), (0.999991, 0.999994)])
def test_levels_differing_in_the_sixth_decimal_are_distinct_points(pair):
    """Two levels 2e-6 to 3e-6 apart in coded units are two points: listed against their order, the run column
    is no standard order (rank correlation that of scipy against the order of the values, 0.8), and drift is
    tested; listed in their order, it is the standard order."""
    low, high = pair
    against = np.array([[-1.0], [high], [low], [1.0]])
    runs = np.arange(1.0, 5.0)
    by_value = stats.rankdata(against[:, 0])
    expected = float(stats.spearmanr(runs, by_value)[0])
    assert expected == pytest.approx(0.8, abs=1e-12)
    assert standard_order_correlation(runs, against) == pytest.approx(expected, abs=1e-12)
    out = assess_run_order(runs, against, {})
    assert (out.drift_tested, out.reason) == (True, "")
    along = against[[0, 2, 1, 3]]
    assert standard_order_correlation(runs, along) == pytest.approx(1.0, abs=1e-12)
    assert assess_run_order(runs, along, {}).reason == "standard_order"

"""Whether the run column is the performed order (criticism.run_order) at the documented limits: a design of four
runs is read for a standard order and one of three is not; a response is read for the run column's order when four
of its runs are finite and not when three are; of responses the run column follows equally closely the first
listed is named; up to four factors every naming of the factors is tried, beyond four only the table's column
order and its reverse (a five-factor factorial in the Yates order of a shuffled naming is not recognised)."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from demid.criticism.run_order import assess_run_order, standard_order_correlation


def _yates(k: int) -> np.ndarray:
    """The 2^k factorial in Yates order (first factor varying fastest), written out."""
    return np.array([[(-1.0) ** (1 + (i >> j) % 2) for j in range(k)] for i in range(2 ** k)])


def test_a_four_run_design_is_read_for_its_standard_order_and_three_runs_are_not():
    points = _yates(2)
    assert standard_order_correlation(np.arange(1, 5), points) == pytest.approx(1.0)
    out = assess_run_order(np.arange(1, 5), points, {"y": np.array([3.0, 1.0, 4.0, 2.0])})
    assert (out.drift_tested, out.reason) == (False, "standard_order")
    assert standard_order_correlation(np.arange(1, 4), points[:3]) == 0.0
    assert assess_run_order(np.arange(1, 4), points[:3], {"y": np.array([3.0, 1.0, 2.0])}).drift_tested


@pytest.mark.parametrize("finite,named", [(3, False), (4, True), (5, True)])
def test_a_response_is_read_with_four_finite_runs_and_not_with_three(finite, named):
    n = 9
    runs = np.arange(1.0, n + 1)
    y = 2.0 * runs + 1.0
    y[finite:] = np.nan
    coded = np.random.default_rng(3).uniform(-1, 1, (n, 2))  # no standard order
    out = assess_run_order(runs, coded, {"y": y})
    assert (out.reason == "sorted_by_response") == named
    assert out.response == ("y" if named else None)
    if named:
        assert out.correlation == pytest.approx(1.0)


@pytest.mark.parametrize("order", [("up", "down"), ("down", "up"), ("up", "again")])
def test_of_responses_followed_equally_closely_the_first_listed_is_named(order):
    runs = np.arange(1.0, 11.0)
    values = {"up": 5.0 + runs, "down": 40.0 - 3.0 * runs, "again": 0.1 * runs ** 2}
    coded = np.random.default_rng(5).uniform(-1, 1, (10, 2))
    out = assess_run_order(runs, coded, {name: values[name] for name in order})
    assert out.response == order[0]
    assert out.correlation == pytest.approx(1.0 if order[0] != "down" else -1.0)


def test_four_factors_are_named_in_any_order_and_five_only_in_the_columns_order_or_its_reverse():
    runs4 = np.arange(1, 17)
    for perm in itertools.islice(itertools.permutations(range(4)), 0, 24, 5):
        shuffled = np.empty_like(_yates(4))
        shuffled[:, list(perm)] = _yates(4)
        assert standard_order_correlation(runs4, shuffled) == pytest.approx(1.0)
    runs5 = np.arange(1, 33)
    assert standard_order_correlation(runs5, _yates(5)) == pytest.approx(1.0)
    assert standard_order_correlation(runs5, _yates(5)[:, ::-1][::-1]) == pytest.approx(1.0)
    shuffled = _yates(5)[:, [2, 0, 4, 1, 3]]  # the Yates order of another naming of the factors
    assert standard_order_correlation(runs5, shuffled) < 0.95

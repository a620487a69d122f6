"""Known answers for the ranking's reachability test and its advice in words: a closed-form closest approach at
the edge of the tolerance, and hand-made rankings whose sentences follow from their fractions by arithmetic."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from demid.sampling.domain import Domain
from demid.surrogate import Surrogate
from demid.story.measurements import measurement_order
from demid.uncertainty.ranking import reachable_targets

LINE = Domain(("a",), (0.0,), (1.0,))


def _line(response: str) -> Surrogate:
    """y = 1 + a on [0, 1]: its closest approach to a target t > 2 is at a = 1, (t - 2) / t."""
    return Surrogate(response, ["a"], [(0,), (1,)], np.array([1.0, 1.0]), np.eye(2) * 1e-4, 0.01, 5)


@pytest.mark.parametrize("excess, reachable", [(0.0, True), (5e-10, True), (-1e-6, True), (2e-9, False),
                                               (1e-6, False)])
def test_a_target_at_the_edge_of_the_tolerance_is_reachable_within_the_round_off_slack(excess, reachable):
    # the closest approach (t - 2) / t equals tolerance * (1 + excess) for t = 2 / (1 - tolerance (1 + excess));
    # the documented slack is a relative 1e-9 of the tolerance
    tolerance = 0.1
    target = 2.0 / (1.0 - tolerance * (1.0 + excess))
    closest = abs(2.0 - target) / target
    assert closest == pytest.approx(tolerance * (1 + excess), rel=1e-12, abs=0)
    got = reachable_targets({"y": _line("y")}, LINE, ["y"], {"y": target}, tolerance, {"y": 0.0})
    assert got == {"y": reachable}
    # a positive own fraction settles it without a search
    assert reachable_targets({"y": _line("y")}, LINE, ["y"], {"y": 100.0}, tolerance, {"y": 0.3}) == {"y": True}


def _ranking(rows) -> pd.DataFrame:
    return pd.DataFrame(rows, columns=["observables", "information_gain_bits", "feasible_fraction_pct"])


def test_an_added_measurement_that_leaves_the_fraction_is_said_to_leave_it():
    # from a (40 %), adding b keeps 39.99 %: a contraction of 1 - 39.99 / 40 = 2.5e-4, below 5e-4
    ranking = _ranking([("a+b", 3.0, 39.99), ("a", 2.0, 40.0), ("b", 1.0, 60.0)])
    lines = measurement_order(ranking)
    assert lines[0] == ("As a first measurement, a is the most informative: 2.00 bits, admissible fraction 40 % of "
                        "the domain; b would gain 1.00 bits.")
    assert lines[1] == "From a, adding b gains 1.00 bits (2.00 -> 3.00) but leaves the admissible fraction at 40 %."
    # from b (60 %), adding a to 39.99 %: shrinks by 100 (1 - 39.99 / 60) = 33.35 %
    assert lines[2] == ("From b, adding a gains 2.00 bits (1.00 -> 3.00) and shrinks the admissible fraction by "
                        f"{100 * (1 - 39.99 / 60):.1f} % (60 % -> 40 %).")


def test_an_empty_starting_set_is_said_to_be_empty_already():
    ranking = _ranking([("a+b", 3.0, 0.0), ("a", 2.0, 0.0), ("b", 1.0, 10.0)])
    lines = measurement_order(ranking, {"a": "A", "b": "B"})
    assert lines[1] == ("From A, adding B gains 1.00 bits (2.00 -> 3.00) (the admissible set is already empty at "
                        "this tolerance).")
    # the most informative first measurement is also the narrowest: no 'by fraction alone'
    assert lines[0] == ("As a first measurement, A is the most informative: 2.00 bits, admissible fraction 0 % of "
                        "the domain; B would gain 1.00 bits.")

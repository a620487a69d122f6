"""The ranking reuses a stored strict set only where it is exact: a grid set (surrogates that are no polynomial
of the search units, here a factor on a log axis) may lie on another grid, so the ranking recomputes it on its
own grid and every fraction of the table shares that grid; an exact set is the set itself and is reused."""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from demid.sampling import Domain
from demid.sampling.evaluate import evaluate_set
from demid.sampling.grid import admissible_set
from demid.uncertainty.ranking import rank_observable_sets

from .test_uncertainty import linear


@dataclass
class _Posterior:
    information_gain_bits: float
    information_gain_error_bits: float


def _ranking(domain, strict_sets=None):
    y = linear(0.0, [1.0, 0.0])  # y = a: |a - 0.5| <= 0.05 is 10 % of any range of a from 0 to 1
    y.response = "y"
    return rank_observable_sets({"y": y}, domain, ["y"], {"y": 0.5}, {"y": 0.05}, 0.1, 21,
                                posteriors={("y",): _Posterior(1.0, 0.01)}, strict_sets=strict_sets)


def test_a_stored_grid_set_is_recomputed_on_the_rankings_grid():
    log_domain = Domain(("a", "b"), (0.0, 1.0), (1.0, 10.0), (False, True))
    grid = admissible_set({"y": linear(0.0, [1.0, 0.0])}, log_domain, ("y",), {"y": 0.5}, 0.1, 11)
    assert grid.exact is None
    fresh = _ranking(log_domain)
    stored = _ranking(log_domain, {frozenset({"y"}): replace(grid, fraction=0.02)})
    assert stored["feasible_fraction_pct"].iloc[0] == fresh["feasible_fraction_pct"].iloc[0]
    np.testing.assert_allclose(stored["feasible_fraction_pct"].iloc[0], 10.0, rtol=1e-6)


def test_a_stored_exact_set_is_reused():
    square = Domain(("a", "b"), (0.0, 0.0), (1.0, 1.0))
    exact = evaluate_set({"y": linear(0.0, [1.0, 0.0])}, square, ("y",), {"y": 0.5}, 0.1, 21)
    assert exact.exact is not None
    np.testing.assert_allclose(_ranking(square)["feasible_fraction_pct"].iloc[0], 10.0, rtol=1e-9)
    stored = _ranking(square, {frozenset({"y"}): replace(exact, fraction=0.02)})
    assert stored["feasible_fraction_pct"].iloc[0] == 2.0

"""The ranking's feasible fractions are counted on the grid of ``fraction_n`` points per factor when it is given
(the posteriors' ``n`` otherwise): a set that is not exact (a log factor the surrogate reads in actual units) has
the fraction of the admissible set on that grid."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pytest

from demid.sampling.domain import Domain
from demid.sampling.grid import admissible_set
from demid.surrogate import Surrogate
from demid.uncertainty.ranking import rank_observable_sets

DOMAIN = Domain(("a", "b"), (1.0, 0.0), (10.0, 1.0), log=(True, False))
SURROGATE = Surrogate("y", ["a", "b"], [(0, 0), (1, 0), (0, 1)], np.array([0.0, 1.0, 4.0]), np.eye(3) * 1e-6,
                      0.01, 10)


@dataclass
class _Posterior:
    information_gain_bits: float
    information_gain_error_bits: float


@pytest.mark.parametrize("fraction_n", [5, 7])
def test_fractions_are_counted_on_the_fraction_grid(fraction_n):
    frame = rank_observable_sets({"y": SURROGATE}, DOMAIN, ["y"], {"y": 6.0}, {"y": 1.0}, 0.1, 41,
                                 posteriors={("y",): _Posterior(1.0, 0.01)}, fraction_n=fraction_n)
    on_grid = admissible_set({"y": SURROGATE}, DOMAIN, ["y"], {"y": 6.0}, 0.1, fraction_n).fraction
    on_n = admissible_set({"y": SURROGATE}, DOMAIN, ["y"], {"y": 6.0}, 0.1, 41).fraction
    assert abs(on_grid - on_n) > 1e-4  # the two grids tell apart
    assert frame["feasible_fraction_pct"].iloc[0] == pytest.approx(100.0 * on_grid, abs=1e-12)


def test_without_fraction_n_the_posteriors_grid_counts():
    frame = rank_observable_sets({"y": SURROGATE}, DOMAIN, ["y"], {"y": 6.0}, {"y": 1.0}, 0.1, 41,
                                 posteriors={("y",): _Posterior(1.0, 0.01)})
    on_n = admissible_set({"y": SURROGATE}, DOMAIN, ["y"], {"y": 6.0}, 0.1, 41).fraction
    assert frame["feasible_fraction_pct"].iloc[0] == pytest.approx(100.0 * on_n, abs=1e-12)

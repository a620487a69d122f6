"""The plausible-identifiability table's strict columns from a strict set handed in: an exact set is the row as it
is, a grid set on the table's own grid too, a grid set on another grid is computed again on the table's grid (each
handed-in set marked here by a fraction of its own, so the row says which set it shows).  Against the band
|a - 0.5| <= 0.05 of y = a over the unit square, written out: a strict fraction of 10 % and a span of 0.45-0.55."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from demid.sampling.domain import Domain
from demid.sampling.evaluate import evaluate_set
from demid.sampling.grid import admissible_set
from demid.uncertainty.plausible import plausible_identifiability_frame

from .test_uncertainty import linear

N = 21
TARGETS = {"y": 0.5}
SCENARIOS = {"s": (["y"], 0.1)}


def _strict_row(frame):
    return frame.set_index("factor").loc["a"]


def test_a_given_exact_set_is_the_strict_row_as_it_is():
    domain = Domain(("a", "b"), (0.0, 0.0), (1.0, 1.0))
    surrogates = {"y": linear(0.0, [1.0, 0.0])}
    exact = evaluate_set(surrogates, domain, ("y",), TARGETS, 0.1, N)
    assert exact.exact is not None and exact.fraction == pytest.approx(0.1, rel=1e-9)
    frame = plausible_identifiability_frame(surrogates, domain, SCENARIOS, TARGETS, N, polish=False,
                                            strict_sets={"s": replace(exact, fraction=0.02)})
    assert frame["strict_fraction_pct"].tolist() == pytest.approx([2.0, 2.0], rel=1e-12)


@pytest.mark.parametrize("grid_n, reused", [(N, True), (N + 2, False), (N - 2, False)])
def test_a_given_grid_set_is_reused_on_the_tables_grid_only(grid_n, reused):
    # b on a log axis: no polynomial of the search units, so the strict sets are grid sets
    domain = Domain(("a", "b"), (0.0, 1.0), (1.0, 10.0), (False, True))
    surrogates = {"y": linear(0.0, [1.0, 0.0])}
    grid = admissible_set(surrogates, domain, ("y",), TARGETS, 0.1, grid_n)
    assert grid.exact is None and grid.n_nodes == grid_n ** 2
    frame = plausible_identifiability_frame(surrogates, domain, SCENARIOS, TARGETS, N,
                                            strict_sets={"s": replace(grid, fraction=0.02)})
    expected = 2.0 if reused else 10.0  # |a - 0.5| <= 0.05 and all of b: a tenth of the square
    assert frame["strict_fraction_pct"].tolist() == pytest.approx([expected] * 2, rel=1e-6)
    row = _strict_row(frame)
    np.testing.assert_allclose([row["strict_lower"], row["strict_upper"]], [0.45, 0.55], atol=1e-9)  # polished
    assert frame["method"].tolist() == [f"grid {N}^2 with boundary refinement"] * 2
    # no surrogate error, no sigma: the plausible band is the tolerance band read at z, the same |a - 0.5| <= 0.05
    assert frame["robust_fraction_pct"].tolist() == pytest.approx([10.0, 10.0], rel=1e-6)
    np.testing.assert_allclose([row["robust_lower"], row["robust_upper"]], [0.45, 0.55], atol=1e-9)
    assert (frame["robust_fraction_error_pct"] >= 0).all() and (frame["robust_fraction_error_pct"] < 0.5).all()
    assert frame["tolerance"].tolist() == [0.1, 0.1] and frame["z"].tolist() == [2.0, 2.0]

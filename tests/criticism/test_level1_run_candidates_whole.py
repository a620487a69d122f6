"""The runs level 1 proposes when it is given the points to choose them from (criticism.level1.criticize with
``run_candidates``, a next wave's box grid in actual units): every proposed run is one of those points, none of the
design's own levels (the grid here avoids them: fractions 0.15, 0.4, 0.65 and 0.9 of each factor's range), and the
verdict says where they were chosen.  A planted drift on a 2-factor CCD, whose named cause is confirmed by runs."""
from __future__ import annotations

import numpy as np

from demid.criticism.level1 import criticize
from tests.generators import FACTORS, ccd_table


def test_proposed_runs_are_points_of_the_given_grid():
    table, _ = ccd_table(2, 2, "drift", 8.0)
    factors = FACTORS[2]
    lo, hi = table[factors].min().to_numpy(), table[factors].max().to_numpy()
    share = np.array([0.15, 0.4, 0.65, 0.9])
    grid = np.array([[a, b] for a in lo[0] + share * (hi[0] - lo[0]) for b in lo[1] + share * (hi[1] - lo[1])])
    result = criticize(table, factors, "y", n_null=49, run_candidates=grid)
    assert result.runs_for_next_wave and result.discriminating_runs
    points = np.array([[r[f] for f in factors] for r in result.discriminating_runs])
    # each run a grid point, to the 6 significant digits a run is written with
    nearest = np.min(np.max(np.abs(points[:, None, :] - grid[None, :, :]) / (hi - lo), axis=2), axis=1)
    assert np.all(nearest <= 1e-5)
    assert "chosen on the next wave's box grid" in result.verdict_message

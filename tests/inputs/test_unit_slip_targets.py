"""A target a power of ten off the runs is a unit slip even when the runs spread widely."""

from __future__ import annotations

import pandas as pd
import pytest


@pytest.mark.parametrize("target, factor", [(0.6, 10.0), (450.0, 0.1), (0.0061, 1000.0)])
def test_a_target_a_power_of_ten_off_widely_spread_runs_is_a_unit_slip(target, factor):
    """Runs from 5 to 60: 0.6 (for 6), 450 (for 45) and 0.0061 (for 6.1) lie within one range of the runs but a
    power of ten away; 3 and 100 lie less than a factor of 3 outside and stay plausible targets."""
    from demid.data import implausible_targets

    table = pd.DataFrame({"y": [5.0, 12.0, 30.0, 47.0, 60.0]})
    found = implausible_targets(table, {"y": target})["y"]
    assert found["factor"] == pytest.approx(factor) and 5.0 <= found["repaired"] <= 60.0
    assert implausible_targets(table, {"y": 3.0}) == {} and implausible_targets(table, {"y": 100.0}) == {}
    # runs of negative values: the same by magnitude
    assert implausible_targets(-table, {"y": -target})["y"]["factor"] == pytest.approx(factor)

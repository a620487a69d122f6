"""Whether a digit-level repair explains a run's miss (demid.transcription.typos.repair_explains), over generated
predictions and misses of either sign and scale and repairs on either side of the prediction: the repair explains
the miss exactly when it lands within a fifth of the miss of the prediction (on the fifth itself too), whichever
side it lands on -- a repair as far below the prediction as one above it leaves as much of the miss unexplained."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.transcription.typos import repair_explains

# the repair's offset from the prediction, as a share of the miss |found - predicted|
_SHARES = [-3.0, -1.0, -0.5, -0.2 - 1e-6, -0.2 + 1e-6, -0.1, 0.0, 0.1, 0.2 - 1e-6, 0.2 + 1e-6, 0.5, 1.0, 3.0]


@given(predicted=st.floats(-1e6, 1e6), miss=st.floats(1e-3, 1e6), miss_sign=st.sampled_from([-1.0, 1.0]))
@settings(max_examples=30, deadline=None, derandomize=True)
def test_a_repair_explains_the_miss_within_a_fifth_of_it_on_either_side(predicted, miss, miss_sign):
    found = predicted + miss_sign * miss
    for share in _SHARES:
        suggested = predicted + share * miss
        flag = {"found": found, "suggested": suggested, "predicted_from_other_runs": predicted}
        assert repair_explains(flag) is (abs(share) < 0.2), (share, flag)


@pytest.mark.parametrize("miss", [1.0, 10.0, 0.5, 1e4])
@pytest.mark.parametrize("side", [-1.0, 1.0])
def test_a_repair_a_fifth_of_the_miss_away_on_either_side_explains_it(miss, side):
    # predicted 0: the repair's distance is a fifth of the miss to the last bit
    flag = {"found": -side * miss, "suggested": side * 0.2 * miss, "predicted_from_other_runs": 0.0}
    assert repair_explains(flag) is True
    flag["suggested"] = side * 0.2 * miss * (1 + 1e-12)
    assert repair_explains(flag) is False

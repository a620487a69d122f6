"""A factor cell's repair to a design level no other cell prints (demid.transcription.check._cell_repairs) when two
slips of one kind land equally near the level, one on each side: the repair named is the one that changes the
printed value least, whichever of the two the slips list first (10.13, not 10.12, for 10.14 at a level of 10.125).
The levels are dyadic, so both repairs are exactly equally near them."""

from __future__ import annotations

import numpy as np
import pytest

from demid.transcription.check import _cell_repairs


@pytest.mark.parametrize("text, precision, level, near, far", [
    ("10.14", 2, 10.125, 10.13, 10.12),   # the level lies between the two; 10.13 is one step from 10.14
    ("10.16", 2, 10.125, 10.13, 10.12),
    ("10.11", 2, 10.125, 10.12, 10.13),
    ("10.05", 1, 11.0, 10.95, 11.05),     # 11.05 and 10.95 are both 0.05 from 11; 10.95 is nearer 10.05
    ("10.00", 0, 19.5, 19.0, 20.0),       # a column printed to integers: both half a unit from 19.5
])
def test_a_tie_between_two_repairs_goes_to_the_one_nearer_the_printed_value(text, precision, level, near, far):
    # the other cells print levels a unit or more away: the level is reachable only within the print's tolerance
    z = np.array([[level + 3.0], [level + 4.0], [level + 5.0], [float(text)]])
    repairs = _cell_repairs(text, z, 3, 0, np.array([level]), 1.0, precision, False, float(text))
    assert len(repairs) == 1
    kind, _, value, model_value, _ = repairs[0]
    assert abs(near - level) == abs(far - level)
    assert (value, model_value) == (near, near)
    assert kind == "digit_substitution"

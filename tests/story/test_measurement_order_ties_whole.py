"""The walk through the observable ranking breaks ties by the gain each added measurement brings over the starting
set (its difference), not by the larger set's own gain: two measurements whose differences are equal to the last
bit are told apart by the smaller fraction, even where their own gains differ in the last bit (a gain of 0.1 and the
next float above it, from a starting set of 4 bits: both add -3.9 bits)."""

from __future__ import annotations

import numpy as np
import pandas as pd

from demid.story.measurements import measurement_order


def test_equal_gains_over_the_starting_set_go_to_the_smaller_fraction_whatever_the_last_bit_of_the_gains():
    low, high = 0.1, float(np.nextafter(0.1, 1.0))
    assert low - 4.0 == high - 4.0 and low != high
    frame = pd.DataFrame({"observables": ["p", "q", "r", "p+q", "p+r", "q+r", "p+q+r"],
                          "information_gain_bits": [4.0, 0.5, 0.4, low, high, 0.9, 5.0],
                          "feasible_fraction_pct": [50.0, 60.0, 70.0, 10.0, 20.0, 30.0, 1.0]})
    from_p = next(line for line in measurement_order(frame) if line.startswith("From p,"))
    assert from_p == ("From p, adding q gains -3.90 bits (4.00 -> 0.10) and shrinks the admissible fraction by "
                      "80.0 % (50 % -> 10 %); r would gain -3.90 bits.")

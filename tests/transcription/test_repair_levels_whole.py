"""The levels a mistyped factor cell may be repaired to, against the rule written out here over generated columns
of exactly representable (dyadic) values, so that a cell lying exactly the tolerance away from a nominal level is
tested on the boundary: a nominal level some other cell prints within the tolerance (inclusive) is reachable only
as the value those cells print most often (the smallest of equally frequent ones); a level no other cell shows is
reachable within the tolerance; values the other cells repeat are exact levels too.  The cell itself never counts."""

from __future__ import annotations

from collections import Counter

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.transcription.engine import _levels_for_cell

NOMINAL = np.array([-2.0, -1.0, 0.0, 1.0, 2.0])
# multiples of 1/8 near each level: offsets of 0, 1/8 and 1/4 sit on either side of a tolerance of 1/8 or 1/4
VALUES = st.builds(lambda level, eighths: level + eighths / 8.0, st.sampled_from(list(NOMINAL)),
                   st.integers(-3, 3))


def _written_out(column, row, nominal, tolerance):
    others = [v for i, v in enumerate(column) if i != row]
    exact, loose = [], []
    for level in nominal:
        near = Counter(v for v in others if abs(v - level) <= tolerance)
        if near:
            most = max(near.values())
            exact.append(min(v for v, c in near.items() if c == most))
        else:
            loose.append(level)
    exact += [v for v, c in Counter(others).items() if c >= 2]
    return sorted(set(exact)), loose


@given(column=st.lists(VALUES, min_size=2, max_size=12), data=st.data(),
       tolerance=st.sampled_from([0.125, 0.25, 0.3]))
@settings(max_examples=80, deadline=None, derandomize=True)
def test_repair_levels_follow_the_rule_on_and_off_the_tolerance(column, data, tolerance):
    row = data.draw(st.integers(0, len(column) - 1))
    exact, loose = _levels_for_cell(np.array(column), row, NOMINAL, tolerance)
    want_exact, want_loose = _written_out(column, row, NOMINAL, tolerance)
    np.testing.assert_array_equal(exact, want_exact)
    np.testing.assert_array_equal(loose, want_loose)


def test_a_cell_exactly_the_tolerance_from_a_level_makes_it_exact():
    # 1.25 is 0.25 from the level 1: with a tolerance of 0.25 the level is reachable only as 1.25
    exact, loose = _levels_for_cell(np.array([1.25, -1.0, 0.0, 5.0]), 3, NOMINAL, 0.25)
    np.testing.assert_array_equal(exact, [-1.0, 0.0, 1.25])
    np.testing.assert_array_equal(loose, [-2.0, 2.0])
    exact, loose = _levels_for_cell(np.array([1.25, -1.0, 0.0, 5.0]), 3, NOMINAL, 0.125)
    np.testing.assert_array_equal(exact, [-1.0, 0.0])
    np.testing.assert_array_equal(loose, [-2.0, 1.0, 2.0])

"""How a column is printed, seen from each cell: the largest number of decimals among the column's other cells
(a cell's own digits never vouch for themselves), against a brute-force maximum over the others, for columns of
one to six cells with mixed decimals, exponents and missing cells."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.transcription.printed import _precision_elsewhere

SETTINGS = settings(max_examples=25, deadline=None, derandomize=True)

CELLS = ["3", "2.5", "0.25", "1.0757", "1.20", "4.000", "1e-05", "2.5E+03", None]
DECIMALS = {"3": 0, "2.5": 1, "0.25": 2, "1.0757": 4, "1.20": 1, "4.000": 0, "1e-05": 5, "2.5E+03": 0, None: 0}


@given(texts=st.lists(st.sampled_from(CELLS), min_size=1, max_size=6))
@SETTINGS
def test_each_cell_sees_the_largest_decimals_of_the_other_cells(texts):
    if len(texts) == 1:
        expected = [DECIMALS[texts[0]]]  # no other cell: its own
    else:
        expected = [max(DECIMALS[t] for j, t in enumerate(texts) if j != i) for i in range(len(texts))]
    np.testing.assert_array_equal(_precision_elsewhere(texts), expected)


def test_two_cells_see_each_other():
    np.testing.assert_array_equal(_precision_elsewhere(["1.5", "2.25"]), [2, 1])

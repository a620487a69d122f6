"""The printed form of every cell the transcription check reads (demid.transcription.printed._cell_texts), over
generated columns: a cell keeps its printed text, stripped, where the table holds a finite number for it; a blank,
whitespace-only, missing or NaN print, or a cell whose value is not finite (a failed run), has no printed form;
without a printed table each column is reconstructed as numbers print positionally; a printed table of another
length or without the column is refused in one line naming the column."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from hypothesis import Phase, given, settings
from hypothesis import strategies as st

from demid.errors import InputError
from demid.transcription.printed import _cell_texts, _printed_column

PRINTS = st.sampled_from(["1.50", " 2.0 ", "-3", "", "   ", None, float("nan"), "4.125\t", "7e-3"])


@given(cells=st.lists(st.tuples(PRINTS, st.sampled_from([1.5, -2.25, float("nan")])), min_size=1, max_size=8))
@settings(max_examples=25, deadline=None, derandomize=True, phases=[Phase.explicit, Phase.generate])
def test_a_cell_keeps_its_stripped_print_only_where_both_print_and_value_are_there(cells):
    prints, values = zip(*cells)
    table = pd.DataFrame({"y": list(values)})
    printed = pd.DataFrame({"y": pd.Series(list(prints), dtype=object)})
    want = []
    for cell, value in cells:
        text = cell.strip() if isinstance(cell, str) else None
        want.append(text if text and np.isfinite(value) else None)
    assert _cell_texts(table, printed, ["y"], "t.csv") == {"y": want}


def test_without_a_printed_table_each_column_is_reconstructed():
    table = pd.DataFrame({"x": [1.0, 2.5, np.nan], "y": [0.125, -3.0, 4.0]})
    got = _cell_texts(table, None, ["x", "y"], "t.csv")
    assert got == {"x": _printed_column(table["x"].to_numpy()), "y": _printed_column(table["y"].to_numpy())}


@pytest.mark.parametrize("printed", [pd.DataFrame({"y": ["1", "2"]}), pd.DataFrame({"z": ["1", "2", "3"]})])
def test_a_printed_table_that_does_not_match_is_refused_naming_the_column(printed):
    with pytest.raises(InputError) as info:
        _cell_texts(pd.DataFrame({"y": [1.0, 2.0, 3.0]}), printed, ["y"], "t.csv")
    assert info.value.detail == "printed table does not match the table in column 'y'"

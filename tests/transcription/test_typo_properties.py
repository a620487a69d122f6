"""The typo stop over generated tables whose response column mixes printed decimals (two decimals, a few cells
that lost a trailing zero): a digit dropped from a two-decimal cell (16.26 for 106.26) stops the run and is
restored, whichever cells lost their zero; the column's decimals are the most any cell shows."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.errors import InputError
from demid.transcription.typos import _decimal_places

from .test_typo_stop import _study, _validate


@given(seed=st.integers(0, 10_000), short=st.integers(1, 4), run=st.integers(1, 13))
@settings(max_examples=8, deadline=None, derandomize=True)
def test_a_dropped_zero_is_restored_in_a_column_with_mixed_decimals(tmp_path_factory, seed, short, run):
    tmp_path = tmp_path_factory.mktemp("typo")
    rng = np.random.default_rng(seed)
    _study(tmp_path, seed)
    path = tmp_path / "tables" / "m.csv"
    lines = path.read_text().splitlines()
    rows = [line.split(",") for line in lines[1:]]
    values = [106.0 + 0.5 * float(r[1]) + 0.02 * float(r[2]) + rng.normal(0, 0.04) for r in rows]
    others = [i for i in range(len(rows)) if i + 1 != run]
    lost = set(rng.choice(others, size=short, replace=False).tolist())
    for i, (r, v) in enumerate(zip(rows, values)):
        if i in lost:  # a value ending in 0 printed without it: 106.3 for 106.30
            r[3] = f"{v:.1f}"
        elif i + 1 == run:
            r[3] = f"{v:.2f}"
            original = r[3]
            r[3] = original[:1] + original[2:]  # 106.26 typed 16.26
        else:
            r[3] = f"{v:.2f}"
    assert _decimal_places([r[3] for r in rows]) == 2
    path.write_text("\n".join([lines[0]] + [",".join(r) for r in rows]) + "\n")
    try:
        _validate(tmp_path)
    except InputError as err:
        message = str(err)
    else:
        raise AssertionError(f"{original[:1] + original[2:]} for {original} passed")
    assert message.startswith(f"tables/m.csv, run {run}, column 'y1': {original[:1] + original[2:]} looks like "
                              f"{float(original):g} with a digit dropped"), message


@given(st.lists(st.integers(0, 4), min_size=1, max_size=8))
@settings(max_examples=30, deadline=None, derandomize=True)
def test_a_columns_decimals_are_the_most_any_cell_shows(places):
    cells = [f"{12.5:.{p}f}" for p in places] + [""]
    assert _decimal_places(cells) == max(places)

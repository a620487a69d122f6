"""A design table read back whole, against the table built in the test: runs in increasing run order whatever
order the file lists them in, every factor and response value as printed (decimals mixed within a column, signs,
scales), a failed run's empty responses as NaN with its status, block labels as written, the warnings one per
failed run or NaN cell, and each factor's printed place (its finest printed digit), over generated tables of one
to three factors, one to three responses and three to twelve runs."""

from __future__ import annotations

import math
from decimal import Decimal

import numpy as np
import pandas as pd
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.data import read_table
from demid.precision import PRINTED_PLACE


def _cell(rng, scale: float) -> str:
    value = rng.normal() * scale
    return f"{value:.{int(rng.integers(0, 5))}f}"


def _table(seed: int, k: int, m: int, n: int, with_status: bool, with_blocks: bool, scale: float):
    rng = np.random.default_rng(seed)
    factors, responses = [f"f{i}" for i in range(k)], [f"y{j}" for j in range(m)]
    runs = rng.choice(np.arange(1, 60), size=n, replace=False)
    rows = []
    for run in runs:
        failed = with_status and rng.random() < 0.25
        row = {"run": str(run), **{f: _cell(rng, scale) for f in factors}}
        row.update({y: "" if failed else _cell(rng, scale) for y in responses})
        if with_status:
            row["status"] = "failed" if failed else rng.choice(["ok", "done", ""])
        if with_blocks:
            row["block"] = rng.choice(["1", "2.0", "night"])
        rows.append(row)
    if rows and not with_status and m:
        rows[int(rng.integers(0, n))][responses[0]] = "nan"  # a NaN cell: a failed simulation, with a warning
    return factors, responses, rows


@given(seed=st.integers(0, 10_000), k=st.integers(1, 3), m=st.integers(1, 3), n=st.integers(3, 12),
       with_status=st.booleans(), with_blocks=st.booleans(), scale=st.sampled_from([1e-3, 1.0, 4e3]))
@settings(max_examples=25, deadline=None, derandomize=True)
def test_a_table_read_back_is_the_table_written_sorted_by_run(tmp_path_factory, seed, k, m, n, with_status,
                                                              with_blocks, scale):
    factors, responses, rows = _table(seed, k, m, n, with_status, with_blocks, scale)
    columns = list(rows[0])
    path = tmp_path_factory.mktemp("t") / "table.csv"
    path.write_text("\n".join([",".join(columns)] + [",".join(r[c] for c in columns) for r in rows]) + "\n",
                    encoding="utf-8")
    table, warnings = read_table(path, factors, responses)

    ordered = sorted(rows, key=lambda r: int(r["run"]))
    assert list(table["run"]) == [int(r["run"]) for r in ordered]
    assert list(table.index) == list(range(n))
    for name in factors + responses:
        want = [float(r[name]) if r[name] not in ("", "nan") else math.nan for r in ordered]
        np.testing.assert_array_equal(table[name].to_numpy(dtype=float), want)
    failed = [r.get("status") == "failed" for r in ordered]
    assert list(table["status"]) == ["failed" if f else "ok" for f in failed]
    if with_blocks:
        assert list(table["block"]) == [{"2.0": "2"}.get(r["block"], r["block"]) for r in ordered]
    else:
        assert "block" not in table.columns
    nan_cells = sum(r[y] == "nan" for r in rows for y in responses)
    assert len(warnings) == sum(failed) + nan_cells
    for f in factors:
        finest = min(Decimal(r[f]).as_tuple().exponent for r in rows)
        assert table.attrs[PRINTED_PLACE][f] == float(10.0 ** finest)
    assert isinstance(table, pd.DataFrame)

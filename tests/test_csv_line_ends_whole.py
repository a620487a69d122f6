"""Both CSV writers end every line with "\n" whatever the platform's line separator (os.linesep is "\r\n" on
Windows): a table written there has the same bytes as here, and the full-precision table reads back to the same
values, every float at full precision."""

from __future__ import annotations

import os

import numpy as np
import pandas as pd
import pytest

from demid.io import write_csv, write_full_csv


def _frame() -> pd.DataFrame:
    return pd.DataFrame({"run": [1, 2, 3], "a": [0.1, 1 / 3, -2.5e-7], "y": [12.345678901234, np.nan, 7.0],
                         "status": ["ok", "failed", "ok"]})


@pytest.mark.parametrize("linesep", ["\r\n", "\n"])
@pytest.mark.parametrize("writer", [write_full_csv, write_csv])
def test_every_csv_line_ends_with_a_newline_alone_on_any_platform(tmp_path, monkeypatch, writer, linesep):
    monkeypatch.setattr(os, "linesep", linesep)
    path = tmp_path / "t.csv"
    writer(_frame(), path)
    data = path.read_bytes()
    assert b"\r" not in data
    assert data.count(b"\n") == 4 and data.endswith(b"\n")
    if writer is write_full_csv:
        assert data.decode("utf-8").splitlines()[1] == "1,0.1,12.345678901234,ok"
        back = pd.read_csv(path)
        assert back["a"].tolist() == [0.1, 1 / 3, -2.5e-7]
        assert back["y"].iloc[0] == 12.345678901234 and np.isnan(back["y"].iloc[1])

"""Run numbers a design table may hold, read back whole: any integer of magnitude below 2^53 (the largest a float
and parquet hold exactly) is read as written, whatever the other runs' numbers (a second wave numbered from 101 or
from 1001, runs numbered by date, negative numbers), and the first integer from 2^53 on, either sign, is refused in
one line naming it.  The runs come back in increasing run order with their own values."""

from __future__ import annotations

import pytest

from demid.data import read_table
from demid.errors import InputError

_HEAD = "run,x1,x2,y,status"


def _write(tmp_path, runs: list[int | str]):
    lines = [_HEAD] + [f"{r},{0.1 * (i + 1):.1f},{i + 1},{5.0 + i:.1f},ok" for i, r in enumerate(runs)]
    path = tmp_path / "t.csv"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


@pytest.mark.parametrize("runs", [
    [101, 102, 103, 104, 105, 106, 107],          # a second wave numbered on from a first of 100 runs
    [1001, 1002, 1003],
    [105, 106],                                   # either side of 2 * 53
    [20261129, 20261130, 7],                      # runs numbered by date beside a plain number
    [2 ** 53 - 1, 1, -(2 ** 53 - 1)],             # the largest magnitudes held exactly
    [-106, -1000, 0],
])
def test_every_integer_run_number_below_two_to_the_53_is_read_as_written(tmp_path, runs):
    table, warnings = read_table(_write(tmp_path, runs), ["x1", "x2"], ["y"])
    assert warnings == []
    assert list(table["run"]) == sorted(runs)
    assert all(type(r) is int for r in table["run"].tolist())
    # each run keeps its own row: the response written beside it
    written = {r: 5.0 + i for i, r in enumerate(runs)}
    assert {int(r): float(y) for r, y in zip(table["run"], table["y"])} == written


@pytest.mark.parametrize("run", [2 ** 53, -(2 ** 53), 2 ** 53 + 2, 10 ** 17])
def test_the_first_run_numbers_not_exact_as_floats_are_refused_in_one_line(tmp_path, run):
    path = _write(tmp_path, [1, run, 3])
    with pytest.raises(InputError, match=rf"line 3: found '{run}', expected an integer run number below 2\^53"):
        read_table(path, ["x1", "x2"], ["y"])


@pytest.mark.parametrize("cell", ["106.5", "1e-3"])
def test_a_run_number_with_a_fraction_is_refused_without_the_bound(tmp_path, cell):
    path = _write(tmp_path, [1, cell, 3])
    with pytest.raises(InputError, match=rf"line 3: found '{cell}', expected an integer run number$"):
        read_table(path, ["x1", "x2"], ["y"])

"""A table's cells as printed (:func:`demid.data.read_printed`), read back whole against the file written in the
test: exactly the file's columns in its order (an extra column, also one called ``index``, kept; nothing added),
every cell as written without its surrounding spaces (trailing zeros, signs, exponents and words kept), the run
numbers as integers however they were written (``7``, ``07``, ``7.0``), and the rows in the order of the table
given, whatever order the file lists them in; over generated tables of one to three factors and responses."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from demid.data import read_printed


def _number(rng) -> str:
    value = rng.normal() * 10.0 ** int(rng.integers(-3, 4))
    form = int(rng.integers(0, 3))
    return f"{value:.{int(rng.integers(0, 5))}f}" if form < 2 else f"{value:.3e}"


def _run_text(rng, run: int) -> str:
    return str(rng.choice([str(run), f"0{run}", f"{run}.0", f" {run} "]))


@pytest.mark.parametrize("seed", range(6))
def test_printed_cells_are_the_files_text_in_the_tables_run_order(tmp_path, seed):
    rng = np.random.default_rng(seed)
    k, m, n = int(rng.integers(1, 4)), int(rng.integers(1, 4)), int(rng.integers(3, 9))
    columns = ["run"] + [f"f{i}" for i in range(k)] + [f"y{j}" for j in range(m)]
    extra = ["index", "note"][: int(rng.integers(0, 3))]  # an unlisted column called index, a text column
    columns += extra
    order = rng.permutation(columns[1:])
    columns = ["run", *order]  # the run column first, the others in any order
    runs = [int(r) for r in rng.choice(np.arange(1, 40), size=n, replace=False)]
    cells = []
    for run in runs:
        row = {"run": _run_text(rng, run)}
        for c in columns[1:]:
            text = str(rng.choice(["ok", "x y", ""])) if c == "note" else _number(rng)
            row[c] = str(rng.choice(["", " ", "  "])) + text + str(rng.choice(["", " "]))
        cells.append(row)
    path = tmp_path / "table.csv"
    path.write_text("\n".join([",".join(columns)] + [",".join(r[c] for c in columns) for r in cells]) + "\n",
                    encoding="utf-8")
    wanted = [runs[i] for i in rng.permutation(n)]  # the validated table's order (any)
    table = pd.DataFrame({"run": wanted})

    printed = read_printed(path, table)

    assert list(printed.columns) == columns
    assert list(printed.index) == list(range(n))
    by_run = {run: row for run, row in zip(runs, cells)}
    for i, run in enumerate(wanted):
        assert printed["run"].iloc[i] == str(run)
        for c in columns[1:]:
            assert printed[c].iloc[i] == by_run[run][c].strip()

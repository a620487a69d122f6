"""The order of the transcription check's leads where several repairs restore every published statistic, and a
check whose repairs are all of response cells.

A factor cell found off every level of its design is itself irregular: when its repair and a repair of another cell
both restore the published statistics, the off-level cell is named first (CCD tables of two or three factors, the
last two digits of one factor cell transposed, R² and RMSE published to one or two decimals, so that a response
cell's repair restores them too).  A printed table that gives the response column's prints alone (the factor cells
blank) has no factor repair to weigh: the check still names the response cell that was slipped."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from tests.transcription.test_check_whole import _statistics, _table, _transposed
from demid.errors import InputError
from demid.transcription.check import check_transcription


def _slipped_factor_cell(seed: int, k: int, decimals: int):
    """The table with one factor cell's last two digits transposed, that cell, and R² and RMSE published to
    ``decimals`` from the clean table's own fit."""
    table, names, coding, alpha = _table(seed, k, 1.0)
    stats = _statistics(coding.to_coded(table[names].to_numpy()), table["y"].to_numpy())
    published = {"r2": f"{stats['r2']:.{decimals}f}", "rmse": f"{stats['rmse']:.{decimals}f}"}
    rng = np.random.default_rng(seed)
    row, column = int(rng.integers(0, len(table))), names[int(rng.integers(0, k))]
    text = f"{table.loc[row, column]:.4f}"
    slipped_text = text[:-2] + text[-1] + text[-2]
    slipped = table.copy()
    slipped.loc[row, column] = float(slipped_text)
    return slipped, names, alpha, published, row, column, text, slipped_text


# (seed, factors, printed decimals): tables where a response cell's repair restores both statistics too; in the
# first three that repair would come first by kind, row or column were the off-level cell not named first
@pytest.mark.parametrize("seed, k, decimals", [(4, 3, 2), (28, 3, 2), (33, 3, 1), (26, 2, 2), (40, 2, 2),
                                               (43, 2, 1), (45, 3, 2), (47, 2, 2), (48, 2, 2)])
def test_a_factor_cell_off_every_level_is_named_first_among_repairs_that_restore_everything(seed, k, decimals):
    slipped, names, alpha, published, row, column, text, slipped_text = _slipped_factor_cell(seed, k, decimals)
    result = check_transcription(slipped, names, "y", published, alpha=alpha)
    assert not result.consistent and result.explained
    assert len(result.suspects) >= 2 and all(s.restores == 2 for s in result.suspects)
    assert any(s.column == "y" for s in result.suspects)  # a response cell's repair restores both too
    first = result.suspects[0]
    assert (first.run, first.column, first.found_text, first.suggested_text, first.kind) == (
        row + 1, column, slipped_text, text, "transposition")
    assert first.found == float(slipped_text) and first.suggested == float(text)
    assert (f"run {row + 1}, column '{column}' reads {slipped_text} where {text} restores all 2 (transposition)"
            in result.message)


@pytest.mark.parametrize("seed, k", [(3, 2), (11, 3)])
def test_with_only_the_response_printed_the_slipped_response_cell_is_named(seed, k):
    table, names, coding, alpha = _table(seed, k, -1.0)
    stats = _statistics(coding.to_coded(table[names].to_numpy()), table["y"].to_numpy())
    published = {"r2": f"{stats['r2']:.4f}", "adj_r2": f"{stats['adj_r2']:.4f}", "rmse": f"{stats['rmse']:.4f}"}
    row = len(table) // 2
    found_text = f"{table.loc[row, 'y']:.2f}"
    slipped_text = _transposed(found_text)
    slipped = table.copy()
    slipped.loc[row, "y"] = float(slipped_text)
    printed = pd.DataFrame({"run": slipped["run"].astype(str), **{name: [None] * len(table) for name in names},
                            "y": [f"{v:.2f}" for v in slipped["y"]]})
    result = check_transcription(slipped, names, "y", published, alpha=alpha, printed=printed)
    assert not result.consistent and result.explained
    assert {s.column for s in result.suspects} == {"y"}  # no factor cell has a print to repair
    first = result.suspects[0]
    assert (first.run, first.found_text, first.suggested_text, first.restores) == (row + 1, slipped_text,
                                                                                   found_text, 3)
    assert f"run {row + 1}, column 'y' reads {slipped_text} where {found_text} restores all 3" in result.message


def test_a_table_without_a_single_response_value_is_refused_in_one_line_naming_the_column():
    table, names, coding, alpha = _table(1, 2, 1.0)
    table["y"] = np.nan
    with pytest.raises(InputError) as info:
        check_transcription(table, names, "y", {"r2": "0.95"}, alpha=alpha, source="paper.yaml")
    text = str(info.value)
    assert "paper.yaml" in text and "column 'y'" in text and "no run has a value of 'y'" in text
    assert "\n" not in text


def test_repairs_alike_in_kind_and_fit_are_listed_by_run_then_by_the_columns_place_in_the_table():
    """Forty leads of a table whose R² and RMSE (two decimals) many one-digit repairs restore: among those of one
    kind, all restoring both with no misfit left, the lower run comes first, then the column further left (a
    factor cell of run 6 after the response cells of runs 1-5, before run 6's own)."""
    slipped, names, alpha, published, *_ = _slipped_factor_cell(26, 2, 2)
    result = check_transcription(slipped, names, "y", published, alpha=alpha, max_suspects=40)
    alike = [s for s in result.suspects if s.kind == "digit_substitution"]
    assert all(s.restores == 2 and s.misfit == 0.0 for s in alike)
    place = {name: i for i, name in enumerate(slipped.columns)}
    order = [(s.run, place[s.column]) for s in alike]
    assert len({s.column for s in alike}) == 2 and order == sorted(order)

"""What the transcription check reports beyond its verdict: how many leads it lists when many single-cell repairs
restore every published statistic (ten unless asked, the best first, out of the count its message quotes), which
factor cell it names when factor values are missing (the first in reading order, by its run number and column), and
the frame of statistics the workflow stores for a material's responses (one row per published statistic, numbered
from 0 across responses, as each response's own rows say)."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from tests.transcription.test_check_ranking_whole import _slipped_factor_cell
from tests.transcription.test_check_whole import _statistics, _table
from demid.errors import InputError
from demid.transcription.check import TRANSCRIPTION_FRAME_COLUMNS, check_transcription, transcription_frame


def _lead(s):
    return (s.run, s.column, s.found_text, s.suggested_text, s.kind, s.restores)


@pytest.mark.parametrize("seed, k, decimals", [(43, 2, 1)])
def test_without_a_limit_the_ten_best_of_many_equal_repairs_are_listed(seed, k, decimals):
    slipped, names, alpha, published, *_ = _slipped_factor_cell(seed, k, decimals)
    listed = check_transcription(slipped, names, "y", published, alpha=alpha)
    every = check_transcription(slipped, names, "y", published, alpha=alpha, max_suspects=10 ** 6)
    n_full = sum(s.restores == len(published) for s in every.suspects)
    assert n_full == len(every.suspects) > 10  # every lead restores both statistics
    assert [_lead(s) for s in listed.suspects] == [_lead(s) for s in every.suspects[:10]]
    assert f"but {n_full} different single-cell repairs restore all of them" in listed.message
    assert listed.message == every.message


@pytest.mark.parametrize("seed, k, cells", [(1, 2, [(3, 1), (7, 0)]), (2, 3, [(0, 2), (5, 1), (5, 0)]),
                                             (5, 3, [(9, 2), (9, 1)])])
def test_the_first_missing_factor_cell_in_reading_order_is_named(seed, k, cells):
    table, names, coding, alpha = _table(seed, k, 1.0)
    table["run"] = np.arange(101, 101 + len(table))  # run numbers that are not row positions
    for row, col in cells:
        table.loc[row, names[col]] = np.nan
    row, col = min(cells)
    with pytest.raises(InputError) as info:
        check_transcription(table, names, "y", {"r2": "0.9"}, alpha=alpha, source="paper.yaml")
    assert str(info.value) == f"paper.yaml, run {101 + row}, column '{names[col]}': factor value is missing"


def _result(seed, k, sign, decimals):
    """The check of a clean table against R², adjusted R² and RMSE printed from its own fit, one of them
    misprinted by a unit of its last decimal (so that the frame's 'agrees' column holds both values)."""
    table, names, coding, alpha = _table(seed, k, sign)
    stats = _statistics(coding.to_coded(table[names].to_numpy()), table["y"].to_numpy())
    printed = {s: f"{stats[s]:.{decimals}f}" for s in ("r2", "adj_r2", "rmse")}
    printed["rmse"] = f"{stats['rmse'] + 10.0 ** -decimals:.{decimals}f}"
    return check_transcription(table.rename(columns={"y": f"y{seed}"}), names, f"y{seed}", printed,
                               alpha=alpha), stats, printed


def test_the_stored_frame_holds_every_published_statistic_of_every_response_in_order():
    checks = [_result(seed, k, sign, d) for seed, k, sign, d in ((3, 2, 1.0, 3), (8, 3, -1.0, 4), (12, 2, -1.0, 2))]
    frame = transcription_frame([c for c, _, _ in checks])
    rows = []
    for check, stats, printed in checks:
        for name in ("r2", "adj_r2", "rmse"):
            decimals = len(printed[name].partition(".")[2])
            rows.append((check.response, name, float(printed[name]), stats[name],
                         abs(stats[name] - float(printed[name])) <= 0.5 * 10.0 ** -decimals,
                         printed[name], float(decimals)))
    expected = pd.DataFrame(rows, columns=TRANSCRIPTION_FRAME_COLUMNS)
    assert list(frame.index) == list(range(len(rows)))
    pd.testing.assert_frame_equal(frame.drop(columns="reproduced"), expected.drop(columns="reproduced"),
                                  check_dtype=False)
    assert np.allclose(frame["reproduced"], expected["reproduced"], rtol=1e-9, atol=1e-12)
    assert not frame["agrees"].all() and frame["agrees"].any()


def test_no_response_checked_gives_an_empty_frame_with_the_columns():
    frame = transcription_frame([])
    assert list(frame.columns) == TRANSCRIPTION_FRAME_COLUMNS and len(frame) == 0

"""The data dictionary tables/columns.csv read whole: one row for every column of every table in the order it is
written, the next-wave, combination and Pareto tables with their study-dependent columns and units, and the
numbers its descriptions quote against the constants they come from."""

from __future__ import annotations

import re

import pytest

from demid.report.columns import TABLE_COLUMNS, columns_table
from demid.sampling.domain import BOUND_TOUCH


def _rows(frame, table):
    return frame[frame["table"] == table]


@pytest.mark.parametrize("factors", [["e"], ["e", "mu_r"], ["e", "mu_r", "gamma", "k_n"]])
def test_every_column_of_every_table_has_one_row_in_the_order_written(factors):
    units = ["-", "Pa", "J/m²", ""]
    pareto = {"mat": [(f, units[i]) for i, f in enumerate(factors)]}
    next_wave = {"factors": [(f, units[i]) for i, f in enumerate(factors)], "responses": [("aor", "deg"), ("si", "-")]}
    frame = columns_table(pareto, next_wave, factors)
    assert frame.columns.tolist() == ["table", "column", "unit", "description"]
    assert not frame.duplicated(["table", "column"]).any()
    assert frame["description"].str.len().min() > 5 and frame["unit"].str.len().min() >= 1
    for table, columns in TABLE_COLUMNS.items():
        assert _rows(frame, f"{table}.csv")["column"].tolist() == columns
    assert _rows(frame, "combinations.csv")["column"].tolist() == [
        "material", "scenario", "set", "direction", *factors, "width_coded", "width_fraction_of_range"]
    assert _rows(frame, "next_domain.csv")["column"].tolist() == ["material", "factor", "lower", "upper"]
    runs = _rows(frame, "next_runs.csv")
    assert runs["column"].tolist() == ["material", "proposal", *factors, "purpose", "predicted_aor", "predicted_si"]
    shown = {"-": "–", "": "–"}
    assert runs["unit"].tolist()[2:2 + len(factors)] == [shown.get(units[i], units[i]) for i in range(len(factors))]
    assert runs["unit"].tolist()[-2:] == ["deg", "–"]
    front = _rows(frame, "pareto_mat.csv")
    assert front["column"].tolist() == ["kind", *factors, "error", "objective", "factor", "lower", "upper", "n_points"]
    assert front["unit"].tolist()[1:1 + len(factors)] == [shown.get(units[i], units[i]) for i in range(len(factors))]
    assert _rows(frame, "columns.csv")["column"].tolist() == ["table", "column", "unit", "description"]


def test_without_next_wave_combination_or_pareto_tables_their_rows_are_left_out():
    frame = columns_table({})
    tables = set(frame["table"])
    assert not {"next_runs.csv", "next_domain.csv", "combinations.csv"} & tables
    assert not any(t.startswith("pareto_") for t in tables)
    assert len(frame) == sum(map(len, TABLE_COLUMNS.values())) + 4


def test_the_descriptions_quote_the_bound_touch_share_in_percent():
    frame = columns_table({})
    at_bound = frame[(frame["table"] == "identifiability.csv") & (frame["column"] == "at_bound")]["description"].iloc[0]
    share = float(re.search(r"within (\S+) % of the range", at_bound).group(1))
    assert share == pytest.approx(100 * BOUND_TOUCH)
    units = dict(zip(frame["table"] + ":" + frame["column"], frame["unit"]))
    # fractions and percentages of Ω are told apart in the unit column
    assert units["identifiability.csv:tolerance"].startswith("fraction") and units[
        "identifiability.csv:feasible_fraction_pct"] == "% of Ω"
    assert units["observable_ranking.csv:information_gain_bits"] == "bit"

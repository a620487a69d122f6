"""Every field of a comparison row (demid.paper) for each kind of published number, on and just past its
tolerance, against the rule of the module docstring written out here: the differences (absolute, and relative
when the published value is not zero), the tolerance's text, the pass flag (the relative rules fall back to the
absolute difference where the published value is zero) and whether the reproduction rounds to the printed
digits.  The boundary values are chosen so that the differences are exact in binary (1/1000 of 1000, 0.0005 of
0).  And two comparisons of a few published numbers: an unresolved factor's share of a published search range
too narrow to divide by, a Table 3 entry that publishes its feasible fraction only."""

from __future__ import annotations

import math

import pandas as pd
import pytest

from demid.paper import COLUMNS, _Rows

# (kind, published, reproduced, abs_diff, rel_diff, tolerance text, pass)
CASES = [
    ("r2", 0.0, 0.0005, 0.0005, math.nan, "±0.0005", True),
    ("r2", 0.0, -0.0005, 0.0005, math.nan, "±0.0005", True),
    ("r2", 0.0, 0.000501, 0.000501, math.nan, "±0.0005", False),
    ("r2", 0.5, 0.5002, 0.0002, 0.0004, "±0.0005", True),
    ("rmse", 1000.0, 1001.0, 1.0, 0.001, "±0.1 % rel", True),
    ("rmse", -1000.0, -1001.0, 1.0, 0.001, "±0.1 % rel", True),
    ("rmse", 1000.0, 1001.5, 1.5, 0.0015, "±0.1 % rel", False),
    ("rmse", 0.0, 0.001, 0.001, math.nan, "±0.1 % rel", True),
    ("fraction", 1000.0, 999.0, 1.0, 0.001, "±0.1 % rel", True),
    ("fraction", 1000.0, 998.5, 1.5, 0.0015, "±0.1 % rel", False),
    ("width", 0.125, 0.1259765625, 0.0009765625, 0.0078125, "±0.001 abs (value < 0.25)", True),
    ("width", -0.125, -0.1265, 0.0015, 0.012, "±0.001 abs (value < 0.25)", False),
    ("width", 0.0, 0.001, 0.001, math.nan, "±0.001 abs (value < 0.25)", True),
    ("width", 0.25, 0.25125, 0.00125, 0.005, "±0.5 % rel", True),
    ("width", 1000.0, 1005.0, 5.0, 0.005, "±0.5 % rel", True),
    ("width", -1000.0, -994.0, 6.0, 0.006, "±0.5 % rel", False),
    ("contraction", 0.0, 0.1, 0.1, math.nan, "±0.1 point", True),
    ("contraction", -50.0, -50.125, 0.125, 0.0025, "±0.1 point", False),
    ("tolerance", 0.05, 0.05, 0.0, 0.0, "equal", True),
    ("tolerance", 0.0, 1e-12, 1e-12, math.nan, "equal", True),
    ("tolerance", 0.05, 0.0501, 0.0001, 0.002, "equal", False),
    ("unresolved", 100.0, 99.5, 0.5, 0.005, "≥ 99.5 % of the search range", True),
    ("unresolved", 100.0, 99.25, 0.75, 0.0075, "≥ 99.5 % of the search range", False),
    ("unresolved", 100.0, 100.0, 0.0, 0.0, "≥ 99.5 % of the search range", True),
    ("unresolved", 100.0, 101.0, 0.0, 0.0, "≥ 99.5 % of the search range", True),
]


def _same(a, b):
    return (math.isnan(a) and math.isnan(b)) or a == pytest.approx(b, rel=1e-12, abs=1e-15)


@pytest.mark.parametrize("kind, published, reproduced, abs_diff, rel_diff, text, passes", CASES)
def test_a_row_s_every_field_on_and_past_its_tolerance(kind, published, reproduced, abs_diff, rel_diff, text,
                                                        passes):
    rows = _Rows()
    rows.add("q", "m", published, reproduced, kind)
    row = rows.rows[0]
    assert list(row) == COLUMNS
    assert (row["quantity"], row["material"], row["published"], row["reproduced"]) == ("q", "m", published,
                                                                                      reproduced)
    assert _same(row["abs_diff"], abs_diff) and _same(row["rel_diff"], rel_diff), row
    assert row["tolerance"] == text and row["pass"] is passes


@pytest.mark.parametrize("kind", ["r2", "rmse", "fraction", "width", "contraction", "tolerance", "unresolved"])
def test_a_missing_reproduction_has_no_difference_and_neither_passes_nor_agrees(kind):
    rows = _Rows()
    rows.add("q", "m", 100.0 if kind == "unresolved" else 0.5, None, kind)
    row = rows.rows[0]
    assert math.isnan(row["reproduced"]) and math.isnan(row["abs_diff"]) and math.isnan(row["rel_diff"])
    assert row["pass"] is False and row["printed_agrees"] is False


@pytest.mark.parametrize("published, reproduced, decimals, agrees", [
    ("3.980", 3.9805, None, True), ("3.980", 3.98051, None, False), ("3.98", 3.9849, None, True),
    (0.0397, 0.03965, None, True), (0.0397, 0.039649, None, False), (12.0, 12.4, 0, True), (12.0, 12.6, 0, False),
    (-87.3, -87.35, None, True), (-87.3, -87.36, None, False), (100, 100.49, None, True)])
def test_printed_agreement_is_rounding_to_the_printed_decimals(published, reproduced, decimals, agrees):
    rows = _Rows()
    rows.add("q", "m", published, reproduced, "width", decimals=decimals)
    assert rows.rows[0]["printed_agrees"] is agrees


@pytest.mark.parametrize("reproduced, agrees", [(99.5, True), (99.49, False), (100.0, True), (float("nan"), False),
                                                (float("inf"), False)])
def test_an_unresolved_factor_agrees_with_the_print_from_99_5_percent(reproduced, agrees):
    rows = _Rows()
    rows.add("q", "m", 100.0, reproduced, "unresolved")
    assert rows.rows[0]["printed_agrees"] is agrees


def test_a_width_over_a_published_range_too_narrow_to_divide_by_neither_passes_nor_agrees():
    """A search range published as [0, 1e-310] (in another unit than the config's, say): the width's share of it
    overflows, and an infinite share is no reproduction of "the full search range"."""
    from demid.paper import paper_comparison

    ident = pd.DataFrame({"material": ["m"], "scenario": ["s"], "tolerance": [0.05], "feasible_fraction_pct": [40.0],
                          "factor": ["a"], "lower": [0.0], "upper": [0.5], "width": [0.5]})
    published = {"scenario_sets": {"m": {"s": {"unresolved": ["a"]}}}, "search_domain": {"m": {"a": [0.0, 1e-310]}}}
    row = paper_comparison(published, pd.DataFrame(columns=["material", "response", "r2", "rmse"]), ident, {}).iloc[0]
    assert row["reproduced"] == math.inf
    assert not row["pass"] and not row["printed_agrees"]


def test_an_unknown_kind_is_refused_by_name():
    with pytest.raises(ValueError, match="unknown kind of published number 'slope'"):
        _Rows().add("q", "m", 1.0, 1.0, "slope")


def test_a_table3_entry_with_only_its_feasible_fraction_gives_that_one_row():
    from demid.paper import paper_comparison

    ident = pd.DataFrame({"material": ["m", "m"], "scenario": ["s", "s"], "tolerance": [0.05, 0.05],
                          "feasible_fraction_pct": [40.0, 40.0], "factor": ["a", "b"], "lower": [0.0, 1.0],
                          "upper": [0.5, 2.0], "width": [0.5, 1.0]})
    published = {"table3": {"m": {"s": {"feasible_fraction_pct": 40.02}}}}
    table = paper_comparison(published, pd.DataFrame(columns=["material", "response", "r2", "rmse"]), ident, {})
    assert list(table["quantity"]) == ["Table 3 feasible fraction [%] s"]
    row = table.iloc[0]
    assert (row["published"], row["reproduced"]) == (40.02, 40.0)
    assert row["rel_diff"] == pytest.approx(0.02 / 40.02) and row["pass"] and not row["printed_agrees"]

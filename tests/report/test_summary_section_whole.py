"""The summary section at its edges: level 2 (every target at the reference tolerance) can fail while the scenario
the recommended point is read from still has an admissible set, and the point is then recommended as such; a point
whose scenario has no verdict rows; only the material's own widening advice counts as widening its point's bounds;
the verdict table's plausible widths as shares of the search range to three significant digits."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from demid.report.context import ReportContext
from demid.report.summary import summary

from .test_report_sentences_whole import _cells, _material, _text, _write


@pytest.mark.parametrize("strict_empty", [False, True])
def test_a_failed_level2_is_no_failure_of_a_scenario_that_has_an_admissible_set(tmp_path, strict_empty):
    material = _material(2)
    strict = (np.nan, np.nan) if strict_empty else (0.2, 0.6)
    rows = [{"material": "m", "scenario": "t", "factor": f, "strict_lower": strict[0], "strict_upper": strict[1],
             "plausible_lower": 0.1, "plausible_upper": 0.7, "verdict": "bounded", "reason": "why"} for f in "ab"]
    _write(tmp_path, "tables/verdicts.csv", pd.DataFrame(rows))
    _write(tmp_path, "criticism/m.json", {"level1": {}, "level2": {"feasible": False, "tolerance": 0.02,
                                                                   "best_errors": {"y": 0.05, "z": 0.01},
                                                                   "best_max_error": 0.05, "observables": ["y", "z"]}})
    _write(tmp_path, "uncertainty/m.json", {"recommended": {"scenario": "t", "plausible": True,
                                                            "point": {"a": 0.4, "b": 0.5}, "implausibility": 0.5}})
    text = _text(summary(ReportContext(str(tmp_path), {"materials": {"m": material}})))
    recommended = "Recommended parameter set (the point of the plausible set of First alone"
    most_plausible = ("No parameter set meets every target within the tolerance; counting the surrogate's and the "
                      "measurements' uncertainty, the most plausible point (the point of the plausible set of First "
                      "alone")
    assert (recommended in text, most_plausible in text) == (not strict_empty, strict_empty)


def test_a_point_whose_scenario_has_no_verdict_rows_is_quoted_without_intervals(tmp_path):
    """Verdicts of another scenario only (a results tree whose story ran before the point's scenario was judged):
    the point is given to four decimals (no interval sets its digits), without a plausible interval it does not
    have."""
    material = _material(2)
    rows = [{"material": "m", "scenario": "t", "factor": f, "strict_lower": 0.2, "strict_upper": 0.6,
             "plausible_lower": 0.1, "plausible_upper": 0.7, "verdict": "bounded", "reason": "why"} for f in "ab"]
    _write(tmp_path, "tables/verdicts.csv", pd.DataFrame(rows))
    _write(tmp_path, "uncertainty/m.json", {"recommended": {"scenario": "s", "plausible": True,
                                                            "point": {"a": 0.4, "b": 0.5}, "implausibility": 0.5}})
    text = _text(summary(ReportContext(str(tmp_path), {"materials": {"m": material}})))
    assert "Recommended parameter set (the point of the plausible set of Both" in text
    assert "implausibility 0.50): Alpha = 0.4000; Beta = 0.5000." in text and "(plausible " not in text


def test_only_the_materials_own_widening_advice_counts_as_widening_its_points_bounds(tmp_path):
    """A point on two upper bounds: one where the advice recalibrates instead (widening that bound is futile), one
    that another material's advice widens; neither is widened for this material."""
    rows = [{"material": "m", "scenario": "s", "factor": f, "strict_lower": 0.2, "strict_upper": 0.6,
             "plausible_lower": 0.1, "plausible_upper": 0.7, "verdict": "bounded", "reason": "why"} for f in "ab"]
    _write(tmp_path, "tables/verdicts.csv", pd.DataFrame(rows))
    advice = [{"material": "m", "kind": "recalibrate", "factor": "a", "bound": "upper", "observable": "y",
               "text": "Recalibrate y.", "decision": True},
              {"material": "n", "kind": "widen", "factor": "b", "bound": "upper", "observable": "",
               "text": "Widen b.", "decision": True}]
    _write(tmp_path, "tables/advice.csv", pd.DataFrame(advice))
    _write(tmp_path, "uncertainty/m.json", {"recommended": {"scenario": "s", "plausible": True,
                                                            "point": {"a": 1.0, "b": 2.0}, "implausibility": 0.5}})
    config = {"materials": {"m": _material(2), "n": _material(2)}}
    text = _text(summary(ReportContext(str(tmp_path), config)))
    assert ("⚠ Alpha and Beta lie on their upper search bounds; no widening is advised there (the plausible "
            "intervals are bounded: a wider range would not narrow them).") in text
    assert "which the advice below widens" not in text


def test_the_verdict_table_gives_each_plausible_width_as_a_share_of_the_range_to_three_digits(tmp_path):
    rng = np.random.default_rng(3)
    material = _material(3)
    uppers = [1.0, 2.0, 3.0]  # each factor's search range starts at 0
    rows, shares = [], []
    for f, upper in zip("abc", uppers):
        lo, hi = np.sort(rng.uniform(0, upper, 2))
        shares.append(100 * (hi - lo) / upper)
        rows.append({"material": "m", "scenario": "s", "factor": f, "strict_lower": lo, "strict_upper": hi,
                     "plausible_lower": lo, "plausible_upper": hi, "verdict": "bounded", "reason": "why"})
    _write(tmp_path, "tables/verdicts.csv", pd.DataFrame(rows))
    cells = _cells(summary(ReportContext(str(tmp_path), {"materials": {"m": material}})))
    assert [row[:2] for row in cells] == [["Both", label] for label in ("Alpha", "Beta", "Gamma")]
    assert [row[5] for row in cells] == [f"{v:.3g}" for v in shares]

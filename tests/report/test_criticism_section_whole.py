"""The report's section "What the model gets wrong" as a whole: the reference point's line per scenario under the
level-2 paragraph, and a criticism table without per-response columns (nothing named) read as no findings table."""

from __future__ import annotations

import pandas as pd

from demid.report.context import ReportContext
from demid.report.model_criticism import criticism

from .test_report_sentences_whole import _cells, _material, _text, _write

_LEVEL1 = {"y": {"verdict": "adequate", "messages": []}, "z": {"verdict": "adequate", "messages": []}}


def test_the_section_gives_the_reference_points_place_in_each_scenario_with_its_errors(tmp_path):
    positions = [{"scenario": "s", "inside": True, "errors": {"y": 0.0125, "z": -0.0375},
                  "nearest_admissible": None, "distance_pct_of_range": 0.0},
                 {"scenario": "t", "inside": False, "errors": {"y": 0.0125}, "nearest_admissible": None,
                  "distance_pct_of_range": None}]
    _write(tmp_path, "criticism/m.json", {"level1": _LEVEL1, "reference_point": positions})
    text = _text(criticism(ReportContext(str(tmp_path), {"materials": {"m": _material(2)}}), "m"))
    assert "Reference point vs scenario Both: it lies inside the admissible set (errors Yobs +1.25 %, Zobs −3.75 %)." \
        in text
    assert ("Reference point vs scenario First alone: it cannot lie in it: the admissible set is empty (errors Yobs "
            "+1.25 %).") in text


def test_a_criticism_table_without_per_response_columns_gives_no_findings_table(tmp_path):
    _write(tmp_path, "criticism/m.json", {"level1": _LEVEL1})
    _write(tmp_path, "tables/criticism.csv", pd.DataFrame({"material": ["m"], "note": ["nothing named"]}))
    parts = criticism(ReportContext(str(tmp_path), {"materials": {"m": _material(2)}}), "m")
    assert _cells(parts) == []
    assert "Yobs: nothing found by the catalogue tests." in _text(parts)

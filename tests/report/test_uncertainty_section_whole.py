"""The report's uncertainty section ("Beyond deterministic admissibility") with few inputs: a material judged in
one scenario tables its strict and plausible sets without a change from a first to a last scenario, and a results
tree without the strict-vs-plausible table still gives the tolerance sweep, the ranking and the notes."""

from __future__ import annotations

import pandas as pd

from demid.report.context import ReportContext
from demid.report.plausible import uncertainty

from .test_report_sentences_whole import _cells, _material, _text, _write


def _rows(scenarios, factors=("a", "b")) -> pd.DataFrame:
    return pd.DataFrame([{"material": "m", "scenario": sc, "observables": "y", "tolerance": 0.02, "z": 2,
                          "factor": f, "strict_fraction_pct": 10.0 + i, "robust_fraction_pct": 20.0 + i,
                          "strict_width": 0.1, "robust_width": 0.2}
                         for i, sc in enumerate(scenarios) for f in factors])


def test_a_material_judged_in_one_scenario_quotes_no_change_between_scenarios(tmp_path):
    _write(tmp_path, "tables/robust_identifiability.csv", _rows(["s"]))
    _write(tmp_path, "uncertainty/m.json", {})
    parts = uncertainty(ReportContext(str(tmp_path), {"materials": {"m": _material(2)}}), "m")
    text = _text(parts)
    assert "Strict vs plausible admissible sets." in text
    assert len(_cells(parts)) == 2  # one row per factor of the one scenario
    assert "feasible fraction changes" not in text and "From " not in text


def test_without_the_strict_vs_plausible_table_the_rest_of_the_section_is_given(tmp_path):
    _write(tmp_path, "uncertainty/m.json", {"notes": ["a note on y"]})
    text = _text(uncertainty(ReportContext(str(tmp_path), {"materials": {"m": _material(2)}}), "m"))
    assert "Beyond deterministic admissibility" in text and "Strict vs plausible" not in text
    assert "Tolerance sweep" in text and "a note on Yobs" in text

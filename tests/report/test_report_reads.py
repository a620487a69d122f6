"""The report read as a researcher reads it: every table renders, the recommended point says where it sits,
one next step per material, numbers to the precision they carry, labels instead of keys, the answer first."""

from __future__ import annotations

import html as entities
import re

import numpy as np
import pandas as pd
import pytest

from demid.report.safe_html import markdown_html
from demid.report.sections import markdown_table
from demid.spec import MaterialSpec
from demid.story import StudyAdvice, material_advice

#: A Markdown table row left as text: a line that starts and ends with a bar and holds one between (``|x|`` in
#: a cell is text, ``| a | b |`` a row).
RAW_ROW = re.compile(r"^\s*\|.+\|.+\|\s*$", re.M)


def visible_text(html: str) -> str:
    """What a reader sees of report HTML: styles, scripts and images dropped, tags removed, entities read."""
    text = re.sub(r"<(style|script)\b.*?</\1>", "", html, flags=re.S)
    text = re.sub(r"<img\b[^>]*>", "", text)
    return entities.unescape(re.sub(r"<[^>]+>", "", text))


def _spec(**extra) -> MaterialSpec:
    material = {"data": "x.csv", "design": {"type": "ccd", "alpha": 1.41421, "center_runs": 3},
                "factors": {"a": {"lower": 0.0, "upper": 1.0, "label": "α_A"},
                            "b": {"lower": 0.0, "upper": 1.0, "label": "β_B", "limits": {"lower": 0}}},
                "responses": {"y": {"target": 0.5, "label": "Y_obs"}},
                "scenarios": {"s": {"observables": ["y"], "tolerance": 0.02, "label": "Y alone"}}, **extra}
    return MaterialSpec.from_material("m", material, grid_points=51)


# --------------------------------------------------------------------------- every table renders
def test_a_table_whose_header_and_cells_hold_bars_renders_as_a_table():
    frame = pd.DataFrame({"max_abs_student_resid": [1.94], "abs_diff": [0.5], "note": ["|x| > 2"]})
    html = markdown_html(markdown_table(frame))
    assert html.count("<table>") == 1 and not RAW_ROW.search(visible_text(html)), html
    assert "max |studentised residual|" in visible_text(html) and "|x| > 2" in visible_text(html)


@pytest.mark.workflow
def test_the_demo_report_has_no_table_left_as_raw_markdown(demo_run):
    html = (demo_run / "results" / "report" / "report.html").read_text(encoding="utf-8")
    raw = RAW_ROW.findall(visible_text(html))
    assert not raw, raw[:3]
    assert html.count("<table>") >= 20  # the residual diagnostics of every material and the appendix among them


# --------------------------------------------------------------------------- the recommended point on an edge
def _ccd_runs(alpha=1.41421):
    """A two-factor CCD over [0, 1]²: the axial points on the bounds, the factorial ones inside."""
    coded = np.array([[-1, -1], [1, -1], [-1, 1], [1, 1], [-alpha, 0], [alpha, 0], [0, -alpha], [0, alpha], [0, 0]])
    return 0.5 + coded / (2 * alpha)


def test_a_point_on_a_bound_and_outside_the_runs_says_so_with_the_advice_on_that_bound():
    from demid.report.summary import point_on_edge_text

    spec = _spec()
    runs = _ccd_runs()
    assert point_on_edge_text(spec, {"a": 0.5, "b": 0.5}, runs, {}, set()) == ""
    # the corner of the search range: on both lower bounds (b's at its physical limit), outside the CCD's hull
    corner = point_on_edge_text(spec, {"a": 0.0, "b": 0.0}, runs, {"a": "unresolved"}, set())
    assert "α_A lies on its lower search bound; no widening is advised there (the plausible interval is " \
           "unresolved" in corner
    assert "β_B is at its physical lower limit" in corner
    assert "outside the region the design runs cover" in corner and "extrapolation" in corner
    # on a bound the advice widens, at an axial run (inside the hull)
    axial = point_on_edge_text(spec, {"a": 0.0, "b": 0.5}, runs, {"a": "cut by the search range (lower bound)"},
                               {("a", "lower")})
    assert "α_A lies on its lower search bound, which the advice below widens" in axial
    assert "outside the region" not in axial
    # inside the range but beyond the runs: a corner of the factorial square is inside, past it is not
    assert "outside the region" in point_on_edge_text(spec, {"a": 0.9, "b": 0.9}, runs, {}, set())


# --------------------------------------------------------------------------- one next step
def test_one_next_step_by_priority_and_the_generic_line_only_when_it_is_all():
    spec = _spec()
    verdicts = pd.DataFrame({"material": "m", "scenario": "s", "factor": ["a", "b"],
                             "verdict": ["bounded", "cut by the search range (upper bound)"]})
    ranking = pd.DataFrame({"observables": ["y"], "n_observables": [1], "best_subset": ["(none)"],
                            "gain_vs_best_subset_bits": [1.0], "feasible_fraction_pct": [5.0],
                            "targets_reachable": [True]})
    wave = {"scenario": "s", "count": 6, "expected_contraction": 0.4, "plausible_fraction_pct": 10.0,
            "expected_fraction_pct": 6.0, "stop": False}
    advice = material_advice(spec, verdicts, ranking=ranking, wave_value=wave)
    assert [i.kind for i in advice] == ["widen", "next_runs"]  # the generic add-observable line left out
    assert [i.decision for i in advice] == [True, False]
    alone = material_advice(spec, verdicts.assign(verdict="bounded"), ranking=ranking)
    assert [(i.kind, i.decision) for i in alone] == [("add_observable", True)]
    assert "new kind of measurement" in alone[0].text
    # the table keeps the decision, and the summary's next step is the decision with the rest as "also"
    again = StudyAdvice.from_frame(StudyAdvice(advice).to_frame().astype(str))
    assert again.items == advice and again.next_step("m") == (advice[0].text, [advice[1].text])

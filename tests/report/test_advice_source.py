"""The report takes every piece of advice from one source, the story's ``tables/advice.csv``: a results tree
whose advice rows carry marked texts, and whose other files carry advice-like text where advice used to be
read (the uncertainty summary's ranking walk-through, level 2's message with its advice, the combinations'
ridge advice), shows every marked text and none of the others."""

from __future__ import annotations

import ast
import json
from pathlib import Path

import pandas as pd

from demid.report.sections import ReportSections
from demid.story import ADVICE_COLUMNS

REPORT = Path(__file__).resolve().parents[2] / "demid" / "report"
MATERIAL = {"data": "x.csv", "design": {"type": "custom"},
            "factors": {"a": {"lower": 0.0, "upper": 1.0}, "b": {"lower": 0.0, "upper": 1.0}},
            "responses": {"y": {"target": 0.5}, "w": {"target": 2.0}},
            "scenarios": {"s": {"observables": ["y", "w"], "tolerance": 0.02}}}
#: Every kind of advice, in the order the story writes them; the first is the next step.
KINDS = ["check_target", "recalibrate", "widen", "next_runs", "add_observable", "stop", "measurement_order",
         "measurement_order"]
ELSEWHERE = "NOT-THE-STORY"


def _write_json(path: Path, data: dict) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(data), encoding="utf-8")


def _results_tree(root: Path) -> dict[str, str]:
    """One material's results tree; returns kind+position -> the marked advice text written for it."""
    tables = root / "tables"
    tables.mkdir(parents=True)
    marked = {f"{k}{i}": f"ADVICE{i}{k.replace('_', '')}" for i, k in enumerate(KINDS)}
    rows = [{"material": "m", "kind": k, "factor": "a" if k == "widen" else "", "bound": "upper" if k == "widen"
             else "", "observable": "", "text": marked[f"{k}{i}"], "decision": i == 0} for i, k in enumerate(KINDS)]
    pd.DataFrame(rows, columns=ADVICE_COLUMNS).to_csv(tables / "advice.csv", index=False)
    pd.DataFrame({"material": "m", "rank": [1, 2, 3], "observables": ["y+w", "y", "w"],
                  "information_gain_bits": [3.0, 2.0, 1.0], "feasible_fraction_pct": [5.0, 20.0, 40.0]}
                 ).to_csv(tables / "observable_ranking.csv", index=False)
    pd.DataFrame({"material": ["m"], "a": [0.5], "b": [0.25]}).to_csv(tables / "next_runs.csv", index=False)
    _write_json(root / "next_wave" / "reasons.json", {"m": "The box is the plausible set's."})
    _write_json(root / "uncertainty" / "m.json", {"advice": f"{ELSEWHERE} ranking walk-through", "notes": [],
                                                  "recommended": None, "uninformative": {}})
    level2 = {"feasible": False, "tolerance": 0.02, "best_max_error": 0.05, "best_errors": {"y": 0.05, "w": 0.01},
              "observables": ["y", "w"], "finding": "The best point misses y by 5 %.",
              "message": f"The best point misses y by 5 %. {ELSEWHERE} widen the range of a."}
    _write_json(root / "criticism" / "m.json", {"level1": {}, "level2": level2})
    _write_json(root / "combinations" / "m.json", {"sets": [], "advice": [f"{ELSEWHERE} measure w to break it"]})
    return marked


def _report_text(root: Path) -> str:
    sections = ReportSections(str(root), {"materials": {"m": MATERIAL}})
    parts = sections.summary() + sections.criticism("m") + sections.uncertainty("m") + sections.next_wave("m")
    return "\n".join(p.data for p in parts)


def test_the_report_prints_the_story_advice_and_no_advice_text_from_elsewhere(tmp_path):
    marked = _results_tree(tmp_path)
    text = _report_text(tmp_path)
    assert ELSEWHERE not in text
    missing = {k: t for k, t in marked.items() if t not in text}
    assert not missing, missing
    # each where it belongs: the next step once in the answer line and once under "Next step", the ranking's
    # walk-through after the ranking table, the next-wave advice in its section
    first = marked["check_target0"]
    assert text.count(first) == 2
    walk = text.index(marked["measurement_order6"])
    assert text.index("Which experiment next") < walk < text.index(marked["measurement_order7"])
    assert text.rindex(marked["next_runs3"]) > text.index("What to simulate next")


def _advice_reads(tree: ast.AST) -> list[str]:
    """Where a module reads a key named "advice" (``x["advice"]``, ``x.get("advice")``) or imports a function
    that writes advice text outside the story."""
    writers = {"widen_advice", "saturation_advice", "break_ridge_advice", "measurement_order",
               "next_measurement_advice"}
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Subscript) and isinstance(node.slice, ast.Constant) and node.slice.value == "advice":
            found.append(f"line {node.lineno}: [\"advice\"]")
        elif (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and node.func.attr == "get"
              and node.args and isinstance(node.args[0], ast.Constant) and node.args[0].value == "advice"):
            found.append(f"line {node.lineno}: .get(\"advice\")")
        elif isinstance(node, ast.ImportFrom):
            found += [f"line {node.lineno}: imports {a.name}" for a in node.names if a.name in writers]
    return found


def test_no_report_module_reads_advice_but_through_the_story():
    found = {p.name: _advice_reads(ast.parse(p.read_text(encoding="utf-8"))) for p in sorted(REPORT.glob("*.py"))}
    assert not {k: v for k, v in found.items() if v}, found

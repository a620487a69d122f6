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
    from demid.story.recommended import point_on_edge_text

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
                            "information_gain_bits": [1.0], "gain_vs_best_subset_bits": [1.0], "feasible_fraction_pct": [5.0],
                            "targets_reachable": [True]})
    wave = {"scenario": "s", "count": 6, "expected_contraction": 0.4, "plausible_fraction_pct": 10.0,
            "expected_fraction_pct": 6.0, "stop": False}
    advice = material_advice(spec, verdicts, ranking=ranking, wave_value=wave)
    # the generic add-observable line left out; the ranking in words follows, never a step
    assert [i.kind for i in advice] == ["widen", "next_runs", "measurement_order"]
    assert [i.decision for i in advice] == [True, False, False]
    alone = material_advice(spec, verdicts.assign(verdict="bounded"), ranking=ranking)
    assert [(i.kind, i.decision) for i in alone] == [("add_observable", True), ("measurement_order", False)]
    assert "new kind of measurement" in alone[0].text
    # the table keeps the decision, and the summary's next step is the decision with the rest as "also"
    again = StudyAdvice.from_frame(StudyAdvice(advice).to_frame().astype(str))
    assert again.items == advice and again.next_step("m") == (advice[0].text, [advice[1].text])


# --------------------------------------------------------------------------- the demo, read through
@pytest.fixture(scope="module")
def labelled_demo(tmp_path_factory):
    """The demo run with every label different from its key: mortar's scenarios, labelled by their keys'
    observables in the demo, get labels of their own."""
    import shutil

    import yaml

    from ..workflow_helpers import REPO, run_snakemake

    root = tmp_path_factory.mktemp("labelled_demo")
    shutil.copytree(REPO / "data", root / "data")
    config = yaml.safe_load((REPO / "config.yaml").read_text(encoding="utf-8"))
    scenarios = config["materials"]["mortar"]["scenarios"]
    scenarios["d15_only"]["label"] = "Largest sieve only"
    scenarios["full_sequence"]["label"] = "All three sieves"
    (root / "config.yaml").write_text(yaml.safe_dump(config, sort_keys=False, allow_unicode=True), encoding="utf-8")
    proc = run_snakemake(root, root / "config.yaml", timeout=1200)
    assert proc.returncode == 0, proc.stderr[-4000:]
    return root


def _report(root) -> str:
    return (root / "results" / "report" / "report.html").read_text(encoding="utf-8")


@pytest.mark.workflow
def test_the_demo_report_has_no_table_left_as_raw_markdown(labelled_demo):
    html = _report(labelled_demo)
    raw = RAW_ROW.findall(visible_text(html))
    assert not raw, raw[:3]
    # the residual diagnostics of every material and the appendix among the tables
    assert html.count("max |studentised residual|</th>") == 3 and "|difference|</th>" in html


@pytest.mark.workflow
def test_the_demo_says_where_its_recommended_points_sit_and_gives_one_next_step(labelled_demo):
    text = visible_text(_report(labelled_demo))
    summary = text[text.index("Summary"):text.index("Surrogate fidelity")]
    # paste's point is the lower corner of all three factors; mortar's μ_r,M is the bound the advice widens
    assert "lie on their lower search bounds; no widening is advised there" in summary
    assert "lies on its lower search bound, which the advice below widens" in summary
    assert summary.count("outside the region the design runs cover") == 3
    advice = pd.read_csv(labelled_demo / "results" / "tables" / "advice.csv")
    assert advice.groupby("material")["decision"].sum().to_dict() == {"mortar": 1, "paste": 1, "poraver": 1}
    assert "new kind of measurement or a tighter" not in summary  # another step is advised for each material
    assert summary.count("Next step:") == 2 * 3  # in the answer at the top and in each material's part


def significant_digits(printed: str) -> int:
    """Significant digits a printed number shows (an integer's trailing zeros are not counted: 4400)."""
    mantissa = printed.lstrip("−-").split("e")[0]
    digits = mantissa.replace(".", "").lstrip("0")
    return len(digits if "." in mantissa else digits.rstrip("0"))


#: Numbers that break the precision policy (demid.precision), as a reader sees them.
def precision_breaks(text: str) -> list[str]:
    import math

    number = r"[−-]?\d+(?:\.\d+)?(?:e[−+-]?\d+)?"
    found = []
    for m in re.finditer(r"(?<![\w.])\d+(?:\.\d+)?e[−-](\d+)", text):
        if int(m.group(1)) >= 9:  # floating-point round-off printed as a number
            found.append(m.group(0))
    for m in re.finditer(r"(?<![\w.])(\d+(?:\.\d+)?)\s*%", text):
        if float(m.group(1)) > 1000:  # a percentage past 10×
            found.append(m.group(0))
    found += re.findall(r"(?<![\w.])0\.0+\s*%", text)  # nothing, printed as a measured zero

    def places(s: str) -> int:
        mantissa, _, exponent = s.replace("−", "-").partition("e")
        return -(len(mantissa.split(".")[1]) if "." in mantissa else 0) + (int(exponent) if exponent else 0)

    for m in re.finditer(rf"({number})[ \t]*±[ \t]*({number})", text):
        value, error = m.group(1), m.group(2)
        size = float(error.replace("−", "-"))
        if significant_digits(error) > 2 or (size > 0 and places(value) < math.floor(math.log10(size)) - 1):
            found.append(m.group(0))  # an uncertainty past two digits, or a value finer than it
    return found


def uncertainty_column_breaks(html: str) -> list[str]:
    """Cells of a table column of uncertainties (a header with "±" or "standard error") that print more than
    two significant digits."""
    found = []
    for table in re.findall(r"<table>(.*?)</table>", html, re.S):
        heads = [visible_text(h).strip() for h in re.findall(r"<th[^>]*>(.*?)</th>", table, re.S)]
        columns = [i for i, h in enumerate(heads) if "±" in h or "standard error" in h]
        for row in re.findall(r"<tr>(.*?)</tr>", table, re.S):
            cells = [visible_text(c).strip() for c in re.findall(r"<td[^>]*>(.*?)</td>", row, re.S)]
            for i in columns:
                if i < len(cells) and re.fullmatch(r"[−-]?[\d.]+(e[−+-]?\d+)?", cells[i]):
                    if significant_digits(cells[i]) > 2:
                        found.append(f"{heads[i]}: {cells[i]}")
    return found


def test_the_precision_policy_on_known_numbers():
    from demid.precision import coordinate_text, p_text, percent_text, pm_text, uncertainty_text, value_text

    assert value_text(1.819e-12, 0.0038) == "≈ 0" and value_text(0.0002561, 5.156) == "≈ 0"
    assert value_text(50.3127, 0.5906) == "50.31" and value_text(-40.4217, 3.946) == "−40.4"
    assert pm_text(-0.000169, 0.009) == "−0.0002 ± 0.0090" and pm_text(3.0004, 0.0998) == "3.00 ± 0.10"
    assert uncertainty_text(6.222e-06) == "6.2e-06" and p_text(2.3e-13) == "< 0.0001" and p_text(0.04497) == "0.045"
    assert percent_text(969.6697) == "more than 10×" and percent_text(0.0) == "0 %"
    assert percent_text(0.01923) == "1.92 %"
    assert coordinate_text(0.075736, 0.075736, 0.924264) == "0.0757" and coordinate_text(6.21834, 2.9, 17.1) == "6.22"
    for shown in ("1.819e-12 ± 4.8e-16", "misses by 96966.97 %", "4.053 ± 6.222e-06 bit", "−0.000169 ± 0.009",
                  "0.00 % (0 times its tolerance)"):
        assert precision_breaks(shown), shown
    assert not precision_breaks("−0.0002 ± 0.0090; misses by more than 10×; 0.585 %; 6.2e-06 bit")
    table = "<table><tr><th>gain</th><th>± numerical error [bit]</th></tr><tr><td>4.053</td><td>{}</td></tr></table>"
    assert uncertainty_column_breaks(table.format("6.222e-06"))
    assert not uncertainty_column_breaks(table.format("6.2e-06"))


@pytest.mark.workflow
def test_the_demo_report_prints_numbers_to_the_precision_they_carry(labelled_demo):
    html = _report(labelled_demo)
    text = visible_text(html)
    assert precision_breaks(text) == [] and uncertainty_column_breaks(html) == []
    # the coefficient tables: estimates that cannot be told from zero say so (paste's D has two)
    assert text.count("≈ 0") >= 2


def _keys(config: dict) -> set[str]:
    """Every material, factor, response and scenario key a reader could not mistake for a word: longer than
    one character and not a word of any label."""
    labels, keys = [], set()
    for m, material in config["materials"].items():
        keys.add(m)
        labels.append(material.get("label") or "")
        for group in ("factors", "responses", "scenarios"):
            for key, entry in (material.get(group) or {}).items():
                keys.add(key)
                labels.append(entry.get("label") or "")
    words = {w for label in labels for w in re.findall(r"\w+", label)}
    return {k for k in keys if len(k) > 1 and k not in words}


@pytest.mark.workflow
def test_no_key_where_a_reader_looks(labelled_demo):
    import yaml

    config = yaml.safe_load((labelled_demo / "config.yaml").read_text(encoding="utf-8"))
    keys = _keys(config)
    assert {"mu_r", "aor_shape", "full_sequence", "d10", "mortar"} <= keys
    # a file or config path may name a key (figures/sets_mortar.svg, materials.mortar.responses.d5.target)
    paths = re.compile(r"\S*[/.]\S*")
    key = re.compile(r"(?<![\w.])(" + "|".join(sorted(map(re.escape, keys), key=len, reverse=True)) + r")(?!\w)")
    # a label's subscript read with its underscore: d<sub>5</sub> is the label d_5, a bare d5 the key
    seen = {"report": paths.sub(" ", visible_text(_report(labelled_demo).replace("<sub>", "_")))}
    for svg in sorted((labelled_demo / "results" / "figures").glob("*.svg")):  # matplotlib keeps each text
        seen[svg.name] = "\n".join(re.findall(r"<!-- (.*?) -->", svg.read_text(encoding="utf-8")))
    leaks = {where: sorted({m.group(0) for m in key.finditer(text)}) for where, text in seen.items()}
    assert {w: k for w, k in leaks.items() if k} == {}


@pytest.mark.workflow
def test_the_summary_opens_with_the_answer_and_its_terms_are_linked(labelled_demo):
    html = _report(labelled_demo)
    summary = html[html.index('id="Summary"'):]
    first_list, definitions = summary.index("<ul>"), summary.index("How to read it")
    assert first_list < definitions and summary.index("<h3") > definitions
    answers = re.findall(r"<li>(.*?)</li>", summary[first_list:summary.index("</ul>")], re.S)
    assert [visible_text(a).split(",")[0] for a in answers] == [
        "Poraver® (reconstructed data)", "Paste (reconstructed data)", "Mortar (reconstructed data)"]
    assert all("identified:" in a and "Next step:" in a for a in answers)
    ids = re.findall(r' id="([^"]+)"', html)
    assert len(ids) == len(set(ids)), sorted({i for i in ids if ids.count(i) > 1})
    assert set(re.findall(r'href="#([^"]+)"', html)) <= set(ids)
    for term in ("phi", "plausible-set", "implausibility", "q2", "aicc", "ridge", "combination"):
        assert f'id="term-{term}"' in html and f'href="#term-{term}"' in html, term


def test_the_waves_figure_counts_runs_in_integers():
    from demid.plots.waves import waves_figure

    spec = _spec()
    rows = [{"wave": w, "scenario": "s", "runs_simulated": runs, "feasible_fraction_of_omega_pct": pct,
             "factor": f, "box_lower": 0.0, "box_upper": 1.0, "lower": 0.2, "upper": 0.6}
            for w, runs, pct in ((0, 10, 20.0), (1, 11, 12.0)) for f in ("a", "b")]
    fig = waves_figure(pd.DataFrame(rows), spec)
    fig.canvas.draw()
    ticks = fig.axes[0].get_xticks()
    import matplotlib.pyplot as plt

    plt.close(fig)
    assert len(ticks) and np.allclose(ticks, np.round(ticks))


# --------------------------------------------------------------------------- a simulated study's waves
def _wave_frames(number: int, simulated: int, failed: int, analysed: int, pct: float, interval, q2: float):
    table = pd.DataFrame({"run": range(1, simulated + 1), "status": ["failed"] * failed + ["ok"] * (simulated - failed)})
    plausible = pd.DataFrame({"scenario": "s", "factor": ["a", "b"], "robust_fraction_pct": pct,
                           "robust_lower": [interval[0], 0.1], "robust_upper": [interval[1], 0.9]})
    return {"table": table, "analysed": table.head(analysed), "domain": None, "plausible": plausible,
            "statistics": pd.DataFrame({"response": ["y"], "q2": [q2]})}


def test_a_simulated_study_tells_its_waves_and_why_the_loop_stopped(tmp_path):
    """The Waves section: per wave runs simulated, failed and analysed, surrogate and Q², plausible share of Ω and
    intervals, the waves figure, and the stop line word for word as tables/advice.csv has it; the table check
    counts every simulated run, not only the last wave's."""
    import json

    from demid.report.sections import ReportSections
    from demid.waves import WaveEvidence, stop_decision, wave_summary

    spec = _spec()
    waves = [_wave_frames(1, 11, 1, 10, 1.40, (0.2, 0.7), 0.91), _wave_frames(2, 18, 1, 15, 1.55, (0.25, 0.6), 0.95),
             _wave_frames(3, 25, 2, 20, 1.44, (0.3, 0.55), 0.97)]
    decision = stop_decision(None, WaveEvidence(wave=3, max_waves=5, plausible_pct=1.44, previous_pct=1.55,
                                                surrogates={"y": {"q2": 0.97, "lof_p": 0.4, "loo_band": 0.1}}, model_limit=False,
                                                proposed=7, criticism_runs=0))
    summary = wave_summary(spec, waves, decision)
    assert [w["simulated"] for w in summary["waves"]] == [11, 18, 25] and summary["waves"][2]["failed"] == 2
    (tmp_path / "waves").mkdir()
    (tmp_path / "waves" / "summary_m.json").write_text(json.dumps(summary), encoding="utf-8")
    (tmp_path / "tables").mkdir()
    verdicts = pd.DataFrame(columns=["scenario", "factor", "verdict"])
    advice = StudyAdvice(material_advice(spec, verdicts, wave_decision=decision)).to_frame()
    stop_row = advice[advice["kind"] == "stop"]
    assert len(stop_row) == 1 and "from wave 2 to wave 3 (-7.1 %)" in stop_row["text"].iloc[0]
    advice.to_csv(tmp_path / "tables" / "advice.csv", index=False)
    (tmp_path / "validated").mkdir()
    (tmp_path / "validated" / "m.json").write_text(json.dumps({"n_runs": 20, "point_types": {"other": 20},
                                                               "warnings": []}), encoding="utf-8")
    material = {"data": "x.csv", "design": {"type": "ccd", "alpha": 1.41421, "center_runs": 3},
                "factors": {"a": {"lower": 0.0, "upper": 1.0, "label": "α_A"},
                            "b": {"lower": 0.0, "upper": 1.0, "label": "β_B"}},
                "responses": {"y": {"target": 0.5, "label": "Y_obs"}},
                "scenarios": {"s": {"observables": ["y"], "tolerance": 0.02, "label": "Y alone"}}}
    sections = ReportSections(str(tmp_path), {"materials": {"m": material}})
    text = visible_text("".join(part.data for part in sections.waves("m")))
    assert "Waves" in text and "demid simulated 25 runs in 3 waves (2 failed)" in text
    assert "Why the loop stopped after wave 3: " + stop_row["text"].iloc[0] in text
    # a loop that ended with a reason to go on (its budget spent) does not call its advice a reason to stop
    going_on = stop_decision(None, WaveEvidence(wave=3, max_waves=3, plausible_pct=1.44, previous_pct=1.80,
                                                surrogates={"y": {"q2": 0.97, "lof_p": 0.4, "loo_band": 0.37}},
                                                model_limit=False, proposed=7, criticism_runs=0))
    assert going_on["action"] == "next_runs"
    (tmp_path / "waves" / "summary_m.json").write_text(json.dumps(wave_summary(spec, waves, going_on)), encoding="utf-8")
    advice = StudyAdvice(material_advice(spec, verdicts, wave_decision=going_on)).to_frame()
    advice.to_csv(tmp_path / "tables" / "advice.csv", index=False)
    next_row = advice[advice["kind"] == going_on["action"]]
    assert len(next_row) == 1 and "the budget of 3 waves is spent" in next_row["text"].iloc[0]
    told_again = visible_text("".join(part.data for part in
                                      ReportSections(str(tmp_path), {"materials": {"m": material}}).waves("m")))
    assert "The loop ended after wave 3; what it advises: " + next_row["text"].iloc[0] in told_again
    assert "Why the loop stopped" not in told_again
    cells = re.sub(r"\s+", " ", text)
    assert "3 25 2 20 quadratic" in cells and "0.97 1.44 0.3–0.55 0.1–0.9" in cells
    assert "waves_m" in text  # the waves figure (absent here: named as missing)
    told = visible_text("".join(part.data for part in sections.material("m")[:2]))
    assert "25 runs simulated in 3 waves, 2 of them failed" in told and "table's 20 runs over the whole search range" in told and "other)" not in told

"""End to end with a stranger's study: braces in labels, an unreachable target in one of two materials,
a response without target or scenario; a likely typo or a mathtext slip stops the run in its material's job, with one line."""

from __future__ import annotations

import re

import pandas as pd
import pytest

from ..workflow_helpers import run_snakemake, sha256, written_results

pytestmark = pytest.mark.workflow

MATERIAL = """\
  {name}:
    label: "{label}"
    data: data/m.csv
    design: {{type: ccd, alpha: 1.41421, center_runs: 5}}
    factors:
      a: {{lower: 0.1, upper: 0.9, label: "a_{{1}}", unit: "{{-}}"}}
      b: {{lower: 1.0, upper: 11.0, label: "$\\\\beta$"}}
    responses:
      y1: {{target: 115, label: "y {{1}}", unit: "mm{{2}}"}}
      y2: {{target: {y2_target}}}
      y3: {{label: "no target, no scenario"}}
    scenarios:
{scenarios}
"""


def _study(study_dir, second_target):
    table = pd.read_csv(study_dir / "data" / "m.csv")
    table["y3"] = (table["y1"] - table["y2"]).round(3)
    table.to_csv(study_dir / "data" / "m.csv", index=False)
    reachable = MATERIAL.format(name="m", label="Reachable {x}", y2_target=95,
                                scenarios="      y1_only: {observables: [y1], tolerance: 0.02}\n"
                                          "      both: {observables: [y1, y2], tolerance: 0.02}")
    # every scenario of the second material needs y2 = 10 * its largest run: none can be met
    unreachable = MATERIAL.format(name="n", label="Unreachable", y2_target=second_target,
                                  scenarios="      both: {observables: [y1, y2], tolerance: 0.02}\n"
                                            "      y2_only: {observables: [y2], tolerance: 0.02}")
    config = study_dir / "stranger.yaml"
    config.write_text("grid_points: 51\nmaterials:\n" + reachable + unreachable, encoding="utf-8")
    return config


def test_unreachable_material_and_braces_still_give_every_output(study_dir):
    table = pd.read_csv(study_dir / "data" / "m.csv")
    config = _study(study_dir, round(10 * float(table["y2"].max()), 1))
    proc = run_snakemake(study_dir, config, timeout=900)
    assert proc.returncode == 0, proc.stderr[-3000:]
    results = study_dir / "results"
    assert (results / "report" / "report.html").is_file()
    for name in ("surrogate_fit", "identifiability", "observable_ranking", "information_gain", "criticism"):
        frame = pd.read_csv(results / "tables" / f"{name}.csv")
        assert set(frame["material"]) == {"m", "n"}, name
    for material in ("m", "n"):
        for figure in ("sets", "surface", "sweep", "posterior", "residuals"):
            assert (results / "figures" / f"{figure}_{material}.png").is_file()
    identifiability = pd.read_csv(results / "tables" / "identifiability.csv")
    assert (identifiability.loc[identifiability["material"] == "n", "feasible_fraction_pct"] == 0).all()
    assert set(identifiability["at_bound"]) <= {"none", "lower", "upper", "both"}
    # a set with the out-of-reach y2 target is a discrepancy, not information
    ranking = pd.read_csv(results / "tables" / "observable_ranking.csv")
    for material, rows in ranking.groupby("material"):
        reachable = ~rows["observables"].str.contains("y2") if material == "n" else rows["observables"].notna()
        assert list(rows["targets_reachable"]) == list(reachable), material
        assert rows.loc[~reachable, "information_gain_bits"].isna().all()
        assert rows.loc[reachable, "information_gain_bits"].notna().all()
        if material == "n":
            assert rows.loc[~reachable, "rank"].min() > rows.loc[reachable, "rank"].max()
    gains = pd.read_csv(results / "tables" / "information_gain.csv")
    assert gains.loc[(gains["material"] == "n") & gains["observables"].str.contains("y2"),
                     "information_gain_bits"].isna().all()
    report = (results / "report" / "report.html").read_text(encoding="utf-8")
    assert "a discrepancy between simulation and experiment" in report


def _one_line_stop(study_dir, config):
    before = sha256(study_dir / "data" / "m.csv")
    proc = run_snakemake(study_dir, config)
    output = proc.stdout + proc.stderr
    assert proc.returncode != 0 and "Traceback" not in output
    lines = [ln for ln in output.splitlines() if ln.startswith("demid: error:")]
    assert len(lines) == 1, output
    assert sha256(study_dir / "data" / "m.csv") == before
    assert not written_results(study_dir / "results")
    return lines[0]


def test_likely_typo_stops_the_workflow_in_the_material_job(study_dir):
    path = study_dir / "data" / "m.csv"
    lines = path.read_text().splitlines()
    col = lines[0].split(",").index("y1")
    cells = lines[6].split(",")
    run, original = cells[0], cells[col]
    whole, _, frac = original.partition(".")
    cells[col] = whole + frac[0] + "." + frac[1:]  # 123.456 typed as 1234.56
    lines[6] = ",".join(cells)
    path.write_text("\n".join(lines) + "\n")
    line = _one_line_stop(study_dir, study_dir / "study.yaml")
    assert line in (study_dir / "results" / "logs" / "analyse_material" / "m.log").read_text().splitlines()  # job's
    assert re.search(rf"data/m\.csv, run {run}, column 'y1': {re.escape(cells[col])} looks like "
                     rf"{re.escape(format(float(original), 'g'))} with the decimal point shifted; fix the cell, "
                     rf"or confirm the value with confirmed_values: \[\{{run: {run}, column: y1\}}\]", line), line


def test_mathtext_slip_stops_the_workflow_in_the_material_job(study_dir):
    config = study_dir / "study.yaml"
    config.write_text(config.read_text().replace("a: {lower: 0.1, upper: 0.9}",
                                                 'a: {lower: 0.1, upper: 0.9, label: "$\\\\mu_{r$"}'))
    line = _one_line_stop(study_dir, config)
    assert line in (study_dir / "results" / "logs" / "analyse_material" / "m.log").read_text().splitlines()  # job's
    assert "config key materials.m.factors.a.label" in line and "mathtext" in line

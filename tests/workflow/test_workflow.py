"""End-to-end: a self-made study through --configfile/--directory, determinism, incremental reruns."""

from __future__ import annotations

import re
import shutil

import numpy as np
import pandas as pd
import pytest

from demid.io import read_parquet

from ..workflow_helpers import planned_jobs, run_snakemake, tree_hashes, writer_contract_violations

pytestmark = pytest.mark.workflow


def _add_second_material(study_dir):
    """Copy material m as n (own table) so partial reruns can be observed."""
    shutil.copy(study_dir / "data" / "m.csv", study_dir / "data" / "n.csv")
    text = (study_dir / "study.yaml").read_text(encoding="utf-8")
    block = text[text.index("  m:\n"):]
    (study_dir / "study.yaml").write_text(text + block.replace("  m:\n", "  n:\n", 1).replace("data/m.csv", "data/n.csv"),
                                          encoding="utf-8")


def test_self_made_study_runs_and_is_byte_identical(study_dir, tmp_path):
    _add_second_material(study_dir)
    twin = tmp_path / "twin"
    shutil.copytree(study_dir, twin)
    first = run_snakemake(study_dir, study_dir / "study.yaml")
    assert first.returncode == 0, first.stderr[-3000:]
    results = study_dir / "results"
    for name in ["tables/surrogate_fit.csv", "tables/identifiability.csv", "report/report.html",
                 "validated/m.parquet", "fits/m.parquet", "scenarios/n.parquet",
                 "figures/sets_m.png", "figures/surface_n.png"]:
        assert (results / name).is_file(), name
    fit = pd.read_csv(results / "tables" / "surrogate_fit.csv")
    assert list(fit.columns) == ["material", "response", "n_runs", "r2", "adj_r2", "rmse", "resid_std", "q2",
                                 "lof_f", "lof_p"]
    assert len(fit) == 4 and (fit["r2"] > 0.95).all()
    ident = pd.read_csv(results / "tables" / "identifiability.csv")
    assert list(ident.columns[:9]) == ["material", "scenario", "observables", "tolerance", "feasible_fraction_pct",
                                       "factor", "lower", "upper", "width"]
    both = ident[(ident["material"] == "m") & (ident["scenario"] == "both")]
    one = ident[(ident["material"] == "m") & (ident["scenario"] == "y1_only")]
    assert both["feasible_fraction_pct"].iloc[0] <= one["feasible_fraction_pct"].iloc[0]
    # Evaluated on the configured 101 x 101 grid (admissible nodes / node fraction = all nodes);
    # the dense predictions are not stored.
    sets = read_parquet(results / "scenarios" / "m.parquet").drop_duplicates("scenario")
    sets = sets[sets["n_admissible_nodes"] > 0]
    nodes = sets["n_admissible_nodes"] / (sets["node_fraction_pct"] / 100)
    assert len(sets) and nodes.to_numpy() == pytest.approx(101**2) and not (results / "grid").exists()

    # Every output keeps the writers' contracts, which is what makes reruns on another machine or
    # library version byte-identical: sorted JSON keys, no software/time metadata in PNG or parquet.
    assert len(list(results.rglob("*.json"))) and len(list(results.rglob("*.png")))
    assert writer_contract_violations(results) == []

    # A second clean run elsewhere gives byte-identical tables, parquet, JSON, PNG, SVG and the report.
    second = run_snakemake(twin, twin / "study.yaml")
    assert second.returncode == 0, second.stderr[-3000:]
    assert tree_hashes(results) == tree_hashes(twin / "results")

    # A no-op rerun schedules nothing.
    noop = run_snakemake(study_dir, study_dir / "study.yaml", "-n")
    assert noop.returncode == 0
    assert planned_jobs(noop.stdout) == {}, noop.stdout

    # Editing one value of n's table reruns only n's chain plus the cross-material outputs.
    path = study_dir / "data" / "n.csv"
    table = pd.read_csv(path)
    table.loc[0, "y1"] = table.loc[0, "y1"] + 0.5
    table.to_csv(path, index=False)
    edit = run_snakemake(study_dir, study_dir / "study.yaml", "-n")
    jobs = planned_jobs(edit.stdout)
    assert jobs.get("analyse_material") == 1, edit.stdout
    assert re.search(r"material=n\b", edit.stdout)
    assert not re.search(r"material=m\b", edit.stdout), edit.stdout
    assert jobs.get("summary_tables") == 1 and jobs.get("report") == 1

    # Editing one target in the config reruns that material: Snakemake records plain params only, not the
    # spec object, so an edited target left stale sets behind.
    config = (study_dir / "study.yaml").read_text(encoding="utf-8")
    assert config.count("y2: {target: 95}") == 2  # premise: m and n both hold it, m's first
    (study_dir / "study.yaml").write_text(config.replace("y2: {target: 95}", "y2: {target: 96}", 1), encoding="utf-8")
    edit = run_snakemake(study_dir, study_dir / "study.yaml", "-n")
    assert planned_jobs(edit.stdout).get("analyse_material") == 2, edit.stdout  # m for its target, n for its cell
    assert re.search(r"material=m\b", edit.stdout), edit.stdout


def test_failed_run_and_unreachable_target_complete(study_dir):
    table = pd.read_csv(study_dir / "data" / "m.csv")
    table["status"] = "ok"
    table.loc[table["run"] == 2, ["y1", "y2", "status"]] = [np.nan, np.nan, "failed"]  # no value left behind
    table.to_csv(study_dir / "data" / "m.csv", index=False)
    config = (study_dir / "study.yaml").read_text(encoding="utf-8").replace("y2: {target: 95}", "y2: {target: 500}")
    (study_dir / "study.yaml").write_text(config, encoding="utf-8")
    proc = run_snakemake(study_dir, study_dir / "study.yaml", "results/tables/identifiability.csv",
                         "results/validated/m.json", "results/report/report.html")
    assert proc.returncode == 0, proc.stderr[-3000:]
    ident = pd.read_csv(study_dir / "results" / "tables" / "identifiability.csv")
    both = ident[ident["scenario"] == "both"]
    assert (both["feasible_fraction_pct"] == 0).all() and both["lower"].isna().all()
    scenarios = read_parquet(study_dir / "results" / "scenarios" / "m.parquet")
    assert (scenarios.loc[scenarios["scenario"] == "both", "best_max_rel_error"] > 0.5).all()
    assert list(ident.columns) == ["material", "scenario", "observables", "tolerance", "feasible_fraction_pct",
                                   "factor", "lower", "upper", "width", "at_bound"]
    assert (both["at_bound"] == "none").all()  # an empty set reaches no bound
    summary = (study_dir / "results" / "validated" / "m.json").read_text(encoding="utf-8")
    assert '"y1": [\n      2\n    ]' in summary and "failed" in summary
    report = (study_dir / "results" / "report" / "report.html").read_text(encoding="utf-8")
    assert "no point of the domain meets every target" in report
    # the summary recommends no parameter set and shows no empty intervals
    assert "No parameter set meets every target." in report and "Recommended parameter set" not in report
    assert "nan, nan" not in report and "so there are no admissible intervals" in report
    stats = read_parquet(study_dir / "results" / "fits" / "m_statistics.parquet").set_index("response")
    assert stats.loc["y1", "n_runs"] == 12 and stats.loc["y2", "n_runs"] == 12


def test_four_factor_study_uses_sobol_points(tmp_path):
    """Above three factors a grid is out of reach: Sobol points, fractions with a confidence interval."""
    from ..helpers import make_ccd_table

    def responses(x):
        a, b, c, d = x.T
        return {"y": 50 + 10 * a + 4 * b - 3 * c + 2 * d + 6 * a * b + 5 * a**2,
                "z": 20 + 2 * a - 5 * b + 3 * c * d + 2 * d**2}

    table = make_ccd_table(responses, [0] * 4, [1] * 4, alpha=2.0, center_runs=7, noise=0.2, seed=5, decimals=4)
    table = table.rename(columns={"x1": "a", "x2": "b", "x3": "c", "x4": "d"})
    (tmp_path / "data").mkdir()
    table.to_csv(tmp_path / "data" / "four.csv", index=False)
    (tmp_path / "four.yaml").write_text(
        "sobol_points: 4096\n"
        "materials:\n"
        "  four:\n"
        "    data: data/four.csv\n"
        "    design: {type: ccd, alpha: 2.0, center_runs: 7}\n"
        "    factors: {a: {lower: 0, upper: 1}, b: {lower: 0, upper: 1}, c: {lower: 0, upper: 1},"
        " d: {lower: 0, upper: 1}}\n"
        "    responses: {y: {target: 60}, z: {target: 20}}\n"
        "    scenarios:\n"
        "      y_only: {observables: [y], tolerance: 0.05}\n"
        "      both: {observables: [y, z], tolerance: 0.05}\n",
        encoding="utf-8")
    proc = run_snakemake(tmp_path, tmp_path / "four.yaml")
    assert proc.returncode == 0, proc.stderr[-4000:]
    ident = pd.read_csv(tmp_path / "results" / "tables" / "identifiability.csv")
    fractions = ident.drop_duplicates("scenario").set_index("scenario")["feasible_fraction_pct"]
    assert 0 < fractions["both"] <= fractions["y_only"] < 100
    sets = read_parquet(tmp_path / "results" / "scenarios" / "four.parquet").drop_duplicates("scenario")
    assert len(sets) == 2 and (sets["n_admissible_nodes"] / (sets["node_fraction_pct"] / 100)).to_numpy() == pytest.approx(4096)
    # Level 2 reads the same set as identifiability (it was left out above three factors, so "widen the
    # range" was said by the summary but not by level 2).
    import json

    level2 = json.loads((tmp_path / "results" / "criticism" / "four.json").read_text(encoding="utf-8"))["level2"]
    both = ident[ident["scenario"] == "both"].set_index("factor")["at_bound"].to_dict()
    assert level2["feasible"] and level2["set_at_bound"] == both, (level2["set_at_bound"], both)

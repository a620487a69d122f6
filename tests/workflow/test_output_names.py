"""Each output of the workflow is named once: the material job's rule outputs and the parts of its
result read one table (demid.steps.MATERIAL_OUTPUTS), and everything a run writes stays under the
study's results_dir (its logs and benchmarks too), so a study run from its own folder, the Kratos
example included, changes none of the study's own files."""

from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

import pytest

from demid.schema import load_yaml, validate_schema
from demid.spec import MaterialSpec
from demid.steps import MATERIAL_OUTPUTS, PARETO_OUTPUTS, material_step, output_table

from ..workflow_helpers import REPO, run_snakemake


def _spec(study_dir: Path, pareto: bool) -> MaterialSpec:
    config = validate_schema(load_yaml(study_dir / "study.yaml"))
    if pareto:
        config["materials"]["m"]["pareto"] = {"error_of": "y1", "minimise": "y2", "max_error": 0.05}
        config = validate_schema(config)
    return MaterialSpec.from_config("m", config)


@pytest.mark.parametrize("pareto", [False, True])
def test_the_material_job_fills_exactly_the_outputs_of_the_table(study_dir, pareto, monkeypatch):
    """The names the job's result fills are the rule's output names (the SVGs are written beside their
    PNGs): a part renamed on one side only fails here, not at the end of a full run."""
    monkeypatch.chdir(study_dir)
    spec = _spec(study_dir, pareto)
    result = material_step(spec, spec.data, z=2.0, tolerances=[0.01, 0.05])
    expected = {name for name in output_table(pareto) if not name.endswith("_svg")}
    assert result.names() == expected
    assert set(PARETO_OUTPUTS) <= result.names() if pareto else not set(PARETO_OUTPUTS) & result.names()


def test_every_figure_of_the_table_has_a_caption_and_an_svg_twin():
    """A figure (PNG) appears in Snakemake's report with a caption file that exists, and its SVG is an
    output of the same job."""
    table = output_table(pareto=True)
    for name, entry in {**MATERIAL_OUTPUTS, **PARETO_OUTPUTS}.items():
        if entry.path.endswith(".png"):
            assert entry.category and (REPO / "workflow" / "report" / entry.caption).is_file(), name
            assert table[name.removesuffix("_figure") + "_svg"].path == entry.path.removesuffix(".png") + ".svg"


def _planned_files(workdir: Path, configfile: Path) -> dict[str, list[str]]:
    """Every output, log and benchmark file a forced dry run of the study would write, by kind."""
    proc = run_snakemake(workdir, configfile, "-n", "-F")
    assert proc.returncode == 0, proc.stderr[-3000:]
    files: dict[str, list[str]] = {"output": [], "log": [], "benchmark": []}
    for line in (proc.stdout + proc.stderr).splitlines():
        key, _, value = line.strip().partition(": ")
        if key in files and value:
            files[key] += [v.strip() for v in value.split(",") if v.strip()]
    return files


def test_a_study_run_from_its_own_folder_writes_only_under_its_results_dir(study_dir):
    """Logs and benchmarks go to <results_dir>/logs and <results_dir>/benchmarks, beside the results,
    not into the study's folder."""
    config = study_dir / "study.yaml"
    config.write_text(config.read_text(encoding="utf-8") + "results_dir: out\n", encoding="utf-8")
    files = _planned_files(study_dir, config)
    assert files["log"] and files["benchmark"]
    assert all(f.startswith("out/logs/") for f in files["log"]), files["log"]
    assert all(f.startswith("out/benchmarks/") for f in files["benchmark"]), files["benchmark"]
    assert all(f.startswith("out/") for f in files["output"]), files["output"]


def _git(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run(["git", "-C", str(REPO), *args], capture_output=True, text=True)


@pytest.mark.skipif(shutil.which("git") is None or _git("rev-parse").returncode != 0,
                    reason="needs the repository's git checkout")
@pytest.mark.parametrize("configfile", ["config_tables.yaml", "config.yaml"])
def test_the_kratos_example_writes_no_tracked_file(tmp_path, configfile):
    """The example's quick analysis (and its simulated study) writes only files git ignores: none of
    the example's committed files is touched by running it."""
    example = REPO / "examples" / "dem_heap"
    copy = tmp_path / "dem_heap"
    shutil.copytree(example, copy, ignore=shutil.ignore_patterns("results", ".snakemake"))
    files = _planned_files(copy, copy / configfile)
    written = sorted({f for kind in files.values() for f in kind})
    assert written
    paths = [os.path.relpath(example / f, REPO) for f in written]
    tracked = set(_git("ls-files", "examples/dem_heap").stdout.split())
    assert not [p for p in paths if p in tracked or any(t.startswith(p + "/") for t in tracked)]
    ignored = set(_git("check-ignore", "--no-index", *paths).stdout.split())
    assert sorted(set(paths) - ignored) == []

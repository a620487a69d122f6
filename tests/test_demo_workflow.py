"""The demo study as a user runs it (coarse grids to keep the suite fast): a one-cell edit of the mortar
table reruns only mortar jobs and the cross-material outputs; a no-op rerun schedules nothing."""

from __future__ import annotations

import re
import shutil

import pytest

from .workflow_helpers import REPO, planned_jobs, run_snakemake

pytestmark = pytest.mark.workflow

COARSE = ["--config", "grid_points=101", "grid_points_3d=21"]


@pytest.fixture(scope="module")
def demo_copy(tmp_path_factory):
    root = tmp_path_factory.mktemp("demo")
    shutil.copytree(REPO / "data", root / "data")
    shutil.copy(REPO / "config.yaml", root / "config.yaml")
    proc = run_snakemake(root, root / "config.yaml", *COARSE, timeout=900)
    assert proc.returncode == 0, proc.stderr[-4000:]
    return root


def test_noop_rerun_schedules_nothing(demo_copy):
    proc = run_snakemake(demo_copy, demo_copy / "config.yaml", "-n", *COARSE)
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert planned_jobs(proc.stdout) == {}, proc.stdout[-3000:]


def test_mortar_edit_reruns_only_mortar_and_summaries(demo_copy):
    path = demo_copy / "data" / "ccd" / "mortar.csv"
    lines = path.read_text(encoding="utf-8").splitlines()
    header = lines[0].split(",")
    col = header.index("d15")
    cells = lines[1].split(",")
    cells[col] = f"{float(cells[col]) + 0.01:.4f}"
    lines[1] = ",".join(cells)
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    proc = run_snakemake(demo_copy, demo_copy / "config.yaml", "-n", *COARSE)
    assert proc.returncode == 0, proc.stderr[-2000:]
    jobs = planned_jobs(proc.stdout)
    assert jobs.get("validate_and_fit") == 1, proc.stdout[-3000:]
    assert re.search(r"material=mortar\b", proc.stdout)
    assert not re.search(r"material=(poraver|paste)\b", proc.stdout), proc.stdout[-3000:]
    assert jobs.get("report") == 1

"""The demo study as a user runs it (the test session's shared run, copied): a one-cell edit of the mortar
table reruns only mortar jobs and the cross-material outputs; a no-op rerun schedules nothing."""

from __future__ import annotations

import re

import pytest

from ..workflow_helpers import planned_jobs, run_snakemake

pytestmark = pytest.mark.workflow



def test_noop_rerun_schedules_nothing(demo_copy):
    proc = run_snakemake(demo_copy, demo_copy / "config.yaml", "-n")
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
    proc = run_snakemake(demo_copy, demo_copy / "config.yaml", "-n")
    assert proc.returncode == 0, proc.stderr[-2000:]
    jobs = planned_jobs(proc.stdout)
    assert jobs.get("analyse_material") == 1 and "analyse_material_with_pareto" not in jobs, proc.stdout[-3000:]
    assert re.search(r"material=mortar\b", proc.stdout)
    assert not re.search(r"material=(poraver|paste)\b", proc.stdout), proc.stdout[-3000:]
    assert jobs.get("report") == 1

"""Shared fixtures: small synthetic CCD studies written to temporary folders, and the demo study
run once per session."""

from __future__ import annotations

import fcntl
import shutil
import sys

import pytest

from .helpers import make_ccd_table


@pytest.fixture
def study_dir(tmp_path):
    """A self-made two-factor study (own config and table) in a temporary folder."""

    def responses(x):
        a, b = x[:, 0], x[:, 1]
        return {"y1": 100 + 20 * a - 2 * b + 10 * a**2 + 0.5 * a * b,
                "y2": 80 + 5 * a + 3 * b - 0.1 * b**2}

    table = make_ccd_table(responses, [0.1, 1.0], [0.9, 11.0], noise=0.3, seed=3, decimals=3)
    table = table.rename(columns={"x1": "a", "x2": "b"})
    (tmp_path / "data").mkdir()
    table.to_csv(tmp_path / "data" / "m.csv", index=False)
    (tmp_path / "study.yaml").write_text(
        "grid_points: 101\n"
        "materials:\n"
        "  m:\n"
        "    data: data/m.csv\n"
        "    design: {type: ccd, alpha: 1.41421, center_runs: 5}\n"
        "    factors:\n"
        "      a: {lower: 0.1, upper: 0.9}\n"
        "      b: {lower: 1.0, upper: 11.0}\n"
        "    responses:\n"
        "      y1: {target: 115}\n"
        "      y2: {target: 95}\n"
        "    reference_point: {a: 0.5, b: 6}\n"
        "    scenarios:\n"
        "      y1_only: {observables: [y1], tolerance: 0.02}\n"
        "      both: {observables: [y1, y2], tolerance: 0.02}\n",
        encoding="utf-8",
    )
    return tmp_path


@pytest.fixture(scope="session")
def demo_run(tmp_path_factory, request):
    """The demo study run once per test session exactly as a user runs it (configured grids), in a
    temporary folder.  Read it, never edit it: tests that change inputs work on :func:`demo_copy`.

    With parallel workers (pytest-xdist) every worker has a session of its own; the first to ask runs
    the demo under a file lock in the folder the workers share, the others wait for it and read the
    same run (a demo run costs more than any test that reads it)."""
    if not hasattr(request.config, "workerinput"):  # no parallel workers
        return _run_demo(tmp_path_factory.mktemp("demo_run"))
    shared = tmp_path_factory.getbasetemp().parent
    root, done = shared / "demo_run", shared / "demo_run.done"
    with open(shared / "demo_run.lock", "w", encoding="utf-8") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        try:
            if not done.exists():
                shutil.rmtree(root, ignore_errors=True)
                root.mkdir()
                _run_demo(root)
                done.touch()
        finally:
            fcntl.flock(lock, fcntl.LOCK_UN)
    return root


def _run_demo(root):
    from .workflow_helpers import REPO, run_snakemake

    shutil.copytree(REPO / "data", root / "data")
    shutil.copy(REPO / "config.yaml", root / "config.yaml")
    proc = run_snakemake(root, root / "config.yaml", timeout=1200)
    assert proc.returncode == 0, proc.stderr[-4000:]
    return root


@pytest.fixture(scope="module")
def demo_copy(demo_run, tmp_path_factory):
    """A private copy of the finished demo run (inputs, results and Snakemake's records, with their
    modification times), for tests that edit inputs and ask what would rerun."""
    root = tmp_path_factory.mktemp("demo_copy") / "study"
    shutil.copytree(demo_run, root, symlinks=True)
    return root


@pytest.fixture(autouse=True)
def _figures_closed():
    """Every test leaves no figure open: pyplot keeps them, and the 21st open figure warns (an error here)."""
    yield
    pyplot = sys.modules.get("matplotlib.pyplot")
    if pyplot is not None:
        pyplot.close("all")

"""Executing the report notebook (papermill) and rendering it as HTML."""

from __future__ import annotations

import os
import sys
from contextlib import contextmanager
from pathlib import Path


@contextmanager
def _kernel_stderr_to_log():
    """Send the kernel process's stderr (it inherits file descriptor 2) where ``sys.stderr`` points,
    i.e. the rule's log: ipykernel's start-up warnings are no business of the console."""
    try:
        target = sys.stderr.fileno()
    except (AttributeError, OSError, ValueError):
        yield
        return
    if target == 2:
        yield
        return
    sys.stderr.flush()
    saved = os.dup(2)
    os.dup2(target, 2)
    try:
        yield
    finally:
        os.dup2(saved, 2)
        os.close(saved)


def execute_report(notebook: str | Path, output: str | Path, *, results_dir: str, config_json: str) -> None:
    """Run the report notebook with papermill (the kernel is this Python)."""
    import papermill as pm

    Path(output).parent.mkdir(parents=True, exist_ok=True)
    with _kernel_stderr_to_log():
        _execute(pm, notebook, output, results_dir, config_json)
    _drop_run_details(output)


#: Per-run details papermill and the kernel record: clock times, durations, and the path the notebook was
#: read from (a temporary copy under Snakemake).  Dropped, so that two clean runs write the same notebook.
_TIMES = ("start_time", "end_time", "duration")


def _drop_run_details(path: str | Path) -> None:
    import nbformat

    from ..io import atomic_path

    nb = nbformat.read(str(path), as_version=4)
    run = nb.metadata.get("papermill", {})
    for key in _TIMES:
        run.pop(key, None)
    if "input_path" in run:
        run["input_path"] = Path(run["input_path"]).name
    for cell in nb.cells:
        cell.metadata.pop("execution", None)
        for key in _TIMES:
            cell.metadata.get("papermill", {}).pop(key, None)
        if "injected-parameters" in cell.metadata.get("tags", []):
            cell["id"] = "injected-parameters"  # papermill gives the cell it inserts a random id
    with atomic_path(path) as tmp:
        nbformat.write(nb, str(tmp))


def _execute(pm, notebook, output, results_dir, config_json) -> None:
    pm.execute_notebook(str(notebook), str(output), parameters={"results_dir": results_dir,
                                                                  "config_json": config_json},
                        kernel_name="python3", progress_bar=False, log_output=False, cwd=str(Path.cwd()),
                        # every output is in by then: a graceful shutdown only waits for the kernel to exit
                        shutdown_kernel="immediate")


def render_html(notebook: str | Path, output: str | Path) -> None:
    """Self-contained HTML with code cells hidden: the reader sees text, tables and figures."""
    import nbformat
    from nbconvert import HTMLExporter

    from ..io import atomic_path

    exporter = HTMLExporter(exclude_input=True, exclude_input_prompt=True, exclude_output_prompt=True)
    nb = nbformat.read(str(notebook), as_version=4)
    for cell in nb.cells:
        if "injected-parameters" in cell.get("metadata", {}).get("tags", []):
            # papermill gives the cell it inserts a random id, which the HTML carries: a fixed one
            # keeps two clean runs' reports byte-identical
            cell["id"] = "injected-parameters"
    body, _ = exporter.from_notebook_node(nb, resources={"metadata": {"name": "demid — identifiability report"}})
    with atomic_path(output) as tmp:
        Path(tmp).write_text(body, encoding="utf-8")

"""Executing the report notebook (nbclient, parameters injected as papermill does) and rendering it as HTML."""

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
    """Run the report notebook in a fresh kernel, its parameters injected as papermill injects them
    (a cell tagged ``injected-parameters`` after the one tagged ``parameters``).  nbclient runs it:
    papermill's own import pulls in cloud-storage clients, more than a second of start-up."""
    import nbformat
    from nbclient import NotebookClient

    from ..io import atomic_path

    nb = with_parameters(nbformat.read(str(notebook), as_version=4),
                         {"results_dir": results_dir, "config_json": config_json})
    with _kernel_stderr_to_log():
        NotebookClient(nb, kernel_name="python3", resources={"metadata": {"path": str(Path.cwd())}}).execute()
    with atomic_path(output) as tmp:
        nbformat.write(nb, str(tmp))


def with_parameters(nb, parameters: dict):
    """``nb`` with a code cell assigning ``parameters`` (as Python literals) after the cell tagged
    ``parameters`` (first, if none is), replacing an earlier injected cell."""
    import json

    import nbformat

    cells = [c for c in nb.cells if "injected-parameters" not in c.get("metadata", {}).get("tags", [])]
    tagged = [i for i, c in enumerate(cells) if "parameters" in c.get("metadata", {}).get("tags", [])]
    source = "# Parameters\n" + "".join(f"{name} = {json.dumps(value)}\n" for name, value in parameters.items())
    cell = nbformat.v4.new_code_cell(source, metadata={"tags": ["injected-parameters"]})
    cell["id"] = "injected-parameters"  # papermill's is random, and the HTML carries it: two runs would differ
    cells.insert(tagged[0] + 1 if tagged else 0, cell)
    nb.cells = cells
    return nb


def render_html(notebook: str | Path, output: str | Path) -> None:
    """Self-contained HTML with code cells hidden: the reader sees text, tables and figures."""
    import nbformat
    from nbconvert import HTMLExporter

    from ..io import atomic_path

    exporter = HTMLExporter(exclude_input=True, exclude_input_prompt=True, exclude_output_prompt=True)
    nb = nbformat.read(str(notebook), as_version=4)
    body, _ = exporter.from_notebook_node(nb, resources={"metadata": {"name": "demid — identifiability report"}})
    with atomic_path(output) as tmp:
        Path(tmp).write_text(body, encoding="utf-8")

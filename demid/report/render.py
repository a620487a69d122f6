"""Executing the report notebook (papermill) and rendering it as HTML."""

from __future__ import annotations

from pathlib import Path


def execute_report(notebook: str | Path, output: str | Path, *, results_dir: str, config_json: str) -> None:
    """Run the report notebook with papermill (the kernel is this Python)."""
    import papermill as pm

    Path(output).parent.mkdir(parents=True, exist_ok=True)
    pm.execute_notebook(str(notebook), str(output), parameters={"results_dir": results_dir,
                                                                  "config_json": config_json},
                        kernel_name="python3", progress_bar=False, log_output=False, cwd=str(Path.cwd()))


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

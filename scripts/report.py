"""Snakemake script: execute the report notebook with papermill and render it as HTML."""

import sys
from pathlib import Path

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.report import execute_report, render_html  # noqa: E402

out = snakemake.output  # noqa: F821
execute_report(snakemake.input.notebook, out.notebook, results_dir=str(Path(out.notebook).parent.parent),  # noqa: F821
               config_json=snakemake.params.config_json)  # noqa: F821
render_html(out.notebook, out.html)

"""Snakemake script: render the executed report notebook as a self-contained HTML page."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.report import render_html  # noqa: E402

render_html(snakemake.input.notebook, snakemake.output.html)  # noqa: F821

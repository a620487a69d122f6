"""Snakemake script: execute the report notebook with papermill."""

import sys
from pathlib import Path

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.report import execute_report  # noqa: E402

execute_report(snakemake.input.notebook, snakemake.output.notebook,  # noqa: F821
               results_dir=str(Path(snakemake.output.notebook).parent.parent), config_json=snakemake.params.config_json)  # noqa: F821

"""Snakemake script: the cross-material tables (Table 2, Table 3, transcription, uncertainty, criticism)."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.io import write_csv  # noqa: E402
from demid.report import summary_tables  # noqa: E402
from demid.report.columns import columns_table  # noqa: E402

inputs = {name: dict(zip(snakemake.params.materials, files))  # noqa: F821
          for name, files in snakemake.input.items()}  # noqa: F821
write_csv(columns_table(snakemake.params.pareto_factors, snakemake.params.next_wave),  # noqa: F821
          snakemake.output.columns)  # noqa: F821
for name, table in summary_tables(inputs).items():
    write_csv(table, getattr(snakemake.output, name))  # noqa: F821

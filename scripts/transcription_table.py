"""Snakemake script: tables/transcription_check.csv — published statistics against the refit."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.io import write_csv  # noqa: E402
from demid.report import stack_material_tables  # noqa: E402

files = dict(zip(snakemake.params.materials, snakemake.input.checks))  # noqa: F821
table = stack_material_tables(files)
columns = ["material", "response", "statistic", "published", "reproduced", "agrees", "printed"]
write_csv(table.reindex(columns=columns), snakemake.output.table)  # noqa: F821

"""Snakemake script: Table 2 — fit statistics of every material x response."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.io import write_csv  # noqa: E402
from demid.report import surrogate_fit_table  # noqa: E402

table = surrogate_fit_table(dict(zip(snakemake.params.materials, snakemake.input.statistics)))  # noqa: F821
write_csv(table, snakemake.output.table)  # noqa: F821

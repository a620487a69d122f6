"""Snakemake script: Table 3 in long form — fractions and spans of every scenario."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.io import write_csv  # noqa: E402
from demid.report import identifiability_table  # noqa: E402

write_csv(identifiability_table(snakemake.input.scenarios), snakemake.output.table)  # noqa: F821

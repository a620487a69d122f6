"""Snakemake script: tables/criticism.csv (one row per finding) and tables/calibration_residuals.csv."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.io import write_csv  # noqa: E402
from demid.report import stack_material_tables  # noqa: E402

for name in ("findings", "calibration"):
    files = dict(zip(snakemake.params.materials, getattr(snakemake.input, name)))  # noqa: F821
    write_csv(stack_material_tables(files), getattr(snakemake.output, name))  # noqa: F821

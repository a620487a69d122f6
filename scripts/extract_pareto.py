"""Snakemake script: non-dominated grid points (observable error vs second objective)."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.io import read_parquet, write_csv, write_parquet  # noqa: E402
from demid.pareto import pareto_analysis  # noqa: E402

cfg = snakemake.params.material_cfg  # noqa: F821
par = cfg["pareto"]
result = pareto_analysis(read_parquet(snakemake.input.grid), list(cfg["factors"]), par["error_of"],  # noqa: F821
                         cfg["responses"][par["error_of"]]["target"], par["minimise"], par["max_error"])
write_parquet(result.front, snakemake.output.front)  # noqa: F821
write_csv(result.to_frame(), snakemake.output.table)  # noqa: F821

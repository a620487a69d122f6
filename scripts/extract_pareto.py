"""Snakemake script: non-dominated grid points (observable error vs second objective) and their figure."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.io import read_parquet, save_figure, write_csv  # noqa: E402
from demid.pareto import pareto_analysis  # noqa: E402
from demid.plots import pareto_figure  # noqa: E402

cfg = snakemake.params.material_cfg  # noqa: F821
par = cfg["pareto"]
target = cfg["responses"][par["error_of"]]["target"]
grid = read_parquet(snakemake.input.grid)  # noqa: F821
result = pareto_analysis(grid, list(cfg["factors"]), par["error_of"], target, par["minimise"], par["max_error"])
write_csv(result.to_frame(), snakemake.output.table)  # noqa: F821
fig = pareto_figure(grid, result.front, par["error_of"], target, par["minimise"], par["max_error"],
                    cfg["responses"], cfg.get("label") or snakemake.wildcards.material)  # noqa: F821
save_figure(fig, snakemake.output.figure)  # noqa: F821

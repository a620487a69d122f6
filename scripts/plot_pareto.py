"""Snakemake script: objective cloud and Pareto front (paper Fig. 4)."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.io import read_parquet, save_figure  # noqa: E402
from demid.plots import pareto_figure  # noqa: E402

cfg = snakemake.params.material_cfg  # noqa: F821
par = cfg["pareto"]
fig = pareto_figure(read_parquet(snakemake.input.grid), read_parquet(snakemake.input.front),  # noqa: F821
                    par["error_of"], cfg["responses"][par["error_of"]]["target"], par["minimise"],
                    par["max_error"], cfg["responses"], cfg.get("label") or snakemake.wildcards.material)  # noqa: F821
save_figure(fig, snakemake.output.figure)  # noqa: F821

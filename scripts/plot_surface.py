"""Snakemake script: response-surface contour panels with design runs and target levels."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.admissibility import Domain  # noqa: E402
from demid.io import read_parquet, save_figure  # noqa: E402
from demid.plots import surface_figure  # noqa: E402

cfg = snakemake.params.material_cfg  # noqa: F821
fig = surface_figure(Domain.from_config(cfg["factors"]), cfg["factors"], cfg["responses"],
                     read_parquet(snakemake.input.grid), snakemake.params.grid_points,  # noqa: F821
                     read_parquet(snakemake.input.table), cfg.get("label") or snakemake.wildcards.material)  # noqa: F821
save_figure(fig, snakemake.output.figure)  # noqa: F821

"""Snakemake script: admissible-set overlay (paper Figs. 3 and 5) and response-surface panels."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.io import read_parquet, save_figure  # noqa: E402
from demid.plots import material_figures  # noqa: E402
from demid.surrogate import surrogates_from_frame  # noqa: E402

cfg = snakemake.params.material_cfg  # noqa: F821
surrogates = surrogates_from_frame(read_parquet(snakemake.input.fits), list(cfg["factors"]))  # noqa: F821
figures = material_figures(surrogates, cfg, snakemake.params.grid_points,  # noqa: F821
                           read_parquet(snakemake.input.grid), read_parquet(snakemake.input.table),  # noqa: F821
                           cfg.get("label") or snakemake.wildcards.material)  # noqa: F821
for name, fig in figures.items():
    save_figure(fig, getattr(snakemake.output, name))  # noqa: F821

"""Snakemake script: surrogate predictions on the evaluation grid over the search domain."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.admissibility import Domain, predict_grid  # noqa: E402
from demid.io import read_parquet, write_parquet  # noqa: E402
from demid.surrogate import surrogates_from_frame  # noqa: E402

cfg = snakemake.params.material_cfg  # noqa: F821
surrogates = surrogates_from_frame(read_parquet(snakemake.input.fits), list(cfg["factors"]))  # noqa: F821
grid = predict_grid(surrogates, Domain.from_config(cfg["factors"]), snakemake.params.grid_points)  # noqa: F821
write_parquet(grid, snakemake.output.grid)  # noqa: F821

"""Snakemake script: admissible sets, feasible fractions and spans of every scenario (eq. 2-4)."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.admissibility import evaluate_scenarios  # noqa: E402
from demid.io import read_parquet, write_parquet  # noqa: E402
from demid.surrogate import surrogates_from_frame  # noqa: E402

cfg = snakemake.params.material_cfg  # noqa: F821
surrogates = surrogates_from_frame(read_parquet(snakemake.input.fits), list(cfg["factors"]))  # noqa: F821
grid = read_parquet(snakemake.input.grid)  # noqa: F821
table, _ = evaluate_scenarios(surrogates, cfg, snakemake.params.grid_points, grid)  # noqa: F821
table.insert(0, "material", snakemake.wildcards.material)  # noqa: F821
write_parquet(table, snakemake.output.scenarios)  # noqa: F821

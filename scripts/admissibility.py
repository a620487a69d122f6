"""Snakemake script: surrogate predictions on the grid over Omega, then every scenario's admissible set
(feasible fraction and spans, eq. 2-4) and their overlay figure (paper Figs. 3 and 5)."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.admissibility import Domain, evaluate_scenarios, predict_grid  # noqa: E402
from demid.io import read_parquet, save_figure, write_parquet  # noqa: E402
from demid.plots import sets_figure  # noqa: E402
from demid.surrogate import surrogates_from_frame  # noqa: E402

cfg = snakemake.params.material_cfg  # noqa: F821
n = snakemake.params.grid_points  # noqa: F821
domain = Domain.from_config(cfg["factors"])
surrogates = surrogates_from_frame(read_parquet(snakemake.input.fits), list(cfg["factors"]))  # noqa: F821
grid = predict_grid(surrogates, domain, n)
write_parquet(grid, snakemake.output.grid)  # noqa: F821
table, sets = evaluate_scenarios(surrogates, cfg, n, grid)
table.insert(0, "material", snakemake.wildcards.material)  # noqa: F821
write_parquet(table, snakemake.output.scenarios)  # noqa: F821
fig = sets_figure(domain, cfg["factors"], sets, cfg.get("scenarios") or {}, n, cfg.get("reference_point"),
                  cfg.get("label") or snakemake.wildcards.material)  # noqa: F821
save_figure(fig, snakemake.output.figure)  # noqa: F821

"""Snakemake script: surrogate predictions on the grid over Omega, every scenario's admissible set
(feasible fraction and spans, eq. 2-4), their overlay figure (paper Figs. 3 and 5) and the
response-surface panels."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.admissibility import evaluate_scenarios, predict_grid  # noqa: E402
from demid.io import read_parquet, save_figure, write_parquet  # noqa: E402
from demid.plots import sets_figure, surface_figure_from_surrogates  # noqa: E402
from demid.surrogate import surrogates_from_frame  # noqa: E402

spec = snakemake.params.spec  # noqa: F821
n = spec.grid_points
surrogates = surrogates_from_frame(read_parquet(snakemake.input.fits), spec.factor_names)  # noqa: F821
grid = predict_grid(surrogates, spec.domain, n)
table, sets = evaluate_scenarios(surrogates, spec, n, grid)
table.insert(0, "material", snakemake.wildcards.material)  # noqa: F821
write_parquet(table, snakemake.output.scenarios)  # noqa: F821
save_figure(sets_figure(spec, sets, n, surrogates), snakemake.output.figure)  # noqa: F821
del grid, sets  # the surface panels predict their own slice; free the dense grid first
save_figure(surface_figure_from_surrogates(surrogates, spec, read_parquet(snakemake.input.table)),  # noqa: F821
            snakemake.output.surface)  # noqa: F821

"""Snakemake script: non-dominated grid points (observable error vs second objective) and their figure."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.admissibility import predict_grid  # noqa: E402
from demid.io import read_parquet, save_figure, write_csv  # noqa: E402
from demid.pareto import pareto_analysis  # noqa: E402
from demid.plots import pareto_figure  # noqa: E402
from demid.surrogate import surrogates_from_frame  # noqa: E402

spec = snakemake.params.spec  # noqa: F821
par = spec.pareto
surrogates = surrogates_from_frame(read_parquet(snakemake.input.fits), spec.factor_names)  # noqa: F821
grid = predict_grid(surrogates, spec.domain, spec.grid_points)
result = pareto_analysis(grid, spec.factor_names, par.error_of, spec.targets[par.error_of], par.minimise,
                         par.max_error)
write_csv(result.to_frame(), snakemake.output.table)  # noqa: F821
save_figure(pareto_figure(grid, result.front, spec), snakemake.output.figure)  # noqa: F821

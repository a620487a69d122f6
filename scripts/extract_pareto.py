"""Snakemake script: non-dominated grid points (observable error vs second objective) and their figure."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.io import read_parquet, save_figure, write_csv  # noqa: E402
from demid.steps import pareto_step  # noqa: E402
from demid.surrogate import surrogates_from_frame  # noqa: E402

spec = snakemake.params.spec  # noqa: F821
result = pareto_step(surrogates_from_frame(read_parquet(snakemake.input.fits), spec.factor_names), spec)  # noqa: F821
write_csv(result.table, snakemake.output.table)  # noqa: F821
save_figure(result.figure, snakemake.output.figure)  # noqa: F821

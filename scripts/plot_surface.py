"""Snakemake script: response-surface contour panels with design runs and target levels."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.io import read_parquet, save_figure  # noqa: E402
from demid.plots import surface_figure_from_surrogates  # noqa: E402
from demid.surrogate import surrogates_from_frame  # noqa: E402

spec = snakemake.params.spec  # noqa: F821
surrogates = surrogates_from_frame(read_parquet(snakemake.input.fits), spec.factor_names)  # noqa: F821
fig = surface_figure_from_surrogates(surrogates, spec, read_parquet(snakemake.input.table))  # noqa: F821
save_figure(fig, snakemake.output.figure)  # noqa: F821

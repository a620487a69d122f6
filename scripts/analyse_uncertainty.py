"""Snakemake script: robust sets, tolerance sweep, posteriors and observable ranking for one material."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.io import read_parquet, save_figure, write_json, write_parquet  # noqa: E402
from demid.surrogate import surrogates_from_frame  # noqa: E402
from demid.uncertainty import analyse_material  # noqa: E402

spec = snakemake.params.spec  # noqa: F821
title = spec.label
surrogates = surrogates_from_frame(read_parquet(snakemake.input.fits), spec.factor_names)  # noqa: F821
result = analyse_material(surrogates, spec, z=snakemake.params.z, tolerances=snakemake.params.tolerances)  # noqa: F821
for name in ("robust", "sweep", "information_gain", "ranking"):
    write_parquet(getattr(result, name), getattr(snakemake.output, name))  # noqa: F821
write_json({"advice": result.advice, "notes": result.notes}, snakemake.output.summary)  # noqa: F821
save_figure(result.sweep_figure(title), snakemake.output.sweep_figure)  # noqa: F821
save_figure(result.posterior_figure(title), snakemake.output.posterior_figure)  # noqa: F821

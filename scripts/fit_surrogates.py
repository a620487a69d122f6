"""Snakemake script: quadratic OLS surrogates and their diagnostics for one material."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.io import read_parquet, write_parquet  # noqa: E402
from demid.surrogate import fit_frames, fit_material  # noqa: E402

table = read_parquet(snakemake.input.table)  # noqa: F821
frames = fit_frames(fit_material(table, snakemake.params.spec))  # noqa: F821
for name, frame in frames.items():
    write_parquet(frame, getattr(snakemake.output, name))  # noqa: F821

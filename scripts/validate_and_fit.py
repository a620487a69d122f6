"""Snakemake script: validate one material's transcribed table, check it against the published
statistics, then fit the quadratic OLS surrogates and their diagnostics (two steps, one start-up)."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.io import read_parquet, write_json, write_parquet  # noqa: E402
from demid.steps import validate_step  # noqa: E402
from demid.surrogate import fit_frames, fit_material  # noqa: E402

spec, out = snakemake.params.spec, snakemake.output  # noqa: F821
validated = validate_step(spec, snakemake.input.data)  # noqa: F821
for warning in validated.warnings:
    print(f"warning: {warning}", file=sys.stderr)
write_parquet(validated.table, out.table)
write_parquet(validated.transcription, out.transcription)
write_json(validated.summary, out.summary)
# The fit reads the stored table back, exactly as every later step sees it.
for name, frame in fit_frames(fit_material(read_parquet(out.table), spec)).items():
    write_parquet(frame, getattr(out, name))

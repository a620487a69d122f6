"""Snakemake script: validate one material's transcribed table and check it against published statistics."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.io import write_json, write_parquet  # noqa: E402
from demid.steps import validate_step  # noqa: E402

out = snakemake.output  # noqa: F821
result = validate_step(snakemake.params.spec, snakemake.input.data)  # noqa: F821
for warning in result.warnings:
    print(f"warning: {warning}", file=sys.stderr)
write_parquet(result.table, out.table)
write_parquet(result.transcription, out.transcription)
write_json(result.summary, out.summary)

"""Snakemake script: validate one material's transcribed table and check it against published statistics."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.data import read_printed, validate_material  # noqa: E402
from demid.io import write_json, write_parquet  # noqa: E402
from demid.transcription import check_material, likely_typos, transcription_frame  # noqa: E402

spec = snakemake.params.spec  # noqa: F821
validated = validate_material(spec.name, spec.material_config())
for warning in validated.warnings:
    print(f"warning: {warning}", file=sys.stderr)
printed = read_printed(snakemake.input.data, validated.table)  # noqa: F821
checks = check_material(validated, spec, printed)
typos = likely_typos(validated, spec, printed)
for flag in typos:
    if (int(flag["run"]), flag["column"]) in spec.confirmed_values:
        flag["confirmed"] = True
        flag["message"] += " (confirmed correct under confirmed_values)"
    print(f"warning: {flag['message']}", file=sys.stderr)
summary = validated.summary(spec.name)
summary["warnings"] += [flag["message"] for flag in typos]
summary["likely_typos"] = typos
summary["transcription"] = {r.response: r.to_json() for r in checks}
write_parquet(validated.to_frame(), snakemake.output.table)  # noqa: F821
write_parquet(transcription_frame(checks), snakemake.output.transcription)  # noqa: F821
write_json(summary, snakemake.output.summary)  # noqa: F821

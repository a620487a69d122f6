"""Snakemake script: validate one material's transcribed table and check it against published statistics."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.data import read_printed, validate_material  # noqa: E402
from demid.io import write_json, write_parquet  # noqa: E402
from demid.transcription import check_material, likely_typos, transcription_frame  # noqa: E402

material = snakemake.wildcards.material  # noqa: F821
cfg = snakemake.params.material_cfg  # noqa: F821
validated = validate_material(material, cfg)
for warning in validated.warnings:
    print(f"warning: {warning}", file=sys.stderr)
printed = read_printed(snakemake.input.data, validated.table)  # noqa: F821
checks = check_material(validated, cfg, printed)
typos = likely_typos(validated, cfg, printed)
confirmed = {(int(item["run"]), item["column"]) for item in cfg.get("confirmed_values") or []}
for flag in typos:
    if (int(flag["run"]), flag["column"]) in confirmed:
        flag["confirmed"] = True
        flag["message"] += " (confirmed correct under confirmed_values)"
    print(f"warning: {flag['message']}", file=sys.stderr)
summary = validated.summary(material)
summary["warnings"] += [flag["message"] for flag in typos]
summary["likely_typos"] = typos
summary["transcription"] = {r.response: r.to_json() for r in checks}
write_parquet(validated.to_frame(), snakemake.output.table)  # noqa: F821
write_parquet(transcription_frame(checks), snakemake.output.transcription)  # noqa: F821
write_json(summary, snakemake.output.summary)  # noqa: F821

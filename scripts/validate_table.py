"""Snakemake script: validate one material's transcribed table (structure, levels, bounds)."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.data import validate_material  # noqa: E402
from demid.io import write_json, write_parquet  # noqa: E402

material = snakemake.wildcards.material  # noqa: F821
validated = validate_material(material, snakemake.params.material_cfg)  # noqa: F821
for warning in validated.warnings:
    print(f"warning: {warning}", file=sys.stderr)
write_parquet(validated.to_frame(), snakemake.output.table)  # noqa: F821
write_json(validated.summary(material), snakemake.output.summary)  # noqa: F821

"""Snakemake script: one material from its transcribed table to every per-material output
(validation, fit, scenario sets, Pareto front, uncertainty, criticism, their figures)."""

import sys
from pathlib import Path

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.io import save_figure, write_csv, write_json, write_parquet  # noqa: E402
from demid.steps import material_step  # noqa: E402

spec, out, params = snakemake.params.spec, snakemake.output, snakemake.params  # noqa: F821
result = material_step(spec, snakemake.input.data, z=params.z, tolerances=params.tolerances)  # noqa: F821
for warning in result.warnings:
    print(f"warning: {warning}", file=sys.stderr)
for name, frame in result.parquet.items():
    write_parquet(frame, getattr(out, name))
for name, frame in result.csv.items():
    write_csv(frame, getattr(out, name))
for name, document in result.json.items():
    write_json(document, getattr(out, name))
Path(out.criticism).mkdir(parents=True, exist_ok=True)
for response, document in result.responses.items():
    write_json(document, Path(out.criticism) / f"{response}.json")
for name, figure in result.figures.items():
    save_figure(figure, getattr(out, name))

"""Snakemake script: what the surrogate and the calibrated simulation get wrong, why, and the gain of a fix."""

import sys
from pathlib import Path

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.criticism import criticize_material  # noqa: E402
from demid.io import read_parquet, save_figure, write_json, write_parquet  # noqa: E402
from demid.surrogate import surrogates_from_frame  # noqa: E402

spec = snakemake.params.spec  # noqa: F821
out = snakemake.output  # noqa: F821
surrogates = surrogates_from_frame(read_parquet(snakemake.input.fits), spec.factor_names)  # noqa: F821
result = criticize_material(read_parquet(snakemake.input.table), surrogates, spec)  # noqa: F821
Path(out.responses).mkdir(parents=True, exist_ok=True)
for response, payload in result.response_json.items():
    write_json(payload, Path(out.responses) / f"{response}.json")
write_parquet(result.findings, out.findings)
write_parquet(result.calibration, out.calibration)
write_json(result.summary, out.summary)
save_figure(result.figure, out.figure)

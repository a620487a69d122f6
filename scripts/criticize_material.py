"""Snakemake script: what the surrogate and the calibrated simulation get wrong, why, and the gain of a fix."""

import sys
from pathlib import Path

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.criticism import criticize_material  # noqa: E402
from demid.io import read_parquet, save_figure, write_json, write_parquet  # noqa: E402
from demid.sampling.stored import stored_strict_sets  # noqa: E402
from demid.surrogate import surrogates_from_frame  # noqa: E402

spec, inp, out = snakemake.params.spec, snakemake.input, snakemake.output  # noqa: F821
surrogates = surrogates_from_frame(read_parquet(inp.fits), spec.factor_names)
strict_sets = stored_strict_sets(read_parquet(inp.scenarios), surrogates, spec, reference=True)
result = criticize_material(read_parquet(inp.table), surrogates, spec, strict_sets=strict_sets)
Path(out.responses).mkdir(parents=True, exist_ok=True)
for response, payload in result.response_json.items():
    write_json(payload, Path(out.responses) / f"{response}.json")
write_parquet(result.findings, out.findings)
write_parquet(result.calibration, out.calibration)
write_json(result.summary, out.summary)
save_figure(result.figure, out.figure)

"""Snakemake script: the refocused search box and the proposed runs of the next wave, per material asking."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.io import read_parquet, write_csv, write_json  # noqa: E402
from demid.next_wave import plan_waves, tabulate_waves  # noqa: E402

inp, params = snakemake.input, snakemake.params  # noqa: F821
specs = {spec.name: spec for spec in params.specs}
frames = {name: {m: read_parquet(path) for m, path in zip(specs, getattr(inp, name))}
          for name in ("tables", "fits", "plausible", "findings")}
waves = plan_waves(specs, frames, z=params.z)
domain, runs, reasons = tabulate_waves(specs, waves)
write_csv(domain, snakemake.output.domain)  # noqa: F821
write_csv(runs, snakemake.output.runs)  # noqa: F821
write_json(reasons, snakemake.output.reasons)  # noqa: F821
write_json({m: w.value for m, w in waves.items()}, snakemake.output.value)  # noqa: F821

"""Snakemake script: one simulation run (params.json, the command, run.json with its status)."""

from pathlib import Path

from demid.io import write_json
from demid.simulation import FAILED, execute

params, out = snakemake.params, snakemake.output  # noqa: F821
run_dir = Path(out.params).parent
write_json(params.run, out.params)
with open(snakemake.log[0], "w", encoding="utf-8") as log:  # noqa: F821
    record = execute(params.run, run_dir, params.responses, log)
    if record["status"] == FAILED and snakemake.attempt <= params.retries:  # noqa: F821
        log.write(f"attempt {snakemake.attempt} of {params.retries + 1}: trying again\n")  # noqa: F821
        raise SystemExit(f"run {params.run['run']} failed: {record['reason']}")
write_json(record, out.record)

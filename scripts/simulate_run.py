"""Snakemake script: one simulation run (params.json, the command, run.json with its status)."""

import shutil
from pathlib import Path

from demid.simulation import FAILED, RunStopped, Simulation, execute, write_run_json

params, out = snakemake.params, snakemake.output  # noqa: F821
material = params.run["material"]
# The time limit and retries are read from the config, not params: changing them reruns nothing.
simulation = Simulation.from_material(snakemake.config["materials"][material])  # noqa: F821
attempt = snakemake.resources.attempt  # noqa: F821
with open(snakemake.log[0], "w", encoding="utf-8") as log:  # noqa: F821
    try:
        record = execute(params.run, Path(out.params).parent, params.responses, log, simulation.timeout_s)
    except RunStopped as stop:  # no run.json: the next invocation runs it again
        raise SystemExit(f"run {params.run['run']} stopped: {stop}") from None
    retry = record["status"] == FAILED and attempt <= simulation.retries
    if retry:
        log.write(f"attempt {attempt} of {simulation.retries + 1}: trying again\n")
if retry:  # Snakemake clears the log before the next attempt: keep this one beside it
    shutil.copyfile(snakemake.log[0], f"{snakemake.log[0]}.attempt{attempt}")  # noqa: F821
    raise SystemExit(f"run {params.run['run']} failed: {record['reason']}")
write_run_json(record, out.record)

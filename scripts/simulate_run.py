"""Snakemake script: one simulation run (params.json, the command, run.json with its status)."""

from pathlib import Path

from demid.io import write_json
from demid.simulation import FAILED, Simulation, execute

params, out = snakemake.params, snakemake.output  # noqa: F821
material = params.run["material"]
# The time limit and retries are read from the config, not params: changing them reruns nothing.
simulation = Simulation.from_material(snakemake.config["materials"][material])  # noqa: F821
write_json(params.run, out.params)
with open(snakemake.log[0], "w", encoding="utf-8") as log:  # noqa: F821
    record = execute(params.run, Path(out.params).parent, params.responses, log, simulation.timeout_s)
    if record["status"] == FAILED and snakemake.resources.attempt <= simulation.retries:  # noqa: F821
        log.write(f"attempt {snakemake.resources.attempt} of {simulation.retries + 1}: trying again\n")  # noqa: F821
        raise SystemExit(f"run {params.run['run']} failed: {record['reason']}")
write_json(record, out.record)

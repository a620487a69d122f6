"""Snakemake script: one material from its transcribed table to every per-material output
(validation, fit, scenario sets, Pareto front, uncertainty, criticism, their figures)."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.data import content_hidden_outside  # noqa: E402
from demid.errors import InputError, stop_job  # noqa: E402
from demid.steps import material_step, write_material_analysis  # noqa: E402

spec, out, params = snakemake.params.spec, snakemake.output, snakemake.params  # noqa: F821
try:  # the table's one full validation is this job's first stage: bad input is one line, not a traceback
    with content_hidden_outside(spec.data):  # a table outside the study folder: none of its lines shown
        result = material_step(spec, snakemake.input.data, z=params.z, tolerances=params.tolerances)  # noqa: F821
except InputError as err:
    stop_job(err)
for warning in result.warnings:
    print(f"warning: {warning}", file=sys.stderr)
write_material_analysis(result, out)

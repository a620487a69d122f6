"""Snakemake script: one wave of a simulated material, analysed like a finished table (every run so far,
over the declared search range Omega; after wave 1 as a custom design, each response's sets judged by the
quadratic or kriging, whichever predicts left-out runs better)."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

import pandas as pd  # noqa: E402

from demid.errors import InputError, stop_job  # noqa: E402
from demid.steps import material_step, write_material_analysis  # noqa: E402
from demid.waves import wave_spec  # noqa: E402

inp, out, params = snakemake.input, snakemake.output, snakemake.params  # noqa: F821
domain = pd.read_csv(inp.domain) if "domain" in inp.keys() else None
spec = wave_spec(params.spec, inp.data, domain)
try:  # e.g. too many failed runs for the quadratic: one line naming the wave's table, not a traceback
    result = material_step(spec, inp.data, z=params.z, tolerances=params.tolerances, typo_stop=False,
                           choose_surrogate=domain is not None)  # after wave 1: quadratic or kriging, measured
except InputError as err:
    stop_job(err)
for warning in result.warnings:
    print(f"warning: {warning}", file=sys.stderr)
write_material_analysis(result, out)

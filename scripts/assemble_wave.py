"""Snakemake script: a simulated material's table after one wave (every run so far, and the runs the
wave analyses: every run so far too, over the search range Omega; failed runs stay failed rows)."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.errors import InputError, stop_job  # noqa: E402
from demid.io import write_full_csv  # noqa: E402
from demid.simulation import assemble_table, read_run  # noqa: E402

inp, out, params = snakemake.input, snakemake.output, snakemake.params  # noqa: F821

try:  # a run's files changed since its job: one line naming its folder
    records = [read_run(p, r) for p, r in zip(inp.params, inp.records)]
except InputError as err:
    stop_job(err)
table = assemble_table(records, params.factors, params.responses)
write_full_csv(table, out.table)
write_full_csv(table, out.analysed)

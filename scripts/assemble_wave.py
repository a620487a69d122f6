"""Snakemake script: a simulated material's table after one wave (every run so far, and the runs the
wave analyses: every run so far too, over the search range Omega; failed runs stay failed rows)."""

import json
import sys
from pathlib import Path

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.io import write_full_csv  # noqa: E402
from demid.simulation import assemble_table  # noqa: E402

inp, out, params = snakemake.input, snakemake.output, snakemake.params  # noqa: F821


def read(path):
    return json.loads(Path(path).read_text(encoding="utf-8"))


records = [(read(p), read(r)) for p, r in zip(inp.params, inp.records)]
table = assemble_table(records, params.factors, params.responses)
write_full_csv(table, out.table)
write_full_csv(table, out.analysed)

"""Snakemake script: every published number against its reproduction."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

import pandas as pd  # noqa: E402
import yaml  # noqa: E402

from demid.io import write_csv  # noqa: E402
from demid.paper import paper_comparison  # noqa: E402
from demid.report import pareto_intervals  # noqa: E402

with open(snakemake.input.published, encoding="utf-8") as fh:  # noqa: F821
    published = yaml.safe_load(fh)
intervals = {m: pareto_intervals(p) for m, p in zip(snakemake.params.pareto_materials, snakemake.input.pareto)}  # noqa: F821
table = paper_comparison(published, pd.read_csv(snakemake.input.surrogate_fit),  # noqa: F821
                         pd.read_csv(snakemake.input.identifiability), intervals)  # noqa: F821
write_csv(table, snakemake.output.table)  # noqa: F821

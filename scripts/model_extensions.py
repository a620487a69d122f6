"""Snakemake script: the gain of extending a model (a material that ``extends`` another), read from the results."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

import json  # noqa: E402

import pandas as pd  # noqa: E402

from demid.io import write_csv  # noqa: E402
from demid.story.extensions import model_extensions  # noqa: E402

inp, out, params = snakemake.input, snakemake.output, snakemake.params  # noqa: F821
specs = {spec.name: spec for spec in params.specs}
criticism = {name: json.loads(open(path, encoding="utf-8").read()) for name, path in zip(specs, inp.criticism)}
table = model_extensions(specs, dict(params.extends), criticism, pd.read_csv(inp.identifiability),
                         pd.read_csv(inp.surrogate_fit))
write_csv(table, out.table)

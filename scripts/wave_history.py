"""Snakemake script: a simulated material's admissible sets wave by wave (table and figure)."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

import pandas as pd  # noqa: E402

from demid.io import read_parquet, save_figure, write_csv  # noqa: E402
from demid.plots.waves import waves_figure  # noqa: E402
from demid.waves import wave_history  # noqa: E402

inp, out, spec = snakemake.input, snakemake.output, snakemake.params.spec  # noqa: F821
domains = [None] + [pd.read_csv(path) for path in inp.domains]
waves = [{"scenarios": read_parquet(s), "domain": d, "simulated": len(pd.read_csv(t)), "analysed": len(pd.read_csv(a))}
         for s, d, t, a in zip(inp.scenarios, domains, inp.tables, inp.analysed)]
history = wave_history(spec, waves)
write_csv(history, out.table)
save_figure(waves_figure(history, spec), out.figure)

"""Snakemake script: a simulated material's admissible sets wave by wave (table and figure), and the summary the
report's "Waves" section and the study's advice read (per wave runs, surrogate and plausible set; the decision)."""

import json
import sys
from pathlib import Path

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

import pandas as pd  # noqa: E402

from demid.io import read_parquet, save_figure, write_csv, write_json  # noqa: E402
from demid.plots.waves import waves_figure  # noqa: E402
from demid.waves import wave_history, wave_summary  # noqa: E402

inp, out, spec = snakemake.input, snakemake.output, snakemake.params.spec  # noqa: F821
domains = [None] + [pd.read_csv(path) for path in inp.domains]
tables = [pd.read_csv(t) for t in inp.tables]
analysed = [pd.read_csv(a) for a in inp.analysed]
plausible = [read_parquet(r) for r in inp.plausible]
waves = [{"scenarios": read_parquet(s), "domain": d, "simulated": len(t), "analysed": len(a), "plausible": r}
         for s, d, t, a, r in zip(inp.scenarios, domains, tables, analysed, plausible)]
history = wave_history(spec, waves)
write_csv(history, out.table)
save_figure(waves_figure(history, spec, runs=tables[-1]), out.figure)
decision = json.loads(Path(inp.decision).read_text(encoding="utf-8")) if "decision" in inp.keys() else None
summary = wave_summary(spec, [{"table": t, "analysed": a, "domain": d, "plausible": r,
                               "statistics": read_parquet(s)}
                              for t, a, d, r, s in zip(tables, analysed, domains, plausible, inp.statistics)],
                       decision)
write_json(summary, out.summary)

"""Snakemake script: a simulated material's next wave after wave k (its refocused box, the runs to
simulate, and whether the waves go on)."""

import json
import sys
from pathlib import Path

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

import pandas as pd  # noqa: E402

from demid.io import read_parquet, write_csv, write_json  # noqa: E402
from demid.next_wave import plan_waves, tabulate_waves  # noqa: E402
from demid.waves import stop_decision, wave_evidence, wave_spec  # noqa: E402

inp, out, params = snakemake.input, snakemake.output, snakemake.params  # noqa: F821
domain = pd.read_csv(inp.domain) if "domain" in inp.keys() else None
spec = wave_spec(params.spec, inp.data, domain)
frames = {name: {spec.name: read_parquet(getattr(inp, name))} for name in ("tables", "fits", "plausible", "findings")}
waves = plan_waves({spec.name: spec}, frames, z=params.z, analysed_over_omega=True)  # a wave analyses every run
next_domain, runs, reasons = tabulate_waves({spec.name: spec}, waves)
write_csv(next_domain, out.domain)
write_csv(runs, out.runs)
write_json(reasons, out.reasons)
previous = json.loads(Path(inp.previous).read_text(encoding="utf-8")) if "previous" in inp.keys() else None
evidence = wave_evidence(params.spec, int(snakemake.wildcards.wave), domain, frames["plausible"][spec.name],  # noqa: F821
                         read_parquet(inp.statistics), json.loads(Path(inp.criticism).read_text(encoding="utf-8")),
                         previous, runs)
decision = stop_decision(waves[spec.name].value, evidence)
write_json({**decision, "plausible_fraction_of_omega_pct": evidence.plausible_pct, "value": waves[spec.name].value},
           out.decision)

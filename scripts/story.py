"""Snakemake script: the verdict per factor and every piece of advice, computed once for the report."""

import sys
from pathlib import Path

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.io import write_csv  # noqa: E402
from demid.story import study_story  # noqa: E402

inp, out, params = snakemake.input, snakemake.output, snakemake.params  # noqa: F821
specs = {spec.name: spec for spec in params.specs}
per_material = {name: dict(zip(specs, getattr(inp, name))) for name in ("tables", "criticism", "uncertainty",
                                                                          "combinations")}
files = {"identifiability": inp.identifiability, "plausible": inp.plausible, "ranking": inp.ranking, **per_material,
         "next_wave_value": inp.get("next_wave_value"),
         "wave_summaries": {Path(f).stem.removeprefix("summary_"): f for f in inp.get("wave_summaries", [])}}
verdicts, advice = study_story(specs, files)
write_csv(verdicts, out.verdicts)
write_csv(advice, out.advice)

"""Snakemake script: robust sets, tolerance sweep, posteriors and observable ranking for one material."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.io import read_parquet, save_figure, write_json, write_parquet  # noqa: E402
from demid.sampling.stored import stored_strict_sets  # noqa: E402
from demid.surrogate import surrogates_from_frame  # noqa: E402
from demid.uncertainty import analyse_material  # noqa: E402

spec, inp, out, params = snakemake.params.spec, snakemake.input, snakemake.output, snakemake.params  # noqa: F821
surrogates = surrogates_from_frame(read_parquet(inp.fits), spec.factor_names)
result = analyse_material(surrogates, spec, z=params.z, tolerances=params.tolerances,
                          strict_sets=stored_strict_sets(read_parquet(inp.scenarios), surrogates, spec))
for name in ("robust", "sweep", "information_gain", "ranking"):
    write_parquet(getattr(result, name), getattr(out, name))
write_json(result.summary, out.summary)
save_figure(result.sweep_figure(spec.label), out.sweep_figure)
save_figure(result.posterior_figure(spec.label), out.posterior_figure)

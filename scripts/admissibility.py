"""Snakemake script: every scenario's admissible set (feasible fraction and spans, eq. 2-4) on the
grid over Omega, their overlay figure (paper Figs. 3 and 5) and the response-surface panels."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.io import read_parquet, save_figure, write_parquet  # noqa: E402
from demid.steps import admissibility_step  # noqa: E402
from demid.surrogate import surrogates_from_frame  # noqa: E402

spec, inp, out = snakemake.params.spec, snakemake.input, snakemake.output  # noqa: F821
surrogates = surrogates_from_frame(read_parquet(inp.fits), spec.factor_names)
result = admissibility_step(surrogates, spec, read_parquet(inp.table))
write_parquet(result.scenarios, out.scenarios)
save_figure(result.figure, out.figure)
save_figure(result.surface, out.surface)

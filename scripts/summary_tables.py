"""Snakemake script: the cross-material tables (Table 2, Table 3, transcription, uncertainty, criticism)
and, where the config names a published-values file, every published number against its reproduction."""

import sys

sys.stderr = open(snakemake.log[0], "w", encoding="utf-8")  # noqa: F821

from demid.io import write_csv  # noqa: E402
from demid.report import summary_tables  # noqa: E402
from demid.report.columns import columns_table  # noqa: E402

inp, out, params = snakemake.input, snakemake.output, snakemake.params  # noqa: F821
per_material = {name: dict(zip(params.materials, files))
                for name, files in inp.items() if name not in ("published", "pareto")}
write_csv(columns_table(params.pareto_factors, params.next_wave, params.combination_factors), out.columns)
for name, table in summary_tables(per_material).items():
    write_csv(table, getattr(out, name))

if "paper_comparison" in out.keys():
    import pandas as pd

    from demid.config import load_yaml
    from demid.paper import paper_comparison
    from demid.published_values import for_materials
    from demid.report import pareto_intervals

    published = for_materials(load_yaml(inp.published), params.materials)
    intervals = {m: pareto_intervals(p) for m, p in zip(params.pareto_materials, inp.pareto)}
    # compared as written: the tables a reader sees, rounded as they are
    table = paper_comparison(published, pd.read_csv(out.surrogate_fit), pd.read_csv(out.identifiability), intervals)
    write_csv(table, out.paper_comparison)

localrules:
    summary_tables,


rule summary_tables:
    input:
        **summary_inputs(),
    output:
        **summary_outputs(),
    params:
        materials=MATERIALS,
        pareto_materials=pareto_materials(),
        pareto_factors={m: [(f.name, f.unit) for f in SPECS[m].factors] for m in pareto_materials()},
        next_wave=next_wave_columns(),
        combination_factors=list(dict.fromkeys(f for m in MATERIALS for f in SPECS[m].factor_names)),
        published_digest=published_digest,  # the published file's content (a rerun after an edit)
    resources:
        mem_mb=1000,
    conda:
        "../envs/demid.yaml"
    log:
        log_file("tables/summary.log"),
    benchmark:
        benchmark_file("tables/summary.tsv")
    script:
        "../../scripts/summary_tables.py"

rule admissibility:
    input:
        fits=f"{RESULTS}/fits/{{material}}.parquet",
    output:
        grid=f"{RESULTS}/grid/{{material}}.parquet",
        scenarios=f"{RESULTS}/scenarios/{{material}}.parquet",
        figure=report(
            f"{RESULTS}/figures/sets_{{material}}.png",
            category="Admissible sets",
            caption="../report/sets.rst",
        ),
    params:
        spec=material_spec,
    resources:
        mem_mb=evaluation_mem_mb,
    conda:
        "../envs/demid.yaml"
    log:
        "logs/admissibility/{material}.log",
    benchmark:
        "benchmarks/admissibility/{material}.tsv"
    script:
        "../../scripts/admissibility.py"


rule extract_pareto:
    input:
        grid=f"{RESULTS}/grid/{{material}}.parquet",
    output:
        table=f"{RESULTS}/tables/pareto_{{material}}.csv",
        figure=report(
            f"{RESULTS}/figures/pareto_{{material}}.png",
            category="Pareto trade-off",
            caption="../report/pareto.rst",
        ),
    params:
        spec=material_spec,
    resources:
        mem_mb=evaluation_mem_mb,
    conda:
        "../envs/demid.yaml"
    log:
        "logs/pareto/{material}.log",
    benchmark:
        "benchmarks/pareto/{material}.tsv"
    script:
        "../../scripts/extract_pareto.py"

rule fit_surrogates:
    input:
        table=f"{RESULTS}/validated/{{material}}.parquet",
    output:
        fits=f"{RESULTS}/fits/{{material}}.parquet",
        statistics=f"{RESULTS}/fits/{{material}}_statistics.parquet",
        anova=f"{RESULTS}/fits/{{material}}_anova.parquet",
        diagnostics=f"{RESULTS}/fits/{{material}}_diagnostics.parquet",
    params:
        spec=material_spec,
    conda:
        "../envs/demid.yaml"
    log:
        "logs/fit/{material}.log",
    benchmark:
        "benchmarks/fit/{material}.tsv"
    script:
        "../../scripts/fit_surrogates.py"

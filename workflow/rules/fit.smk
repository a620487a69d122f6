# Validation and the fit share one job: each is a fraction of a second of work, less than a
# Python start-up with pandas and statsmodels.  Both keep their parquet intermediates.
rule validate_and_fit:
    input:
        data=material_data,
    output:
        table=f"{RESULTS}/validated/{{material}}.parquet",
        summary=f"{RESULTS}/validated/{{material}}.json",
        transcription=f"{RESULTS}/validated/{{material}}_transcription.parquet",
        fits=f"{RESULTS}/fits/{{material}}.parquet",
        statistics=f"{RESULTS}/fits/{{material}}_statistics.parquet",
        anova=f"{RESULTS}/fits/{{material}}_anova.parquet",
        diagnostics=f"{RESULTS}/fits/{{material}}_diagnostics.parquet",
    params:
        spec=material_spec,
    resources:
        mem_mb=1000,
    conda:
        "../envs/demid.yaml"
    log:
        "logs/validate_and_fit/{material}.log",
    benchmark:
        "benchmarks/validate_and_fit/{material}.tsv"
    script:
        "../../scripts/validate_and_fit.py"

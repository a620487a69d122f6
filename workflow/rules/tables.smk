localrules:
    surrogate_fit_table,
    identifiability_table,
    paper_comparison_table,
    transcription_table,


rule surrogate_fit_table:
    input:
        statistics=expand(f"{RESULTS}/fits/{{material}}_statistics.parquet", material=MATERIALS),
    output:
        table=f"{RESULTS}/tables/surrogate_fit.csv",
    params:
        materials=MATERIALS,
    conda:
        "../envs/demid.yaml"
    log:
        "logs/tables/surrogate_fit.log",
    benchmark:
        "benchmarks/tables/surrogate_fit.tsv"
    script:
        "../../scripts/surrogate_fit_table.py"


rule identifiability_table:
    input:
        scenarios=expand(f"{RESULTS}/scenarios/{{material}}.parquet", material=MATERIALS),
    output:
        table=f"{RESULTS}/tables/identifiability.csv",
    params:
        materials=MATERIALS,
    conda:
        "../envs/demid.yaml"
    log:
        "logs/tables/identifiability.log",
    benchmark:
        "benchmarks/tables/identifiability.tsv"
    script:
        "../../scripts/identifiability_table.py"


rule paper_comparison_table:
    input:
        published=config["published"] or [],
        surrogate_fit=f"{RESULTS}/tables/surrogate_fit.csv",
        identifiability=f"{RESULTS}/tables/identifiability.csv",
        pareto=expand(f"{RESULTS}/tables/pareto_{{material}}.csv", material=pareto_materials()),
    output:
        table=f"{RESULTS}/tables/paper_comparison.csv",
    params:
        pareto_materials=pareto_materials(),
    conda:
        "../envs/demid.yaml"
    log:
        "logs/tables/paper_comparison.log",
    benchmark:
        "benchmarks/tables/paper_comparison.tsv"
    script:
        "../../scripts/paper_comparison_table.py"


rule transcription_table:
    input:
        checks=expand(f"{RESULTS}/validated/{{material}}_transcription.parquet", material=MATERIALS),
    output:
        table=f"{RESULTS}/tables/transcription_check.csv",
    params:
        materials=MATERIALS,
    conda:
        "../envs/demid.yaml"
    log:
        "logs/tables/transcription_check.log",
    benchmark:
        "benchmarks/tables/transcription_check.tsv"
    script:
        "../../scripts/transcription_table.py"

localrules:
    summary_tables,
    paper_comparison_table,


rule summary_tables:
    input:
        statistics=expand(f"{RESULTS}/fits/{{material}}_statistics.parquet", material=MATERIALS),
        scenarios=expand(f"{RESULTS}/scenarios/{{material}}.parquet", material=MATERIALS),
        transcription=expand(f"{RESULTS}/validated/{{material}}_transcription.parquet", material=MATERIALS),
        robust=expand(f"{RESULTS}/uncertainty/{{material}}_robust.parquet", material=MATERIALS),
        sweep=expand(f"{RESULTS}/uncertainty/{{material}}_sweep.parquet", material=MATERIALS),
        information_gain=expand(
            f"{RESULTS}/uncertainty/{{material}}_information_gain.parquet", material=MATERIALS
        ),
        ranking=expand(f"{RESULTS}/uncertainty/{{material}}_ranking.parquet", material=MATERIALS),
        findings=expand(f"{RESULTS}/criticism/{{material}}_findings.parquet", material=MATERIALS),
        calibration=expand(f"{RESULTS}/criticism/{{material}}_calibration.parquet", material=MATERIALS),
    output:
        surrogate_fit=f"{RESULTS}/tables/surrogate_fit.csv",
        identifiability=f"{RESULTS}/tables/identifiability.csv",
        transcription=f"{RESULTS}/tables/transcription_check.csv",
        robust=f"{RESULTS}/tables/robust_identifiability.csv",
        sweep=f"{RESULTS}/tables/tolerance_sweep.csv",
        information_gain=f"{RESULTS}/tables/information_gain.csv",
        ranking=f"{RESULTS}/tables/observable_ranking.csv",
        findings=f"{RESULTS}/tables/criticism.csv",
        calibration=f"{RESULTS}/tables/calibration_residuals.csv",
        columns=f"{RESULTS}/tables/columns.csv",
    params:
        materials=MATERIALS,
        pareto_factors={m: [(f.name, f.unit) for f in SPECS[m].factors] for m in pareto_materials()},
        next_wave=next_wave_columns(),
    resources:
        mem_mb=1000,
    conda:
        "../envs/demid.yaml"
    log:
        "logs/tables/summary.log",
    benchmark:
        "benchmarks/tables/summary.tsv"
    script:
        "../../scripts/summary_tables.py"


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
    resources:
        mem_mb=1000,
    conda:
        "../envs/demid.yaml"
    log:
        "logs/tables/paper_comparison.log",
    benchmark:
        "benchmarks/tables/paper_comparison.tsv"
    script:
        "../../scripts/paper_comparison_table.py"

rule analyse_uncertainty:
    input:
        fits=f"{RESULTS}/fits/{{material}}.parquet",
    output:
        robust=f"{RESULTS}/uncertainty/{{material}}_robust.parquet",
        sweep=f"{RESULTS}/uncertainty/{{material}}_sweep.parquet",
        information_gain=f"{RESULTS}/uncertainty/{{material}}_information_gain.parquet",
        ranking=f"{RESULTS}/uncertainty/{{material}}_ranking.parquet",
        summary=f"{RESULTS}/uncertainty/{{material}}.json",
        sweep_figure=report(
            f"{RESULTS}/figures/sweep_{{material}}.png",
            category="Uncertainty",
            caption="../report/sweep.rst",
        ),
        posterior_figure=report(
            f"{RESULTS}/figures/posterior_{{material}}.png",
            category="Uncertainty",
            caption="../report/posterior.rst",
        ),
    params:
        material_cfg=material_cfg,
        z=config["robust_z"],
        tolerances=config["sweep_tolerances"],
    conda:
        "../envs/demid.yaml"
    log:
        "logs/uncertainty/{material}.log",
    benchmark:
        "benchmarks/uncertainty/{material}.tsv"
    script:
        "../../scripts/analyse_uncertainty.py"


rule uncertainty_tables:
    input:
        robust=expand(f"{RESULTS}/uncertainty/{{material}}_robust.parquet", material=MATERIALS),
        sweep=expand(f"{RESULTS}/uncertainty/{{material}}_sweep.parquet", material=MATERIALS),
        information_gain=expand(
            f"{RESULTS}/uncertainty/{{material}}_information_gain.parquet", material=MATERIALS
        ),
        ranking=expand(f"{RESULTS}/uncertainty/{{material}}_ranking.parquet", material=MATERIALS),
    output:
        robust=f"{RESULTS}/tables/robust_identifiability.csv",
        sweep=f"{RESULTS}/tables/tolerance_sweep.csv",
        information_gain=f"{RESULTS}/tables/information_gain.csv",
        ranking=f"{RESULTS}/tables/observable_ranking.csv",
    params:
        materials=MATERIALS,
    conda:
        "../envs/demid.yaml"
    log:
        "logs/tables/uncertainty.log",
    benchmark:
        "benchmarks/tables/uncertainty.tsv"
    script:
        "../../scripts/uncertainty_tables.py"

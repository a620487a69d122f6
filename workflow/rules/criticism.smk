rule criticize_material:
    input:
        table=f"{RESULTS}/validated/{{material}}.parquet",
        fits=f"{RESULTS}/fits/{{material}}.parquet",
        scenarios=f"{RESULTS}/scenarios/{{material}}.parquet",
    output:
        responses=directory(f"{RESULTS}/criticism/{{material}}"),
        findings=f"{RESULTS}/criticism/{{material}}_findings.parquet",
        calibration=f"{RESULTS}/criticism/{{material}}_calibration.parquet",
        summary=f"{RESULTS}/criticism/{{material}}.json",
        figure=report(
            f"{RESULTS}/figures/residuals_{{material}}.png",
            category="Model criticism",
            caption="../report/residuals.rst",
        ),
        figure_svg=f"{RESULTS}/figures/residuals_{{material}}.svg",
    params:
        spec=material_spec,
    resources:
        mem_mb=2000,
    conda:
        "../envs/demid.yaml"
    log:
        "logs/criticism/{material}.log",
    benchmark:
        "benchmarks/criticism/{material}.tsv"
    script:
        "../../scripts/criticize_material.py"

# The set evaluation and the response-surface figure share one job: both start from the
# fits, and the surface panels cost less than a Python start-up with the scientific stack.
rule admissibility:
    input:
        fits=f"{RESULTS}/fits/{{material}}.parquet",
        table=f"{RESULTS}/validated/{{material}}.parquet",
    output:
        scenarios=f"{RESULTS}/scenarios/{{material}}.parquet",
        figure=report(
            f"{RESULTS}/figures/sets_{{material}}.png",
            category="Admissible sets",
            caption="../report/sets.rst",
        ),
        surface=report(
            f"{RESULTS}/figures/surface_{{material}}.png",
            category="Response surfaces",
            caption="../report/surface.rst",
        ),
        figure_svg=f"{RESULTS}/figures/sets_{{material}}.svg",
        surface_svg=f"{RESULTS}/figures/surface_{{material}}.svg",
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

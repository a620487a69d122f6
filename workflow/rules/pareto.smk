# The grid predictions are recomputed from the fits (a second or two) rather than stored:
# the paste grid alone was 97 MB of parquet, read only here.
rule extract_pareto:
    input:
        fits=f"{RESULTS}/fits/{{material}}.parquet",
    output:
        table=f"{RESULTS}/tables/pareto_{{material}}.csv",
        figure=report(
            f"{RESULTS}/figures/pareto_{{material}}.png",
            category="Pareto trade-off",
            caption="../report/pareto.rst",
        ),
        figure_svg=f"{RESULTS}/figures/pareto_{{material}}.svg",
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

rule plot_surface:
    input:
        fits=f"{RESULTS}/fits/{{material}}.parquet",
        table=f"{RESULTS}/validated/{{material}}.parquet",
    output:
        figure=report(
            f"{RESULTS}/figures/surface_{{material}}.png",
            category="Response surfaces",
            caption="../report/surface.rst",
        ),
    params:
        spec=material_spec,
    resources:
        mem_mb=1000,
    conda:
        "../envs/demid.yaml"
    log:
        "logs/figures/surface_{material}.log",
    benchmark:
        "benchmarks/figures/surface_{material}.tsv"
    script:
        "../../scripts/plot_surface.py"


rule paper_figure:
    input:
        figure=paper_figure_source,
    output:
        figure=report(
            f"{RESULTS}/figures/{{paper_figure}}_{{material}}.png",
            category="Paper figures",
            caption="../report/paper_figure.rst",
        ),
    wildcard_constraints:
        paper_figure=paper_figure_pattern(),
    resources:
        mem_mb=100,
    conda:
        "../envs/demid.yaml"
    log:
        "logs/figures/{paper_figure}_{material}.log",
    benchmark:
        "benchmarks/figures/{paper_figure}_{material}.tsv"
    shell:
        "cp {input.figure} {output.figure} 2> {log}"

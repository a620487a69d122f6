rule plot_material:
    input:
        fits=f"{RESULTS}/fits/{{material}}.parquet",
        grid=f"{RESULTS}/grid/{{material}}.parquet",
        table=f"{RESULTS}/validated/{{material}}.parquet",
    output:
        sets=report(
            f"{RESULTS}/figures/sets_{{material}}.png",
            category="Admissible sets",
            caption="../report/sets.rst",
        ),
        surface=report(
            f"{RESULTS}/figures/surface_{{material}}.png",
            category="Response surfaces",
            caption="../report/surface.rst",
        ),
    params:
        material_cfg=material_cfg,
        grid_points=material_grid_points,
    conda:
        "../envs/demid.yaml"
    log:
        "logs/figures/{material}.log",
    benchmark:
        "benchmarks/figures/{material}.tsv"
    script:
        "../../scripts/plot_material.py"


rule plot_pareto:
    input:
        grid=f"{RESULTS}/grid/{{material}}.parquet",
        front=f"{RESULTS}/pareto/{{material}}.parquet",
    output:
        figure=report(
            f"{RESULTS}/figures/pareto_{{material}}.png",
            category="Pareto trade-off",
            caption="../report/pareto.rst",
        ),
    params:
        material_cfg=material_cfg,
    conda:
        "../envs/demid.yaml"
    log:
        "logs/figures/pareto_{material}.log",
    benchmark:
        "benchmarks/figures/pareto_{material}.tsv"
    script:
        "../../scripts/plot_pareto.py"


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
    conda:
        "../envs/demid.yaml"
    log:
        "logs/figures/{paper_figure}_{material}.log",
    benchmark:
        "benchmarks/figures/{paper_figure}_{material}.tsv"
    shell:
        "cp {input.figure} {output.figure} 2> {log}"

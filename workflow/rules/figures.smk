# A byte copy of a figure: run in Snakemake's own process (a non-local `run:` job would start a second
# Snakemake, which parses and validates the whole workflow again, to copy two files).
localrules:
    paper_figure,


rule paper_figure:
    input:
        figure=paper_figure_source,
        figure_svg=lambda wildcards: paper_figure_source(wildcards).removesuffix(".png") + ".svg",
    output:
        figure=report(
            f"{RESULTS}/figures/{{paper_figure}}_{{material}}.png",
            category="Paper figures",
            caption="../report/paper_figure.rst",
        ),
        figure_svg=f"{RESULTS}/figures/{{paper_figure}}_{{material}}.svg",
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
    run:
        # No shell: paths (results_dir may hold spaces or `$(...)`) reach the copy as arguments only.
        copy_files({input.figure: output.figure, input.figure_svg: output.figure_svg}, log[0])

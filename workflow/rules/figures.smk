# A byte copy of a figure, by a short script: a `run:` job, local or not, is started as a second Snakemake,
# which parses and validates the whole workflow again (2-3 s of a core) to copy two files; and no rule runs a
# shell (paths, results_dir among them, may hold spaces or `$(...)`).
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
        log_file("figures/{paper_figure}_{material}.log"),
    benchmark:
        benchmark_file("figures/{paper_figure}_{material}.tsv")
    script:
        "../../scripts/copy_figure.py"

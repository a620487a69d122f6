# A byte copy of a figure, by `cp` in Snakemake's own process: a `run:` job, local or not, is started as a
# second Snakemake, which parses and validates the whole workflow again (2-3 s of a core) to copy two files.
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
    shell:
        # every path quoted (:q): results_dir may hold spaces or `$(...)`, which reach cp as text only
        "cp -v -- {input.figure:q} {output.figure:q} > {log:q} && "
        "cp -v -- {input.figure_svg:q} {output.figure_svg:q} >> {log:q}"

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

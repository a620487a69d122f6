rule report:
    input:
        tables=report_tables(),
        figures=report_figures(),
        notebook=workflow.source_path("../notebooks/report.ipynb"),
    output:
        notebook=f"{RESULTS}/report/report.ipynb",
        html=f"{RESULTS}/report/report.html",
    params:
        config_json=config_json,
    conda:
        "../envs/demid.yaml"
    log:
        "logs/report/report.log",
    benchmark:
        "benchmarks/report/report.tsv"
    script:
        "../../scripts/report.py"

rule report_notebook:
    input:
        tables=report_tables(),
        figures=report_figures(),
        notebook=workflow.source_path("../notebooks/report.ipynb"),
    output:
        notebook=f"{RESULTS}/report/report.ipynb",
    params:
        config_json=config_json(),
    conda:
        "../envs/demid.yaml"
    log:
        "logs/report/notebook.log",
    benchmark:
        "benchmarks/report/notebook.tsv"
    script:
        "../../scripts/run_report.py"


rule report_html:
    input:
        notebook=f"{RESULTS}/report/report.ipynb",
    output:
        html=f"{RESULTS}/report/report.html",
    conda:
        "../envs/demid.yaml"
    log:
        "logs/report/html.log",
    benchmark:
        "benchmarks/report/html.tsv"
    script:
        "../../scripts/render_report.py"

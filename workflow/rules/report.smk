rule report:
    input:
        tables=report_tables(),
        figures=report_figures(),
        notebook=workflow.source_path("../notebooks/report.ipynb"),
    output:
        notebook=f"{RESULTS}/report/report.ipynb",
        html=f"{RESULTS}/report/report.html",
    params:
        config_json=report_config_json,
        published_digest=published_digest,  # the header quotes the published file's provenance
    resources:
        mem_mb=2000,
    conda:
        "../envs/demid.yaml"
    log:
        log_file("report/report.log"),
    benchmark:
        benchmark_file("report/report.tsv")
    script:
        "../../scripts/report.py"

rule validate_table:
    input:
        data=material_data,
    output:
        table=f"{RESULTS}/validated/{{material}}.parquet",
        summary=f"{RESULTS}/validated/{{material}}.json",
        transcription=f"{RESULTS}/validated/{{material}}_transcription.parquet",
    params:
        material_cfg=material_cfg,
    conda:
        "../envs/demid.yaml"
    log:
        "logs/validate/{material}.log",
    benchmark:
        "benchmarks/validate/{material}.tsv"
    script:
        "../../scripts/validate_table.py"

rule validate_table:
    input:
        data=material_data,
    output:
        table=f"{RESULTS}/validated/{{material}}.parquet",
        summary=f"{RESULTS}/validated/{{material}}.json",
        transcription=f"{RESULTS}/validated/{{material}}_transcription.parquet",
    params:
        spec=material_spec,
    conda:
        "../envs/demid.yaml"
    log:
        "logs/validate/{material}.log",
    benchmark:
        "benchmarks/validate/{material}.tsv"
    script:
        "../../scripts/validate_table.py"

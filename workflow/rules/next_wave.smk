rule next_wave:
    input:
        tables=expand(f"{RESULTS}/validated/{{material}}.parquet", material=next_wave_materials()),
        fits=expand(f"{RESULTS}/fits/{{material}}.parquet", material=next_wave_materials()),
        plausible=expand(f"{RESULTS}/uncertainty/{{material}}_robust.parquet", material=next_wave_materials()),
        findings=expand(f"{RESULTS}/criticism/{{material}}_findings.parquet", material=next_wave_materials()),
    output:
        domain=f"{RESULTS}/tables/next_domain.csv",
        runs=f"{RESULTS}/tables/next_runs.csv",
        reasons=f"{RESULTS}/next_wave/reasons.json",
        value=f"{RESULTS}/next_wave/value.json",
    params:
        specs=[SPECS[m] for m in next_wave_materials()],
        spec_digests=[SPECS[m].digest for m in next_wave_materials()],
        z=config["robust_z"],
    resources:
        mem_mb=1000,
    conda:
        "../envs/demid.yaml"
    log:
        log_file("next_wave/next_wave.log"),
    benchmark:
        benchmark_file("next_wave/next_wave.tsv")
    script:
        "../../scripts/next_wave.py"

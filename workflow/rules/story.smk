# One verdict per factor (on the plausible interval) and every piece of advice, computed once from the
# results tree: the report's summary, level 2 and next-wave sections all read these two tables.


def story_inputs():
    out = dict(
        identifiability=f"{RESULTS}/tables/identifiability.csv",
        robust=f"{RESULTS}/tables/robust_identifiability.csv",
        ranking=f"{RESULTS}/tables/observable_ranking.csv",
        tables=[f"{RESULTS}/validated/{m}.parquet" for m in MATERIALS],
        criticism=[f"{RESULTS}/criticism/{m}.json" for m in MATERIALS],
        uncertainty=[f"{RESULTS}/uncertainty/{m}.json" for m in MATERIALS],
    )
    if next_wave_materials():
        out["next_wave_value"] = f"{RESULTS}/next_wave/value.json"
        out["next_wave_reasons"] = f"{RESULTS}/next_wave/reasons.json"
    return out


STORY_TABLES = [f"{RESULTS}/tables/verdicts.csv", f"{RESULTS}/tables/advice.csv"]


localrules:
    story,


rule story:
    input:
        **story_inputs(),
    output:
        verdicts=STORY_TABLES[0],
        advice=STORY_TABLES[1],
    params:
        specs=[SPECS[m] for m in MATERIALS],
        spec_digests=[SPECS[m].digest for m in MATERIALS],
    resources:
        mem_mb=1000,
    conda:
        "../envs/demid.yaml"
    log:
        "logs/story/story.log",
    benchmark:
        "benchmarks/story/story.tsv"
    script:
        "../../scripts/story.py"

# One verdict per factor (on the plausible interval) and every piece of advice, computed once from the
# results tree: the report's summary, level 2 and next-wave sections all read these two tables.


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
        log_file("story/story.log"),
    benchmark:
        benchmark_file("story/story.tsv")
    script:
        "../../scripts/story.py"


localrules:
    model_extensions,


rule model_extensions:
    input:
        identifiability=f"{RESULTS}/tables/identifiability.csv",
        surrogate_fit=f"{RESULTS}/tables/surrogate_fit.csv",
        criticism=[f"{RESULTS}/criticism/{m}.json" for m in MATERIALS],
    output:
        table=MODEL_EXTENSIONS_TABLE,
    params:
        specs=[SPECS[m] for m in MATERIALS],
        extends={m: SPECS[m].extends or "" for m in MATERIALS},
    resources:
        mem_mb=500,
    conda:
        "../envs/demid.yaml"
    log:
        log_file("story/model_extensions.log"),
    benchmark:
        benchmark_file("story/model_extensions.tsv")
    script:
        "../../scripts/model_extensions.py"

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
        "logs/story/story.log",
    benchmark:
        "benchmarks/story/story.tsv"
    script:
        "../../scripts/story.py"

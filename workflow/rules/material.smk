# One job per material, from its transcribed table to every per-material output: validation, the
# fit, the scenario sets, uncertainty and criticism are each less work than a Python start-up
# with the scientific stack, so they share one (scripts/analyse_material.py, demid.steps).  The
# validated table, the fits and the scenario sets are still written as parquet intermediates.
# A material that declares `pareto:` adds its front, from the same grid predictions as its sets:
# the same rule with two more outputs.


rule analyse_material:
    input:
        data=material_data,
    output:
        **material_outputs(),
    wildcard_constraints:
        material=material_pattern(pareto=False),
    params:
        spec=material_spec,
        spec_digest=material_spec_digest,  # what Snakemake compares to rerun an edited material
        z=config["robust_z"],
        tolerances=config["sweep_tolerances"],
    resources:
        mem_mb=evaluation_mem_mb,
    conda:
        "../envs/demid.yaml"
    log:
        log_file("analyse_material/{material}.log"),
    benchmark:
        benchmark_file("analyse_material/{material}.tsv")
    script:
        "../../scripts/analyse_material.py"


use rule analyse_material as analyse_material_with_pareto with:
    output:
        **material_outputs(pareto=True),
    wildcard_constraints:
        material=material_pattern(pareto=True),

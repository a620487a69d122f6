# demid: which experiments identify the DEM micro-parameters, and what the simulation gets wrong.
# Run `snakemake -c2`; your own study: `snakemake -c2 --configfile their.yaml --directory their_dir`.

# The demonstration study; a --configfile given on the command line replaces it instead of
# being merged into it, so a user's study never inherits the demo materials.
if not workflow.overwrite_configfiles:

    configfile: "config.yaml"



include: "workflow/rules/common.smk"
include: "workflow/rules/material.smk"
include: "workflow/rules/figures.smk"
include: "workflow/rules/tables.smk"
include: "workflow/rules/next_wave.smk"
include: "workflow/rules/story.smk"
include: "workflow/rules/simulation_common.smk"
include: "workflow/rules/simulation.smk"
include: "workflow/rules/report.smk"


rule all:
    input:
        all_outputs(),
    default_target: True


rule smoke:
    input:
        smoke_outputs(),


onsuccess:
    cancel_scheduler_timers()


onerror:
    cancel_scheduler_timers()

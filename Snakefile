# demid: which experiments identify the DEM micro-parameters, and what the simulation gets wrong.
# Run `snakemake -c2`; your own study: `snakemake -c2 --configfile their.yaml --directory their_dir`.

import sys

from snakemake.utils import min_version

from demid.config_text import refuse_unsafe_config_files
from demid.errors import InputError

# The Snakemake features the rules use (requirements.in pins the same).
min_version("8.20")

# Each config file read as plain data first: a templated one (YTE) would run code while `configfile:` loads it.
try:
    refuse_unsafe_config_files(workflow.overwrite_configfiles or ["config.yaml"])
except InputError as err:
    sys.exit(f"demid: error: {err}")

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


# Material names or a paper_figure that would give two rules one output: one line naming the config key.
refuse_ambiguous_outputs(workflow.rules)


rule all:
    input:
        all_outputs(),
        refuse_a_second_run,
    default_target: True


rule smoke:
    input:
        smoke_outputs(),


onstart:
    claim_results()


onsuccess:
    cancel_scheduler_timers()


onerror:
    cancel_scheduler_timers()

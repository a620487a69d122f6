import os
import sys
from pathlib import Path

from demid.config import check_semantics, load_yaml, validate_schema
from demid.io import content_digest
from demid.data import check_table_columns, content_hidden_outside
from demid.errors import InputError
from demid.next_wave import check_next_runs
from demid.out_path import claim_results_dir, results_owner_problem
from demid.rule_outputs import ambiguous_output
from demid.sampling import uses_grid
from demid.spec import MaterialSpec
from demid.steps import output_table
from demid.waves import check_simulated, simulated_materials


# Validate the config (schema with defaults, then cross-references) and that every table can be read
# and has its columns before any job is scheduled: a config error stops here with one line, and
# nothing is written.  Each table's cells, design and likely typos, and the material's labels
# (matplotlib's mathtext parser, the costliest check), are checked once, in its job
# (demid.steps.validate_step), which stops with the same one line.
CONFIG_SOURCE = ", ".join(str(p) for p in workflow.overwrite_configfiles) or "config.yaml"

try:
    for _configfile in workflow.overwrite_configfiles or ["config.yaml"]:
        if Path(_configfile).is_file():
            load_yaml(_configfile)  # Snakemake's own reading keeps the last of a repeated key silently
    _checked = validate_schema(dict(config), source=CONFIG_SOURCE)
    config.clear()
    config.update(_checked)
    check_semantics(config, source=CONFIG_SOURCE, labels=False)  # labels: in each material's job
    check_next_runs(config, source=CONFIG_SOURCE)
    check_simulated(config, source=CONFIG_SOURCE)
    # One MaterialSpec per material, built once from the validated config; rules pass it as their
    # only per-material parameter.
    SPECS = {name: MaterialSpec.from_config(name, config) for name in config["materials"]}
    for _spec in SPECS.values():
        if _spec.simulated:  # its tables do not exist yet: each wave validates its own
            continue
        with content_hidden_outside(_spec.data):
            check_table_columns(_spec)
except InputError as err:
    sys.exit(f"demid: error: {err}")


# The jobs allocate short-lived arrays of hundreds of MB (paste's grid has 8.1 million nodes).  numpy
# asks the kernel to back them with transparent huge pages, and where the kernel compacts memory to
# find them (THP defrag "madvise") each fault stalls: on the 2-core demo machine that was about a
# third of the paste job's system time.  Jobs inherit this; a value set by the user wins.
os.environ.setdefault("NUMPY_MADVISE_HUGEPAGE", "0")
# Each job is one thread (no rule asks for more).  OpenBLAS would start one per core for every large
# product: with one job per core those threads only wait for each other, spinning (the paste grid's
# prediction took 1.3 s of CPU instead of 0.3), and how a product is split among them depends on the
# machine's core count, which can move a last bit: one thread, the same numbers whatever the core count.
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

RESULTS = config["results_dir"]
if results_owner_problem(RESULTS, Path.cwd()):  # another study's results: refused before anything runs
    sys.exit(f"demid: error: {results_owner_problem(RESULTS, Path.cwd())}")
MATERIALS = list(SPECS)


def log_file(name):
    """A job's log, under the results folder: a study run from its own folder (--directory) gets
    everything the workflow writes in its results_dir, and its own files stay as they were."""
    return f"{RESULTS}/logs/{name}"


def benchmark_file(name):
    """A job's timings and memory (Snakemake's benchmark), under the results folder like its log."""
    return f"{RESULTS}/benchmarks/{name}"


# The cross-material tables: summary_tables' output name -> file under tables/.
SUMMARY_TABLE_FILES = {
    "surrogate_fit": "surrogate_fit",
    "identifiability": "identifiability",
    "transcription": "transcription_check",
    "plausible": "robust_identifiability",
    "sweep": "tolerance_sweep",
    "information_gain": "information_gain",
    "ranking": "observable_ranking",
    "findings": "criticism",
    "calibration": "calibration_residuals",
    "columns": "columns",
    "combinations": "combinations",
}
SUMMARY_TABLES = [f"{RESULTS}/tables/{stem}.csv" for stem in SUMMARY_TABLE_FILES.values()]


wildcard_constraints:
    material="|".join(MATERIALS),


def material_spec(wildcards):
    return SPECS[wildcards.material]


def material_spec_digest(wildcards):
    """The material's settings and the content of its table: either edited (even while the job runs)
    reruns the job."""
    table = SPECS[wildcards.material].data  # none for a simulated material: its runs
    return f"{SPECS[wildcards.material].digest}:{content_digest(table) if table else ''}"  # are jobs of their own


def published_digest(wildcards=None):
    """The content of the published-values file ("" without one): an edit reruns what reads it."""
    return content_digest(config["published"]) if config.get("published") else ""


def material_data(wildcards):
    return SPECS[wildcards.material].data


def evaluation_mem_mb(wildcards):
    """Memory of a job that holds every evaluation point's predictions (about 3 copies of 8-byte values)."""
    spec = SPECS[wildcards.material]
    points = spec.grid_points ** spec.dim if uses_grid(spec.dim) else spec.grid_points
    return 1000 + int(24 * points * (spec.dim + len(spec.responses)) / 1e6)


def pareto_materials():
    return [m for m in MATERIALS if SPECS[m].pareto]


def material_pattern(pareto, simulated=False):
    """The materials with (or without) a Pareto front, as a wildcard constraint (none: matches nothing);
    those with a finished table, or with ``simulated`` those demid simulates."""
    names = [m for m in MATERIALS if bool(SPECS[m].pareto) == pareto and SPECS[m].simulated == simulated]
    return "|".join(names) if names else "(?!x)x"


def paper_figures():
    return [
        f"{RESULTS}/figures/{SPECS[m].paper_figure}_{m}.png" for m in MATERIALS if SPECS[m].paper_figure
    ]


def paper_figure_pattern():
    names = sorted({SPECS[m].paper_figure for m in MATERIALS if SPECS[m].paper_figure})
    return "|".join(names) if names else "(?!x)x"


def paper_figure_source(wildcards):
    kind = "pareto" if SPECS[wildcards.material].pareto else "sets"
    return f"{RESULTS}/figures/{kind}_{wildcards.material}.png"


def next_wave_materials():
    return [m for m in MATERIALS if SPECS[m].next_runs]


def next_wave_columns():
    """(name, unit) of the factors and responses that appear in the next-wave tables."""
    factors, responses = {}, {}
    for m in next_wave_materials():
        factors.update((f.name, f.unit) for f in SPECS[m].factors)
        responses.update((r.name, r.unit) for r in SPECS[m].responses)
    if not factors:
        return {}
    return {"factors": sorted(factors.items()), "responses": sorted(responses.items())}


def next_wave_tables():
    """The next-wave tables exist only when some material asks for next_runs."""
    if not next_wave_materials():
        return []
    return [f"{RESULTS}/tables/next_domain.csv", f"{RESULTS}/tables/next_runs.csv",
            f"{RESULTS}/next_wave/reasons.json"]


def per_material_outputs(material):
    out = [
        f"{RESULTS}/validated/{material}.parquet",
        f"{RESULTS}/fits/{material}.parquet",
        f"{RESULTS}/scenarios/{material}.parquet",
        f"{RESULTS}/figures/sets_{material}.png",
        f"{RESULTS}/figures/surface_{material}.png",
    ]
    if SPECS[material].pareto:
        out += [
            f"{RESULTS}/tables/pareto_{material}.csv",
            f"{RESULTS}/figures/pareto_{material}.png",
        ]
    return out


SUMMARY_INPUTS = {
    "statistics": "fits/{material}_statistics.parquet",
    "scenarios": "scenarios/{material}.parquet",
    "transcription": "validated/{material}_transcription.parquet",
    "plausible": "uncertainty/{material}_robust.parquet",
    "sweep": "uncertainty/{material}_sweep.parquet",
    "information_gain": "uncertainty/{material}_information_gain.parquet",
    "ranking": "uncertainty/{material}_ranking.parquet",
    "findings": "criticism/{material}_findings.parquet",
    "calibration": "criticism/{material}_calibration.parquet",
    "combinations": "combinations/{material}.parquet",
}


def summary_inputs():
    """Named inputs of summary_tables: each per-material intermediate it stacks, and, where the
    config names a published-values file, that file and the Pareto tables it is compared with."""
    out = {name: [f"{RESULTS}/{path.format(material=m)}" for m in MATERIALS] for name, path in SUMMARY_INPUTS.items()}
    if config.get("published"):
        out["published"] = config["published"]
        out["pareto"] = [f"{RESULTS}/tables/pareto_{m}.csv" for m in pareto_materials()]
    return out


def summary_outputs():
    """Named outputs of summary_tables: the cross-material tables, and the paper comparison where
    the config names a published-values file (one job: it reads two of those tables back)."""
    out = {name: f"{RESULTS}/tables/{stem}.csv" for name, stem in SUMMARY_TABLE_FILES.items()}
    if config.get("published"):
        out["paper_comparison"] = f"{RESULTS}/tables/paper_comparison.csv"
    return out


def report_tables():
    out = list(SUMMARY_TABLES)
    out += [f"{RESULTS}/tables/pareto_{m}.csv" for m in pareto_materials()]
    out += [f"{RESULTS}/validated/{m}.json" for m in MATERIALS]
    out += [f"{RESULTS}/validated/{m}.parquet" for m in MATERIALS]  # with the stored fits: the rsm tables
    out += [f"{RESULTS}/fits/{m}.parquet" for m in MATERIALS]
    out += [f"{RESULTS}/fits/{m}_anova.parquet" for m in MATERIALS]
    out += [f"{RESULTS}/fits/{m}_diagnostics.parquet" for m in MATERIALS]
    if config.get("published"):
        out.append(f"{RESULTS}/tables/paper_comparison.csv")
    out += [f"{RESULTS}/uncertainty/{m}.json" for m in MATERIALS]
    out += [f"{RESULTS}/criticism/{m}.json" for m in MATERIALS]
    out += next_wave_tables()
    out += [f"{RESULTS}/combinations/{m}.json" for m in MATERIALS]
    out += [f"{RESULTS}/fits/{m}.json" for m in MATERIALS]
    out += [f"{RESULTS}/tables/verdicts.csv", f"{RESULTS}/tables/advice.csv"]  # rule story
    out.append(MODEL_EXTENSIONS_TABLE)  # rule model_extensions
    out += [f"{RESULTS}/waves/summary_{m}.json" for m in simulated_materials(config)]  # the Waves section
    return out


def report_figures():
    out = []
    for m in MATERIALS:
        out += [f"{RESULTS}/figures/sets_{m}.png", f"{RESULTS}/figures/surface_{m}.png"]
        if SPECS[m].pareto:
            out.append(f"{RESULTS}/figures/pareto_{m}.png")
        out += [
            f"{RESULTS}/figures/sweep_{m}.png",
            f"{RESULTS}/figures/posterior_{m}.png",
            f"{RESULTS}/figures/residuals_{m}.png",
            f"{RESULTS}/figures/combinations_{m}.png",
        ]
        if config["materials"][m].get("simulation"):
            out.append(f"{RESULTS}/figures/waves_{m}.png")
    return out


def report_config_json(wildcards):
    """What the report reads of the config: the materials (labels, units, scenarios) and the
    published-values file.  A function, not a string: Snakemake would read braces in labels or
    units as wildcards."""
    import json

    return json.dumps({"materials": config["materials"], "published": config.get("published")})


def with_svg(figures):
    """Every figure is written as PNG and as SVG (vector, for a paper)."""
    return [f for png in figures for f in (png, png.removesuffix(".png") + ".svg")]


def material_outputs(pareto=False):
    """Named outputs of a material's job (analyse_material), from the one table of them
    (demid.steps.MATERIAL_OUTPUTS, whose names the job's result uses); with ``pareto`` also the
    front's table and figure."""
    out = {}
    for name, entry in output_table(pareto).items():
        path = f"{RESULTS}/{entry.path}"
        if entry.caption:
            path = report(path, category=entry.category, caption=f"../report/{entry.caption}")
        out[name] = directory(path) if entry.directory else path
    return out


def all_outputs():
    out = [o for m in MATERIALS for o in per_material_outputs(m)]
    out += with_svg(paper_figures())
    out += with_svg(report_figures())
    out += SUMMARY_TABLES
    out += [f"{RESULTS}/criticism/{m}" for m in MATERIALS]
    out += next_wave_tables()
    out += [f"{RESULTS}/tables/verdicts.csv", f"{RESULTS}/tables/advice.csv"]  # rule story
    out.append(MODEL_EXTENSIONS_TABLE)  # rule model_extensions
    out += wave_history_outputs()  # workflow/rules/simulation_common.smk
    out.append(f"{RESULTS}/report/report.html")
    if config.get("published"):
        out.append(f"{RESULTS}/tables/paper_comparison.csv")
    return out


def smoke_outputs():
    return per_material_outputs(config.get("smoke_material") or MATERIALS[0])


def cancel_scheduler_timers():
    """Let Snakemake exit as soon as the run is done.  Its scheduler looks at the queue again on a
    one-second timer (--max-jobs-per-timespan) and sets one more after the last job; Python waits for
    that timer before exiting, which added up to a second to every run."""
    import threading

    for thread in threading.enumerate():
        if isinstance(thread, threading.Timer):
            thread.cancel()


# Inputs and outputs of the story step (workflow/rules/story.smk), verdicts and advice computed once.
def story_inputs():
    out = dict(
        identifiability=f"{RESULTS}/tables/identifiability.csv",
        plausible=f"{RESULTS}/tables/robust_identifiability.csv",
        ranking=f"{RESULTS}/tables/observable_ranking.csv",
        tables=[f"{RESULTS}/validated/{m}.parquet" for m in MATERIALS],
        criticism=[f"{RESULTS}/criticism/{m}.json" for m in MATERIALS],
        uncertainty=[f"{RESULTS}/uncertainty/{m}.json" for m in MATERIALS],
        combinations=[f"{RESULTS}/combinations/{m}.json" for m in MATERIALS],
    )
    if next_wave_materials():
        out["next_wave_value"] = f"{RESULTS}/next_wave/value.json"
    if simulated_materials(config):  # why each simulated material's loop stopped (rule wave_history)
        out["wave_summaries"] = [f"{RESULTS}/waves/summary_{m}.json" for m in simulated_materials(config)]
    return out


# A material that extends another's model, against it (workflow/rules/story.smk, rule model_extensions).
MODEL_EXTENSIONS_TABLE = f"{RESULTS}/tables/model_extensions.csv"

STORY_TABLES = [f"{RESULTS}/tables/verdicts.csv", f"{RESULTS}/tables/advice.csv"]


def refuse_a_second_run(wildcards=None):
    """A run started where another is still writing would stop on the other run's unfinished files
    (IncompleteFilesException) without saying why: it names the lock and what to do instead.  Checked
    while the DAG is built (not at parse time: only then is a dry run known); dry runs, --nolock,
    --unlock, --summary and the jobs of a cluster run are not concerned."""
    if workflow.executor_plugin is None or workflow.dryrun or workflow.remote_exec or workflow.subprocess_exec:
        return []
    if not workflow.execution_settings.lock:
        return []
    locks = Path(".snakemake", "locks")
    if locks.is_dir() and any(locks.iterdir()):
        sys.stderr.write(f"demid: error: another run is writing in {Path.cwd()} (Snakemake's lock in "
                         ".snakemake/locks); wait until it finishes, or, if none is running (it was stopped), "
                         "run snakemake --unlock with the same options, then snakemake --rerun-incomplete\n")
        sys.stderr.flush()
        os._exit(1)  # from inside the DAG's construction: nothing written, nothing to clean up
    return []


def refuse_ambiguous_outputs(rules):
    """Stop with one line naming the config key when material names or a paper_figure would give two
    rules (or one rule for two materials) the same output file (demid.rule_outputs)."""
    from snakemake.io import strip_wildcard_constraints

    patterns = [(strip_wildcard_constraints(str(f)), f.wildcard_constraints()) for r in rules for f in r.output]
    problem = ambiguous_output(patterns, config["materials"])
    if problem:
        sys.exit(f"demid: error: {problem}")


def claim_results():
    """At the start of a run (not a dry run): results_dir names this study folder, and a second study
    pointing at it is refused (demid.out_path.claim_results_dir)."""
    problem = claim_results_dir(RESULTS, Path.cwd())
    if problem:
        sys.stderr.write(f"demid: error: {problem}\n")
        sys.stderr.flush()
        os._exit(1)  # before any job: nothing written, nothing to clean up

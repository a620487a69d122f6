# Materials with `simulation:` instead of `data:`: demid runs the simulations, wave after wave.
#
#   simulate_run    one job per run: results/runs/<material>/wave<k>/run<r>/ (params.json, the
#                   command's responses file, run.json with status ok/failed, log); resources from
#                   `simulation:`, so a cluster profile sends each run as its own job
#   assemble_wave   the material's table after wave k: every run so far (with `wave` and `status`),
#                   and the runs inside wave k's search box, which wave k analyses
#   analyse_wave    the per-material analysis of wave k, under results/waves/<k>/
#   propose_wave    (a checkpoint) wave k's next runs and refocused box: wave k+1 simulates them
#   final_wave      the material's main results are its last wave's (copies), for the tables and report
#   wave_history    the admissible sets wave by wave: waves/history_<material>.csv, figures/waves_<material>,
#                   and waves/summary_<material>.json (per wave runs, surrogate, plausible set; the stop decision)
#
# Wave 1's runs are the declared design (known when the workflow is read); wave k+1's are wave k's
# proposals, known once that checkpoint has run.  Each run's factor values, seed and command are the
# job's params, so an edited bound or command reruns exactly the runs it changes.

# Assembling a table and copying the last wave's files are cheap: on a cluster they run on the
# submitting host; every simulation run and each wave's analysis is a job of its own.
localrules:
    assemble_wave,
    final_wave,
    final_wave_with_pareto,


rule simulate_run:
    output:
        params=f"{WAVE_RUN}/params.json",
        record=f"{WAVE_RUN}/run.json",
    wildcard_constraints:
        material=simulated_pattern(),
        wave=r"[1-9][0-9]*",
        run=r"[1-9][0-9]*",
    params:
        run=simulate_run_parameters,  # factor values, seed, command: a change reruns this run only
        responses=lambda wildcards: SPECS[wildcards.material].response_names,
    threads: lambda wildcards: SIMULATIONS[wildcards.material].threads
    retries: SIMULATION_RETRIES
    resources:
        mem_mb=lambda wildcards: SIMULATIONS[wildcards.material].mem_mb,
        runtime=lambda wildcards: SIMULATIONS[wildcards.material].runtime_resource,
        cpus_per_task=lambda wildcards: SIMULATIONS[wildcards.material].threads,  # a cluster's CPUs per run
        attempt=lambda wildcards, attempt: attempt,  # the script retries a failed run until the last one
    conda:
        "../envs/demid.yaml"
    log:
        f"{WAVE_RUN}/log",
    benchmark:
        benchmark_file("simulate_run/{material}/wave{wave}/run{run}.tsv")
    script:
        "../../scripts/simulate_run.py"


rule assemble_wave:
    input:
        unpack(assemble_inputs),
    output:
        table=f"{RESULTS}/waves/{{wave}}/data/{{material}}.csv",
        analysed=f"{RESULTS}/waves/{{wave}}/data/{{material}}_analysed.csv",
    wildcard_constraints:
        material=simulated_pattern(),
        wave=r"[1-9][0-9]*",
    params:
        factors=lambda wildcards: SPECS[wildcards.material].factor_names,
        responses=lambda wildcards: SPECS[wildcards.material].response_names,
    resources:
        mem_mb=1000,
    conda:
        "../envs/demid.yaml"
    log:
        log_file("assemble_wave/{material}_wave{wave}.log"),
    benchmark:
        benchmark_file("assemble_wave/{material}_wave{wave}.tsv")
    script:
        "../../scripts/assemble_wave.py"


rule analyse_wave:
    input:
        unpack(wave_domain),
        data=f"{RESULTS}/waves/{{wave}}/data/{{material}}_analysed.csv",
    output:
        **wave_outputs(),
    wildcard_constraints:
        material=simulated_pattern(pareto=False),
        wave=r"[1-9][0-9]*",
    params:
        spec=material_spec,
        spec_digest=material_spec_digest,
        z=config["robust_z"],
        tolerances=config["sweep_tolerances"],
    resources:
        mem_mb=evaluation_mem_mb,
    conda:
        "../envs/demid.yaml"
    log:
        log_file("analyse_wave/{material}_wave{wave}.log"),
    benchmark:
        benchmark_file("analyse_wave/{material}_wave{wave}.tsv")
    script:
        "../../scripts/analyse_wave.py"


use rule analyse_wave as analyse_wave_with_pareto with:
    output:
        **wave_outputs(pareto=True),
    wildcard_constraints:
        material=simulated_pattern(pareto=True),
        wave=r"[1-9][0-9]*",


checkpoint propose_wave:
    input:
        unpack(wave_domain),
        unpack(previous_decision),  # the measured change of the plausible set since the previous wave
        data=f"{RESULTS}/waves/{{wave}}/data/{{material}}_analysed.csv",
        tables=f"{RESULTS}/waves/{{wave}}/validated/{{material}}.parquet",
        fits=f"{RESULTS}/waves/{{wave}}/fits/{{material}}.parquet",
        plausible=f"{RESULTS}/waves/{{wave}}/uncertainty/{{material}}_robust.parquet",
        findings=f"{RESULTS}/waves/{{wave}}/criticism/{{material}}_findings.parquet",
        statistics=f"{RESULTS}/waves/{{wave}}/fits/{{material}}_statistics.parquet",
        criticism=f"{RESULTS}/waves/{{wave}}/criticism/{{material}}.json",
    output:
        **proposal_files("{material}", "{wave}"),
    wildcard_constraints:
        material=simulated_pattern(proposing=True),
        wave=r"[1-9][0-9]*",
    params:
        spec=material_spec,
        spec_digest=material_spec_digest,
        z=config["robust_z"],
    resources:
        mem_mb=1000,
    conda:
        "../envs/demid.yaml"
    log:
        log_file("propose_wave/{material}_wave{wave}.log"),
    benchmark:
        benchmark_file("propose_wave/{material}_wave{wave}.tsv")
    script:
        "../../scripts/propose_wave.py"


rule final_wave:
    input:
        unpack(final_wave_inputs(pareto=False)),
    output:
        **material_outputs(),
    wildcard_constraints:
        material=simulated_pattern(pareto=False),
    resources:
        mem_mb=500,
    conda:
        "../envs/demid.yaml"
    log:
        log_file("final_wave/{material}.log"),
    benchmark:
        benchmark_file("final_wave/{material}.tsv")
    script:
        "../../scripts/final_wave.py"


use rule final_wave as final_wave_with_pareto with:
    input:
        unpack(final_wave_inputs(pareto=True)),
    output:
        **material_outputs(pareto=True),
    wildcard_constraints:
        material=simulated_pattern(pareto=True),


rule wave_history:
    input:
        unpack(wave_history_inputs),
    output:
        table=f"{RESULTS}/waves/history_{{material}}.csv",
        summary=f"{RESULTS}/waves/summary_{{material}}.json",
        figure=f"{RESULTS}/figures/waves_{{material}}.png",
        svg=f"{RESULTS}/figures/waves_{{material}}.svg",
    wildcard_constraints:
        material=simulated_pattern(),
    params:
        spec=material_spec,
        spec_digest=material_spec_digest,
    resources:
        mem_mb=1000,
    conda:
        "../envs/demid.yaml"
    log:
        log_file("wave_history/{material}.log"),
    benchmark:
        benchmark_file("wave_history/{material}.tsv")
    script:
        "../../scripts/wave_history.py"

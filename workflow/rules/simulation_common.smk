# Functions of the simulation rules (workflow/rules/simulation.smk): which runs each wave of a
# simulated material has, and which files its jobs read and write.

import json

import pandas as pd

from demid.simulation import Simulation, run_parameters
from demid.waves import first_wave, next_wave_runs, stops_early, waves_max

SIMULATED = [m for m in MATERIALS if SPECS[m].simulated]
SIMULATIONS = {m: Simulation.from_material(SPECS[m].material_config()) for m in SIMULATED}
FIRST_WAVES = {m: first_wave(SPECS[m], SIMULATIONS[m].seed) for m in SIMULATED}
# A rule's retries are one number; a material with fewer records its failed run at its own last attempt.
SIMULATION_RETRIES = max((s.retries for s in SIMULATIONS.values()), default=0)
WAVE_RUN = f"{RESULTS}/runs/{{material}}/wave{{wave}}/run{{run}}"


def simulated_pattern(pareto=None, proposing=False):
    """The simulated materials (with or without a Pareto front; with ``proposing`` those whose waves
    propose next runs) as a wildcard constraint (none: matches nothing)."""
    names = [m for m in SIMULATED
             if (pareto is None or bool(SPECS[m].pareto) == pareto)
             and (not proposing or SPECS[m].waves.get("next_runs"))]
    return "|".join(names) if names else "(?!x)x"


def proposal_files(material, wave):
    folder = f"{RESULTS}/waves/{wave}/next_wave/{material}"
    return {"domain": f"{folder}/next_domain.csv", "runs": f"{folder}/next_runs.csv",
            "reasons": f"{folder}/reasons.json", "decision": f"{folder}/decision.json"}


def wave_runs(material, wave):
    """Wave ``wave``'s runs (``run`` and one column per factor); after wave 1, read from the previous
    wave's proposals, so only once the checkpoints up to it have run (see planned_wave_runs)."""
    wave = int(wave)
    if wave == 1:
        return FIRST_WAVES[material]
    first = int(wave_runs(material, wave - 1)["run"].max()) + 1
    proposals = pd.read_csv(proposal_files(material, wave - 1)["runs"])
    return next_wave_runs(proposals, SPECS[material].factor_names, first)


def planned_wave_runs(material, wave):
    """wave_runs after the checkpoints that fix them (for input functions: Snakemake re-evaluates them
    once those have run)."""
    for earlier in range(1, int(wave)):
        checkpoints.propose_wave.get(material=material, wave=str(earlier))
    return wave_runs(material, wave)


def simulate_run_parameters(wildcards):
    runs = wave_runs(wildcards.material, wildcards.wave).set_index("run")
    values = runs.loc[int(wildcards.run), SPECS[wildcards.material].factor_names]
    return run_parameters(wildcards.material, int(wildcards.wave), int(wildcards.run), values.to_dict(),
                          SIMULATIONS[wildcards.material])


def wave_domain(wildcards):
    """Wave k's search box: wave k-1's refocused box (none for wave 1, analysed over the config's bounds)."""
    wave = int(wildcards.wave)
    return {"domain": proposal_files(wildcards.material, wave - 1)["domain"]} if wave > 1 else {}


def previous_decision(wildcards):
    """Wave k-1's decision (none for wave 1): the plausible share of Omega it measured."""
    wave = int(wildcards.wave)
    return {"previous": proposal_files(wildcards.material, wave - 1)["decision"]} if wave > 1 else {}


def assemble_inputs(wildcards):
    runs = [(w, r) for w in range(1, int(wildcards.wave) + 1)
            for r in planned_wave_runs(wildcards.material, w)["run"]]
    folders = [WAVE_RUN.format(material=wildcards.material, wave=w, run=r) for w, r in runs]
    return {"params": [f"{d}/params.json" for d in folders], "records": [f"{d}/run.json" for d in folders],
            **wave_domain(wildcards)}


def wave_outputs(pareto=False):
    """A material's outputs (material_outputs) under results/waves/<k>/."""
    out = {}
    for name, entry in output_table(pareto).items():
        path = f"{RESULTS}/waves/{{wave}}/{entry.path}"
        out[name] = directory(path) if entry.directory else path
    return out


def last_wave(material):
    """The material's last wave: waves.max, or the first whose advice says stop."""
    wave = 1
    while wave < waves_max(SPECS[material]):
        decision = checkpoints.propose_wave.get(material=material, wave=str(wave)).output.decision
        if stops_early(SPECS[material]) and json.loads(Path(decision).read_text(encoding="utf-8"))["stop"]:
            break
        wave += 1
    return wave


def final_wave_inputs(pareto):
    def inputs(wildcards):
        wave = last_wave(wildcards.material)
        out = {name: str(path).format(material=wildcards.material, wave=wave)
               for name, path in wave_outputs(pareto).items()}
        if SPECS[wildcards.material].waves.get("next_runs"):
            out.update({f"proposal_{k}": v for k, v in proposal_files(wildcards.material, wave).items()})
        return out

    return inputs




def wave_history_inputs(wildcards):
    """Every wave of the material up to its last: scenario sets, boxes and tables."""
    m, last = wildcards.material, last_wave(wildcards.material)
    waves = range(1, last + 1)
    return {"scenarios": [f"{RESULTS}/waves/{k}/scenarios/{m}.parquet" for k in waves],
            "domains": [proposal_files(m, k - 1)["domain"] for k in waves if k > 1],
            "tables": [f"{RESULTS}/waves/{k}/data/{m}.csv" for k in waves],
            "analysed": [f"{RESULTS}/waves/{k}/data/{m}_analysed.csv" for k in waves],
            "plausible": [f"{RESULTS}/waves/{k}/uncertainty/{m}_robust.parquet" for k in waves],
            "statistics": [f"{RESULTS}/waves/{k}/fits/{m}_statistics.parquet" for k in waves],
            **({"decision": proposal_files(m, last)["decision"]}
               if (config["materials"][m].get("waves") or {}).get("next_runs") else {})}


def wave_history_outputs():
    """The wave-by-wave table and figure of every simulated material."""
    return [f for m in SIMULATED for f in (f"{RESULTS}/waves/history_{m}.csv", f"{RESULTS}/waves/summary_{m}.json",
                                           *with_svg([f"{RESULTS}/figures/waves_{m}.png"]))]

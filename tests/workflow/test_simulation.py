"""demid runs the simulations: commands without a shell, failed runs as failed rows, seeds, and the
waves driven by Snakemake (one job per run, cached, reruns only what an edit changes)."""

from __future__ import annotations

import hashlib
import json
import re
import shutil
import sys
import time
from pathlib import Path

import pandas as pd
import pytest

from demid.config import check_semantics, validate_schema
from demid.errors import InputError
from demid.io import read_parquet
from demid.simulation import FAILED, OK, assemble_table, execute, fill_command, run_seed
from demid.spec import MaterialSpec
from demid.waves import check_simulated, first_wave

from ..workflow_helpers import planned_jobs, run_snakemake, tree_hashes

SIMULATOR = Path(__file__).resolve().parents[1] / "simulator.py"


def _command(extra: str = "") -> str:
    return (f"{sys.executable} {SIMULATOR} --a {{a}} --b {{b}} --seed {{seed}} --run {{run}} "
            f"--out {{run_dir}}/responses.json {extra}").strip()


def _material(command: str, **extra) -> dict:
    mat = {"design": {"type": "ccd", "alpha": 1.41421, "center_runs": 3},
           "simulation": {"command": command, "runtime_min": 0.05, "retries": 0},
           "factors": {"a": {"lower": 0.1, "upper": 0.9}, "b": {"lower": 1.0, "upper": 11.0}},
           "responses": {"y1": {"target": 115}, "y2": {"target": 95}},
           "scenarios": {"both": {"observables": ["y1", "y2"], "tolerance": 0.02}}}
    mat.update(extra)
    return mat


def _checked(materials: dict) -> dict:
    config = validate_schema({"materials": materials})
    check_semantics(config)
    check_simulated(config)
    return config


# ---------------------------------------------------------------------------------------- one run
def _parameters(run: int, command: str, a: float = 0.5, b: float = 6.0) -> dict:
    return {"material": "m", "wave": 1, "run": run, "seed": run_seed("m", 1, run), "factors": {"a": a, "b": b},
            "command": command, "responses_file": "responses.json"}


def _execute(parameters: dict, run_dir: Path, responses) -> tuple[dict, str]:
    """execute() with a log file, as the workflow gives it; the record and the log's text."""
    run_dir.mkdir(parents=True, exist_ok=True)
    with open(run_dir / "log", "w", encoding="utf-8") as log:
        record = execute(parameters, run_dir, responses, log, timeout_s=3)
    return record, (run_dir / "log").read_text(encoding="utf-8")


def test_a_run_reads_its_responses_and_each_failure_becomes_a_failed_record(tmp_path):
    record, _ = _execute(_parameters(1, _command()), tmp_path / "ok", ["y1", "y2"])
    assert record["status"] == OK and record["reason"] == ""
    # the simulator's quadratic with its seeded 0.3 % noise: within 2 % of the noise-free value
    assert record["responses"]["y1"] == pytest.approx(100 + 10 - 12 + 2.5 + 1.5 + 0.375, rel=0.02)
    cases = {"exit": "exited with status 3", "hang": "timed out after 3 s", "garbage": "not valid JSON",
             "nan": "'y2' is nan", "missing": "wrote no responses.json"}
    for mode, reason in cases.items():
        record, log = _execute(_parameters(2, _command(f"--fail {mode}:2")), tmp_path / mode, ["y1", "y2"])
        assert record["status"] == FAILED, mode
        assert reason in record["reason"], (mode, record["reason"])
        assert record["responses"] == {}
        assert f"status: failed ({record['reason']})" in log
    # a response the command does not write, and a command that cannot start
    record, _ = _execute(_parameters(3, _command()), tmp_path / "lacking", ["y1", "y3"])
    assert record["status"] == FAILED and "'y3' is missing" in record["reason"]
    record, _ = _execute(_parameters(3, "no-such-program-here {a}"), tmp_path / "absent", ["y1"])
    assert record["status"] == FAILED and "could not start" in record["reason"]


def _alive(pid: int) -> bool:
    try:
        state = Path(f"/proc/{pid}/status").read_text(encoding="utf-8")
    except FileNotFoundError:
        return False
    return "\nState:\tZ" not in state  # a zombie has stopped; only its exit status is left


def test_a_timeout_stops_what_the_command_started_too(tmp_path):
    pidfile = tmp_path / "child.pid"
    command = f"sh -c 'sleep 60 & echo $! > {pidfile}; wait'"
    record, _ = _execute(_parameters(1, command), tmp_path / "run", ["y1"])
    assert record["status"] == FAILED and "timed out" in record["reason"]
    pid = int(pidfile.read_text(encoding="utf-8"))
    deadline = time.monotonic() + 5
    while _alive(pid) and time.monotonic() < deadline:
        time.sleep(0.05)
    assert not _alive(pid)


def test_a_stale_responses_file_of_an_earlier_attempt_is_not_read(tmp_path):
    (tmp_path / "responses.json").write_text('{"y1": 1, "y2": 2}', encoding="utf-8")
    record, _ = _execute(_parameters(2, _command("--fail missing:2")), tmp_path, ["y1", "y2"])
    assert record["status"] == FAILED and "wrote no responses.json" in record["reason"]


def test_placeholders_fill_words_and_never_make_shell_syntax(tmp_path):
    argv = fill_command("sim --x={a} '{run_dir}/out file.json' {seed} {{literal}}",
                        {"a": 0.25, "run_dir": "/r/a b;c", "seed": 7})
    assert argv == ["sim", "--x=0.25", "/r/a b;c/out file.json", "7", "{literal}"]
    # Shell syntax written into the command (or reaching it through a value) is passed as plain text.
    received = tmp_path / "argv.txt"
    command = _command(f"--argv-log {received} '$(touch {tmp_path}/INJECTED)' ';' touch {tmp_path}/INJECTED2 "
                       f"'`touch {tmp_path}/INJECTED3`' '|' '&&' '>' {tmp_path}/INJECTED4")
    record, _ = _execute(_parameters(1, command), tmp_path / "run", ["y1", "y2"])
    assert record["status"] == OK
    assert not list(tmp_path.glob("INJECTED*"))
    words = received.read_text(encoding="utf-8").splitlines()
    assert f"$(touch {tmp_path}/INJECTED)" in words and ";" in words and f"`touch {tmp_path}/INJECTED3`" in words


def test_seeds_are_fixed_by_material_wave_and_run():
    expected = int.from_bytes(hashlib.sha256(b"1/m/2/5").digest()[:4], "big") & 0x7FFFFFFF
    assert run_seed("m", 2, 5) == expected == run_seed("m", 2, 5, base=1)
    seeds = {run_seed(m, w, r) for m in ("m", "n") for w in (1, 2) for r in range(1, 21)}
    assert len(seeds) == 80  # no two runs share a seed
    assert run_seed("m", 2, 5, base=2) != expected


def test_first_wave_is_the_design_generator_sheet():
    from demid.design_generation import FactorRange, generate_sheet

    spec = MaterialSpec.from_material("m", _checked({"m": _material(_command())})["materials"]["m"])
    wave = first_wave(spec, seed=4)
    sheet = generate_sheet("ccd", [FactorRange("a", 0.1, 0.9), FactorRange("b", 1.0, 11.0)], center_runs=3,
                           alpha="1.41421", seed=4).to_frame()
    assert wave.equals(sheet.drop(columns="std_order"))
    assert list(wave["run"]) == list(range(1, 12))
    assert not first_wave(spec, seed=5).equals(wave)


def test_assembled_table_keeps_failed_runs_as_failed_rows():
    records = [({"run": 2, "wave": 1, "factors": {"a": 0.5, "b": 2.0}}, {"status": OK, "responses": {"y": 3.5}}),
               ({"run": 1, "wave": 1, "factors": {"a": 0.1, "b": 1.0}}, {"status": FAILED, "responses": {}})]
    table = assemble_table(records, ["a", "b"], ["y"])
    assert list(table.columns) == ["run", "wave", "a", "b", "y", "status"]
    assert list(table["run"]) == [1, 2] and list(table["status"]) == ["failed", "ok"]
    assert pd.isna(table.loc[0, "y"]) and table.loc[1, "y"] == 3.5


@pytest.mark.parametrize("change, message", [
    (lambda m: m["simulation"].update(command="sim {a} {mu}"), "unknown placeholder '{mu}'"),
    (lambda m: m["simulation"].update(command="sim 'open"), "cannot split the command"),
    (lambda m: m.update(data="m.csv"), "both data and simulation"),
    (lambda m: m.pop("simulation"), "no data; give data"),
    (lambda m: m.update(design={"type": "custom"}), "design.type: the first wave"),
    (lambda m: m.update(design={"type": "ccd", "alpha": 1.41421, "center_runs": 0}), "cannot be generated"),
    (lambda m: m.update(waves={"max": 3}), "needs next_runs"),
    (lambda m: m.update(waves={"max": 2, "next_runs": {"count": 7}}, next_runs={"count": 7}), "move next_runs"),
    (lambda m: m.update(waves={"max": 2, "next_runs": {"count": 6}}), "count: 6 runs cannot determine a quadratic"),
    (lambda m: m["responses"].update(wave={}), "'wave' names the simulated table's wave column"),
])
def test_simulation_config_errors_name_the_key(change, message):
    mat = _material(_command())
    change(mat)
    with pytest.raises(InputError, match=re.escape(message)) as err:
        _checked({"m": mat})
    assert "materials.m" in str(err.value)


def test_schema_documents_and_defaults_the_simulation_block():
    config = validate_schema({"materials": {"m": _material("sim {a}")}})
    block = config["materials"]["m"]["simulation"]
    assert block["responses_file"] == "responses.json" and block["threads"] == 1 and block["mem_mb"] == 2000
    with pytest.raises(InputError, match="shell"):
        validate_schema({"materials": {"m": _material("sim {a}", simulation={"command": "x", "shell": True})}})


def test_wave_history_scales_each_wave_fraction_by_its_box_share_of_omega():
    from demid.waves import box_share, wave_history

    mat = _material(_command())
    mat["factors"]["b"].update(lower=1.0, upper=100.0, scale="log")
    spec = MaterialSpec.from_material("m", _checked({"m": mat})["materials"]["m"])
    box = pd.DataFrame({"factor": ["a", "b"], "lower": [0.5, 10.0], "upper": [0.9, 100.0]})
    assert box_share(spec, None) == 1.0
    assert box_share(spec, box) == pytest.approx(0.5 * 0.5)  # half of a's range, half of b's decades
    sets = pd.DataFrame({"scenario": "both", "feasible_fraction_pct": [8.0, 8.0], "factor": ["a", "b"],
                         "lower": [0.6, 20.0], "upper": [0.7, 30.0], "width": [0.1, 10.0]})
    history = wave_history(spec, [{"scenarios": sets, "domain": None, "simulated": 11, "analysed": 11},
                                  {"scenarios": sets, "domain": box, "simulated": 17, "analysed": 9}])
    assert list(history["wave"]) == [1, 1, 2, 2] and list(history["runs_simulated"]) == [11, 11, 17, 17]
    assert list(history["feasible_fraction_of_omega_pct"]) == pytest.approx([8.0, 8.0, 2.0, 2.0])
    assert list(history["box_lower"]) == [0.1, 1.0, 0.5, 10.0] and list(history["box_upper"]) == [0.9, 100.0] * 2


# ------------------------------------------------------------------------------------ the workflow
def _study(folder: Path, centre_run: int) -> Path:
    """Material m: two waves, one run of wave 1 exiting non-zero; material n: one wave, run 2 failing at
    its first attempt only (one retry)."""
    import yaml

    folder.mkdir(parents=True, exist_ok=True)
    config = {"grid_points": 41, "sweep_tolerances": [0.02, 0.05],
              "materials": {"m": _material(_command(f"--fail exit:{centre_run}"),
                                           waves={"max": 2, "stop_early": False, "next_runs": {"count": 7}}),
                            "n": _material(_command("--fail flaky:2"))}}
    config["materials"]["n"]["simulation"]["retries"] = 1
    config["materials"]["n"]["factors"]["a"]["label"] = "$(touch LABEL_INJECTED)"
    path = folder / "study.yaml"
    path.write_text(yaml.safe_dump(config, sort_keys=False), encoding="utf-8")
    return path


TARGETS = ("results/tables/identifiability.csv", "results/waves/history_m.csv", "results/figures/waves_n.png",
           "results/tables/advice.csv")


@pytest.mark.workflow
def test_waves_run_unattended_rerun_nothing_and_are_byte_identical(tmp_path):
    spec = MaterialSpec.from_material("m", _checked({"m": _material(_command())})["materials"]["m"])
    wave1 = first_wave(spec, seed=1)
    centre = int(wave1[(wave1["a"] == 0.5) & (wave1["b"] == 6.0)]["run"].iloc[0])
    study, twin = tmp_path / "study", tmp_path / "twin"
    config = _study(study, centre)
    first = run_snakemake(study, config, *TARGETS)
    assert first.returncode == 0, first.stderr[-3000:]
    results = study / "results"

    # Two waves (stop_early: false): wave 2 simulated wave 1's proposals, numbered on, and was analysed over
    # wave 1's box; wave 1's decision carries the estimate the stop advice reads, whatever it says.
    decision = json.loads((results / "waves/1/next_wave/m/decision.json").read_text(encoding="utf-8"))
    assert set(decision) == {"stop", "action", "reason", "value", "plausible_fraction_of_omega_pct"}
    assert decision["value"]["count"] == 7 and decision["action"] in ("stop", "next_runs", "recalibrate")
    proposals = pd.read_csv(results / "waves/1/next_wave/m/next_runs.csv")
    domain = pd.read_csv(results / "waves/1/next_wave/m/next_domain.csv")
    table = pd.read_csv(results / "waves/2/data/m.csv")
    assert list(table.columns) == ["run", "wave", "a", "b", "y1", "y2", "status"]
    assert list(table["wave"]) == [1] * 11 + [2] * 7 and list(table["run"]) == list(range(1, 19))
    assert table[table["wave"] == 2][["a", "b"]].to_numpy() == pytest.approx(proposals[["a", "b"]].to_numpy())
    analysed = pd.read_csv(results / "waves/2/data/m_analysed.csv")
    bounds = domain.set_index("factor")
    inside = table[table["a"].between(*bounds.loc["a", ["lower", "upper"]])
                   & table["b"].between(*bounds.loc["b", ["lower", "upper"]])]
    assert list(analysed["run"]) == list(inside["run"])
    # The material's results are its last wave's; every run's folder has its parameters, record and log.
    assert (results / "validated/m.parquet").read_bytes() == (results / "waves/2/validated/m.parquet").read_bytes()
    assert (results / "validated/n.parquet").read_bytes() == (results / "waves/1/validated/n.parquet").read_bytes()
    assert not (results / "waves/2/data/n.csv").exists()
    params = json.loads((results / "runs/m/wave2/run15/params.json").read_text(encoding="utf-8"))
    assert params["seed"] == run_seed("m", 2, 15) and params["factors"]["a"] == proposals["a"].iloc[3]

    # The sets wave by wave: Phi of wave 2's box scaled to Omega by the box's share of it.
    history = pd.read_csv(results / "waves/history_m.csv")
    assert list(history.drop_duplicates("wave")["runs_simulated"]) == [11, 18]
    assert list(history.drop_duplicates("wave")["runs_analysed"]) == [11, len(analysed)]
    share = ((bounds.loc["a", "upper"] - bounds.loc["a", "lower"]) / 0.8
             * (bounds.loc["b", "upper"] - bounds.loc["b", "lower"]) / 10.0)
    wave2 = history[history["wave"] == 2].iloc[0]
    assert wave2["feasible_fraction_of_omega_pct"] == pytest.approx(wave2["feasible_fraction_pct"] * share, rel=1e-4)
    assert (results / "figures/waves_m.png").is_file() and (results / "figures/waves_n.svg").is_file()

    # Told: per wave the runs simulated, failed and analysed; the last wave's decision is the material's
    # stop/next_runs/recalibrate advice, word for word; n (one wave, no next runs) has its wave and no decision.
    summary = json.loads((results / "waves/summary_m.json").read_text(encoding="utf-8"))
    assert [(w["simulated"], w["failed"], w["analysed"]) for w in summary["waves"]] == [(11, 1, 11),
                                                                                      (18, 1, len(analysed))]
    last = json.loads((results / "waves/2/next_wave/m/decision.json").read_text(encoding="utf-8"))
    assert summary["decision"] == last and last["stop"] is True  # waves.max: 2 is spent
    advice = pd.read_csv(results / "tables/advice.csv")
    told = advice[(advice["material"] == "m") & advice["kind"].isin(["stop", "next_runs", "recalibrate"])]
    assert list(told["kind"]) == [last["action"]] and last["reason"] in told["text"].iloc[0]
    assert not len(advice[(advice["material"] == "n") & advice["kind"].isin(["stop", "next_runs", "recalibrate"])])
    n_summary = json.loads((results / "waves/summary_n.json").read_text(encoding="utf-8"))
    assert n_summary["decision"] is None and [w["simulated"] for w in n_summary["waves"]] == [11]

    # The run that exited non-zero is a failed row with its log kept; the analysis went on.
    record = json.loads((results / f"runs/m/wave1/run{centre}/run.json").read_text(encoding="utf-8"))
    assert record == {"reason": "the command exited with status 3", "responses": {}, "status": "failed"}
    assert "simulated divergence" in (results / f"runs/m/wave1/run{centre}/log").read_text(encoding="utf-8")
    row = table[table["run"] == centre].iloc[0]
    assert row["status"] == "failed" and pd.isna(row["y1"]) and pd.isna(row["y2"])
    validated = read_parquet(results / "waves/1/validated/m.parquet")
    assert validated.loc[validated["run"] == centre, "status"].iloc[0] == "failed"
    # A run failing once is tried again (retries: 1); the failed attempt's log is kept beside the log.
    assert json.loads((results / "runs/n/wave1/run2/run.json").read_text(encoding="utf-8"))["status"] == "ok"
    earlier = (results / "runs/n/wave1/run2/log.attempt1").read_text(encoding="utf-8")
    assert "status: failed (the command exited with status 4)" in earlier and "attempt 1 of 2: trying again" in earlier
    assert (results / "runs/n/wave1/run2/log").read_text(encoding="utf-8").rstrip().endswith("status: ok")
    ident = pd.read_csv(results / "tables/identifiability.csv")
    assert set(ident["material"]) == {"m", "n"}
    assert not list(study.rglob("*INJECTED*"))  # a label is never part of a command

    # A second invocation has nothing to do.
    noop = run_snakemake(study, config, *TARGETS, "-n")
    assert noop.returncode == 0 and planned_jobs(noop.stdout) == {}, noop.stdout

    # A clean run elsewhere gives byte-identical tables, parquet, JSON and figures.
    shutil.copytree(study, twin, ignore=shutil.ignore_patterns("results", ".snakemake", "logs", "benchmarks"))
    second = run_snakemake(twin, twin / "study.yaml", *TARGETS)
    assert second.returncode == 0, second.stderr[-3000:]
    assert tree_hashes(results) == tree_hashes(twin / "results")

    # An edited bound of n reruns the runs of n it moves (not the axial run on b's lower bound) and
    # n's chain, nothing of m.
    moved = _material(_command())
    moved["factors"]["b"]["upper"] = 12.0
    moved = first_wave(MaterialSpec.from_material("n", _checked({"n": moved})["materials"]["n"]), seed=1)
    before = first_wave(MaterialSpec.from_material("n", _checked({"n": _material(_command())})["materials"]["n"]),
                        seed=1)
    changed = int((moved[["a", "b"]] != before[["a", "b"]]).any(axis=1).sum())
    assert changed == 10
    text = config.read_text(encoding="utf-8")
    n_block = text.index("  n:\n")
    config.write_text(text[:n_block] + text[n_block:].replace("upper: 11.0", "upper: 12.0", 1), encoding="utf-8")
    edit = run_snakemake(study, config, *TARGETS, "-n")
    jobs = planned_jobs(edit.stdout)
    assert jobs.get("simulate_run") == changed and jobs.get("analyse_wave") == 1, edit.stdout
    assert re.search(r"material=n\b", edit.stdout) and not re.search(r"material=m\b", edit.stdout), edit.stdout


def _evidence(**changes):
    from demid.waves import WaveEvidence

    base = dict(wave=2, max_waves=4, plausible_pct=1.55, previous_pct=1.40,
                surrogates={"y1": {"q2": 0.97, "lof_p": 0.40}, "y2": {"q2": 0.93, "lof_p": 0.60}},
                model_limit=False, proposed=9, criticism_runs=0)
    return WaveEvidence(**{**base, **changes})


def test_waves_stop_on_the_measured_change_the_budget_or_the_model_never_on_a_misfitting_surrogate():
    """The loop stops when the plausible share of Omega measured wave to wave stops moving (whatever the
    prediction), when waves.max is spent or when the model itself is the limit; it never stops while a
    surrogate misfits or does not predict, and says what the next wave does about it."""
    from demid.wave_value import STOP_CONTRACTION
    from demid.waves import STOP_Q2, stop_decision

    big = {"scenario": "both", "count": 9, "plausible_fraction_pct": 9.3, "expected_fraction_pct": 6.0,
           "expected_contraction": 0.35, "stop": False}
    small = {**big, "expected_fraction_pct": 9.1, "expected_contraction": STOP_CONTRACTION / 5, "stop": True}
    # 1.40 -> 1.55 %: +10.7 % measured, the set still moves although the prediction says it buys little
    moving = stop_decision(small, _evidence())
    assert moving["stop"] is False and moving["action"] == "next_runs"
    assert "1.4 % → 1.55 % from wave 1 to wave 2 (+10.7 %)" in moving["reason"]
    # 1.55 -> 1.44 %: -7.1 %, within noise: stop though each wave predicted a 35 % shrink
    flat = stop_decision(big, _evidence(wave=3, plausible_pct=1.44, previous_pct=1.55))
    assert flat["stop"] is True and flat["action"] == "stop" and "(-7.1 %): within the 10 % change" in flat["reason"]
    # wave 1 has no measured change: the prediction decides
    assert stop_decision(small, _evidence(wave=1, previous_pct=None))["stop"] is True
    first = stop_decision(big, _evidence(wave=1, previous_pct=None))
    assert first["stop"] is False and "nothing to compare with" in first["reason"]
    # a misfitting surrogate (lack of fit p = 0.019) or one below the stated Q² never stops the loop
    for bad in ({"q2": 0.97, "lof_p": 0.019}, {"q2": STOP_Q2 - 0.1, "lof_p": 0.5}, {"q2": float("nan"), "lof_p": 0.5}):
        going = stop_decision(small, _evidence(wave=1, previous_pct=None, surrogates={"y1": bad},
                                               criticism_runs=4))
        assert going["stop"] is False and going["action"] == "next_runs", bad
        assert "the surrogate of y1" in going["reason"] and "4 of them replicates or runs the criticism asks for" \
            in going["reason"]
    assert "lack of fit p = 0.019" in stop_decision(small, _evidence(surrogates={"y1": {"q2": 0.9, "lof_p": 0.019}}))[
        "reason"]
    # ... unless the budget is spent: then the advice is to recalibrate, not to take the set as the answer
    spent = stop_decision(small, _evidence(wave=4, surrogates={"y1": {"q2": 0.2, "lof_p": 0.5}}))
    assert spent["stop"] is True and spent["action"] == "recalibrate" and "budget of 4 wave(s)" in spent["reason"]
    # the model, not the surrogate, is the limit: stop
    model = stop_decision(big, _evidence(model_limit=True))
    assert model["stop"] is True and "the model, not the surrogate, is the limit" in model["reason"]
    # the budget spent on a set still moving: the loop ends, the advice is another wave
    last = stop_decision(big, _evidence(wave=4))
    assert last["stop"] is True and last["action"] == "next_runs" and "budget of 4 wave(s) is spent" in last["reason"]

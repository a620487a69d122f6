"""demid runs the simulations: commands without a shell, failed runs as failed rows, seeds, and the
waves driven by Snakemake (one job per run, cached, reruns only what an edit changes)."""

from __future__ import annotations

import hashlib
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from demid.config import check_semantics, validate_schema
from demid.errors import InputError
from demid.io import read_parquet
from demid.simulation import (FAILED, OK, RunStopped, _read_responses, assemble_table, execute, fill_command,
                              params_digest, read_run, run_seed)
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


def _wait_dead(pid: int, within_s: float = 10) -> bool:
    deadline = time.monotonic() + within_s
    while _alive(pid) and time.monotonic() < deadline:
        time.sleep(0.05)
    return not _alive(pid)


def test_a_timeout_ends_a_daemon_the_command_started_in_a_session_of_its_own(tmp_path):
    record, _ = _execute(_parameters(1, _command("--fail daemon:1")), tmp_path / "run", ["y1", "y2"])
    assert record["status"] == FAILED and "timed out" in record["reason"]
    daemon = int((tmp_path / "run/daemon.pid").read_text(encoding="utf-8"))
    assert _wait_dead(daemon)


def test_a_signal_stops_the_run_with_all_it_started_and_leaves_no_record(tmp_path):
    """SIGTERM to the run's job (as a Ctrl-C or a cluster's cancel sends): the command and its daemon end,
    and execute raises instead of returning a record, so the run stays to be done."""
    run_dir = tmp_path / "run"
    run_dir.mkdir()
    received = []
    previous = signal.signal(signal.SIGTERM, lambda number, frame: received.append(number))  # pytest lives on
    timer = threading.Timer(1.5, os.kill, (os.getpid(), signal.SIGTERM))
    timer.start()
    try:
        with open(run_dir / "log", "w", encoding="utf-8") as log, pytest.raises(RunStopped, match="SIGTERM received"):
            execute(_parameters(1, _command("--fail daemon:1")), run_dir, ["y1", "y2"], log, timeout_s=8)
    finally:
        timer.join()
        signal.signal(signal.SIGTERM, previous)
    assert _wait_dead(int((run_dir / "daemon.pid").read_text(encoding="utf-8")), within_s=1)
    assert "stopped: SIGTERM received" in (run_dir / "log").read_text(encoding="utf-8")
    assert not (run_dir / "responses.json").exists()


@pytest.mark.parametrize("mode, reason", [
    ("bigint", "'y1' is an integer of 401 digits, too large for a float"),
    ("huge", "'y1' is 1e+300, outside the magnitudes demid computes with (0, or 1e-30 to 1e+30)"),
])
def test_any_number_a_simulator_writes_fails_that_run_with_one_reason(tmp_path, mode, reason):
    record, log = _execute(_parameters(1, _command(f"--fail {mode}:1")), tmp_path, ["y1", "y2"])
    assert record["status"] == FAILED and reason in record["reason"], record
    assert f"status: failed ({record['reason']})" in log


@pytest.mark.parametrize("content, reason", [
    (b"[" * 100_000, "not valid JSON"),
    (b'{"y1": ' + b"7" * 5000 + b"}", "not valid JSON"),
    (b'{"y1": 1e-320}', "outside the magnitudes"),
    (b'{"y1": "\xff"}', "not valid JSON"),
    (b'{"y1": 1.0' + b" " * 2_000_000 + b"}", "larger than 1000000 bytes"),
    (b'{"y1": {"deep": [1]}}', "'y1' is {'deep': [1]}"),
])
def test_any_bytes_in_the_responses_file_give_a_reason_never_an_exception(tmp_path, content, reason):
    path = tmp_path / "responses.json"
    path.write_bytes(content)
    values, found = _read_responses(path, ["y1"])
    assert values == {} and reason in found, found


def test_a_command_writing_params_json_fails_its_run_and_demids_file_is_restored(tmp_path):
    parameters = _parameters(1, _command("--fail params:1"))
    record, _ = _execute(parameters, tmp_path, ["y1", "y2"])
    assert record["status"] == FAILED and "the command wrote params.json" in record["reason"]
    assert json.loads((tmp_path / "params.json").read_text(encoding="utf-8")) == parameters
    assert record["params_sha256"] == params_digest(parameters)


def test_a_record_not_written_by_its_runs_job_is_refused_and_removed(tmp_path):
    own, other = tmp_path / "run1", tmp_path / "run2"
    _execute(_parameters(1, _command()), own, ["y1", "y2"])
    record, _ = _execute(_parameters(2, _command("--fail intrude:2")), other, ["y1", "y2"])
    assert record["status"] == OK  # the intruder's own run is fine; the run it wrote into is not
    with pytest.raises(InputError, match=re.escape(f"{own}: run.json does not match the params.json beside it")):
        read_run(own / "params.json", own / "run.json")
    assert not (own / "run.json").exists()
    (other / "run.json").write_text(json.dumps(record), encoding="utf-8")
    params, kept = read_run(other / "params.json", other / "run.json")
    assert params["run"] == 2 and kept == record


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
    (lambda m: m.update(waves={"max": 1000, "next_runs": {"count": 7}}), "waves.max: 1000 is greater than the "
                                                                         "maximum of 20"),
    (lambda m: m["simulation"].update(responses_file="params.json"), "simulation.responses_file: 'params.json' is "
                                                                      "demid's own file"),
    (lambda m: m["simulation"].update(responses_file="run.json"), "'run.json' is demid's own file"),
    (lambda m: m["simulation"].update(responses_file="log.attempt1"), "'log.attempt1' is demid's own file"),
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


def test_wave_history_gives_each_wave_fraction_of_omega_and_the_box_its_runs_were_placed_in():
    """Every wave is analysed over Omega, so its fraction is the history's as it is; the box is only where the
    wave's runs were placed, with its share of Omega."""
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
    assert list(history["feasible_fraction_of_omega_pct"]) == pytest.approx([8.0, 8.0, 8.0, 8.0])
    assert "feasible_fraction_pct" not in history  # a fraction of which base: the column names say it
    assert list(history["box_lower"]) == [0.1, 1.0, 0.5, 10.0] and list(history["box_upper"]) == [0.9, 100.0] * 2
    assert list(history["box_share_of_omega_pct"]) == pytest.approx([100.0, 100.0, 25.0, 25.0])
    assert history["plausible_fraction_of_omega_pct"].isna().all()  # no plausible frames given: nothing made up


def test_wave_history_carries_the_plausible_share_and_intervals_the_waves_table_prints():
    """The figure plots the plausible share of Omega the report's Waves table prints (wave_summary), per scenario
    and factor from each wave's plausible frame, beside the strict numbers; both scenarios of a wave kept apart."""
    from demid.plots.waves import waves_figure
    from demid.waves import wave_history, wave_summary

    spec = MaterialSpec.from_material("m", _checked({"m": _material(_command())})["materials"]["m"])
    sets = pd.DataFrame({"scenario": ["both", "both", "one", "one"], "feasible_fraction_pct": [8.0, 8.0, 20.0, 20.0],
                         "factor": ["a", "b"] * 2, "lower": [0.6, 2.0, 0.3, 1.5], "upper": [0.7, 3.0, 0.8, 3.5],
                         "width": [0.1, 1.0, 0.5, 2.0]})
    waves, frames = [], []
    for k, (pct_both, pct_one) in enumerate(((11.5, 31.0), (9.25, 27.0)), start=1):
        plausible = pd.DataFrame({"scenario": ["both", "both", "one", "one"], "factor": ["a", "b"] * 2,
                                  "robust_fraction_pct": [pct_both, pct_both, pct_one, pct_one],
                                  "robust_lower": [0.55 + k / 100, 1.8, 0.25, 1.2],
                                  "robust_upper": [0.75, 3.2 - k / 10, 0.85, 3.8]})
        waves.append({"scenarios": sets, "domain": None, "simulated": 11 * k, "analysed": 11 * k,
                      "plausible": plausible})
        table = pd.DataFrame({"run": range(1, 11 * k + 1), "status": "ok"})
        frames.append({"table": table, "analysed": table, "domain": None, "plausible": plausible,
                       "statistics": pd.DataFrame({"response": ["y1"], "q2": [0.9]})})
    history = wave_history(spec, waves)
    summary = wave_summary(spec, frames, None)
    for k, wave in enumerate(summary["waves"], start=1):
        rows = history[(history["wave"] == k) & (history["scenario"] == wave["scenario"])].set_index("factor")
        assert rows["plausible_fraction_of_omega_pct"].tolist() == [wave["plausible_fraction_of_omega_pct"]] * 2
        for f, (lo, hi) in wave["plausible"].items():
            assert (rows.at[f, "plausible_lower"], rows.at[f, "plausible_upper"]) == (lo, hi)
    one = history[(history["scenario"] == "one") & (history["factor"] == "b")]
    assert one["plausible_fraction_of_omega_pct"].tolist() == [31.0, 27.0]
    assert one["plausible_upper"].tolist() == pytest.approx([3.8, 3.8])
    runs = pd.DataFrame({"wave": [1] * 11 + [2] * 11, "a": np.linspace(0.1, 0.9, 22), "b": 2.0,
                         "status": ["ok"] * 21 + ["failed"]})
    fig = waves_figure(history, spec, runs=runs)
    solid = [line for line in fig.axes[0].get_lines() if line.get_linestyle() == "-"]
    assert sorted(tuple(line.get_ydata()) for line in solid) == [(11.5, 9.25), (31.0, 27.0)]
    assert fig.axes[0].get_ylim()[0] == 0
    from matplotlib.collections import PathCollection

    dots = [c for c in fig.axes[1].collections if isinstance(c, PathCollection)]
    assert sorted(len(c.get_offsets()) for c in dots) == [1, 21]  # every run drawn, the failed one apart
    import matplotlib.pyplot as plt

    plt.close(fig)


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

    # Two waves (stop_early: false): wave 2 simulated wave 1's proposals (placed over Omega), numbered on, and
    # was analysed with every run over Omega; wave 1's decision carries the estimate the stop advice reads.
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
    assert list(analysed["run"]) == list(table["run"])
    # The material's results are its last wave's; every run's folder has its parameters, record and log.
    assert (results / "validated/m.parquet").read_bytes() == (results / "waves/2/validated/m.parquet").read_bytes()
    assert (results / "validated/n.parquet").read_bytes() == (results / "waves/1/validated/n.parquet").read_bytes()
    assert not (results / "waves/2/data/n.csv").exists()
    params = json.loads((results / "runs/m/wave2/run15/params.json").read_text(encoding="utf-8"))
    assert params["seed"] == run_seed("m", 2, 15) and params["factors"]["a"] == proposals["a"].iloc[3]

    # The sets wave by wave: Phi of Omega as each wave's scenarios give it, and the box wave 2's runs were placed in.
    history = pd.read_csv(results / "waves/history_m.csv")
    assert list(history.drop_duplicates("wave")["runs_simulated"]) == [11, 18]
    assert list(history.drop_duplicates("wave")["runs_analysed"]) == [11, 18]
    share = ((bounds.loc["a", "upper"] - bounds.loc["a", "lower"]) / 0.8
             * (bounds.loc["b", "upper"] - bounds.loc["b", "lower"]) / 10.0)
    wave2 = history[history["wave"] == 2].iloc[0]
    scenarios2 = read_parquet(results / "waves/2/scenarios/m.parquet")
    assert wave2["feasible_fraction_of_omega_pct"] == pytest.approx(scenarios2["feasible_fraction_pct"].iloc[0],
                                                                    rel=1e-5)  # the CSV's 6 digits
    assert wave2["box_share_of_omega_pct"] == pytest.approx(100 * share, rel=1e-4)
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
    params = json.loads((results / f"runs/m/wave1/run{centre}/params.json").read_text(encoding="utf-8"))
    assert record == {"reason": "the command exited with status 3", "responses": {}, "status": "failed",
                      "params_sha256": params_digest(params)}
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


def _processes_under(folder: Path) -> list[int]:
    """Live processes whose command line names ``folder`` (the run scripts, the simulators)."""
    found = []
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit() and int(entry.name) != os.getpid():
            try:
                if str(folder).encode() in (entry / "cmdline").read_bytes() and _alive(int(entry.name)):
                    found.append(int(entry.name))
            except OSError:
                continue
    return found


def _simulators_under(folder: Path) -> list[int]:
    return [pid for pid in _processes_under(folder)
            if b"simulator.py" in Path(f"/proc/{pid}/cmdline").read_bytes()]


@pytest.mark.workflow
def test_ctrl_c_stops_the_running_simulations_and_leaves_their_runs_to_do(tmp_path):
    """Ctrl-C in a terminal sends SIGINT to Snakemake's process group: with two simulations running,
    nothing of the study is left running afterwards and the next invocation plans every run again."""
    import yaml

    study = tmp_path / "study"
    study.mkdir()
    hang_all = " ".join(f"--fail hang:{run}" for run in range(1, 12))
    mat = _material(_command(hang_all))
    mat["simulation"]["runtime_min"] = 5
    config = study / "study.yaml"
    config.write_text(yaml.safe_dump({"materials": {"m": mat}}, sort_keys=False), encoding="utf-8")
    target = "results/waves/1/data/m.csv"
    cmd = [sys.executable, "-m", "snakemake", "-c2", "--configfile", str(config), "--directory", str(study), target]

    def as_in_a_terminal():  # its own process group, taking SIGINT as a foreground job does
        os.setsid()
        signal.signal(signal.SIGINT, signal.SIG_DFL)

    with open(tmp_path / "snakemake.out", "w", encoding="utf-8") as out:
        workflow = subprocess.Popen(cmd, cwd=Path(__file__).resolve().parents[2], stdout=out,
                                    stderr=subprocess.STDOUT, preexec_fn=as_in_a_terminal,
                                    env=dict(os.environ, PYTHONWARNINGS="ignore"))
    try:
        deadline = time.monotonic() + 120
        while len(_simulators_under(study)) < 2 and time.monotonic() < deadline and workflow.poll() is None:
            time.sleep(0.2)
        assert len(_simulators_under(study)) == 2, (tmp_path / "snakemake.out").read_text(encoding="utf-8")
        os.killpg(workflow.pid, signal.SIGINT)
        workflow.wait(timeout=60)
        deadline = time.monotonic() + 15
        while _processes_under(study) and time.monotonic() < deadline:
            time.sleep(0.2)
        left = _processes_under(study)
    finally:
        if workflow.poll() is None:
            workflow.kill()
            workflow.wait()
        for pid in _processes_under(study):  # what this test started and the change failed to stop
            os.kill(pid, signal.SIGKILL)
    assert left == [], [Path(f"/proc/{pid}/cmdline").read_bytes() for pid in left if _alive(pid)]
    assert not list((study / "results").rglob("run.json"))
    again = run_snakemake(study, config, target, "-n")
    assert again.returncode == 0 and planned_jobs(again.stdout).get("simulate_run") == 11, again.stdout + again.stderr


def test_a_wave_after_a_box_is_judged_on_omega_with_every_run_so_the_box_cuts_nothing(tmp_path):
    """Wave 2 of a planted study: wave 1's CCD over Omega = [0, 1]^2 of an exact quadratic y = |x - c|^2 with
    target R0^2 (its admissible set is an annulus round c of area 2 pi R0^2 eps, closed form), then 9 runs in a box
    that holds only the annulus' upper right part.  The wave's analysis is over Omega with every run: Phi is the
    annulus' share of Omega (not of the box, 14 x larger), the spans run past the box's lower bounds to the
    annulus' ends, and no verdict says "cut by the search range" where only the box ended."""
    from demid.steps import material_step
    from demid.story.verdicts import factor_verdict
    from demid.waves import wave_spec

    centre, r0, eps = np.array([0.3, 0.6]), 0.15, 0.05
    mat = {"design": {"type": "ccd", "alpha": 1.41421, "center_runs": 5},
           "simulation": {"command": _command(), "seed": 1},
           "waves": {"max": 2, "next_runs": {"count": 9}},
           "factors": {"a": {"lower": 0.0, "upper": 1.0}, "b": {"lower": 0.0, "upper": 1.0}},
           "responses": {"y": {"target": r0 ** 2}},
           "scenarios": {"y": {"observables": ["y"], "tolerance": eps}}}
    config = _checked({"m": mat})
    spec = MaterialSpec.from_material("m", config["materials"]["m"], grid_points=config["grid_points"])
    box = pd.DataFrame({"factor": ["a", "b"], "lower": [0.3, 0.6], "upper": [0.6, 0.9]})
    wave1 = first_wave(spec, seed=1)
    levels = np.linspace(0.0, 1.0, 3)
    wave2 = pd.DataFrame({"a": 0.3 + 0.3 * np.repeat(levels, 3), "b": 0.6 + 0.3 * np.tile(levels, 3)})
    table = pd.concat([wave1.assign(wave=1), wave2.assign(run=np.arange(14, 23), wave=2)], ignore_index=True)
    table["y"] = ((table[["a", "b"]].to_numpy() - centre) ** 2).sum(axis=1)
    table["status"] = "ok"
    path = tmp_path / "m.csv"
    table[["run", "wave", "a", "b", "y", "status"]].to_csv(path, index=False)

    wave = wave_spec(spec, str(path), box)
    result = material_step(wave, path, z=2.0, tolerances=[0.02, 0.05], typo_stop=False)
    sets = result.parquet["scenarios"].set_index("factor")
    annulus_pct = 100 * 2 * np.pi * r0 ** 2 * eps  # 0.71 % of Omega; 7.9 % of the box's 0.09
    assert sets["feasible_fraction_pct"].iloc[0] == pytest.approx(annulus_pct, rel=0.05)
    outer = r0 * np.sqrt(1 + eps)
    for factor, c, box_lower in (("a", 0.3, 0.3), ("b", 0.6, 0.6)):
        assert sets.at[factor, "lower"] == pytest.approx(c - outer, abs=0.01) and sets.at[factor, "lower"] < box_lower
        assert sets.at[factor, "upper"] == pytest.approx(c + outer, abs=0.01)
        verdict, width = factor_verdict(sets.at[factor, "lower"], sets.at[factor, "upper"], 0.0, 1.0,
                                        at_bound=sets.at[factor, "at_bound"])
        assert verdict == "bounded" and width == pytest.approx(2 * outer, abs=0.02)  # of Omega's range
    plausible = result.parquet["plausible"].set_index("factor")
    assert plausible["robust_fraction_pct"].iloc[0] == pytest.approx(annulus_pct, rel=0.1)


def _evidence(**changes):
    from demid.waves import WaveEvidence

    base = dict(wave=2, max_waves=4, plausible_pct=1.55, previous_pct=1.40,
                surrogates={"y1": {"q2": 0.97, "lof_p": 0.40, "loo_band": 0.1},
                            "y2": {"q2": 0.93, "lof_p": 0.60, "loo_band": 0.2}},
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
    # wave 1 has no measured change: the prediction decides where the band fixes the boundary (each surrogate's
    # leave-one-out error small against the tolerance band), not where the surrogate's error is a good part of it
    fixed = {"y1": {"q2": 0.97, "lof_p": 0.40, "loo_band": 0.1}, "y2": {"q2": 0.93, "lof_p": 0.60, "loo_band": 0.2}}
    assert stop_decision(small, _evidence(wave=1, previous_pct=None, surrogates=fixed))["stop"] is True
    loose = {**fixed, "y2": {**fixed["y2"], "loo_band": 0.6}}
    assert stop_decision(small, _evidence(wave=1, previous_pct=None, surrogates=loose))["stop"] is False
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
    assert spent["stop"] is True and spent["action"] == "recalibrate" and "budget of 4 waves" in spent["reason"]
    # the model, not the surrogate, is the limit: stop
    model = stop_decision(big, _evidence(model_limit=True))
    assert model["stop"] is True and "the model, not the surrogate, is the limit" in model["reason"]
    # the budget spent on a set still moving: the loop ends, the advice is another wave
    last = stop_decision(big, _evidence(wave=4))
    assert last["stop"] is True and last["action"] == "next_runs" and "budget of 4 waves is spent" in last["reason"]

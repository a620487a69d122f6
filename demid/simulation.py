"""Running a material's simulations: one run = one command, its responses read back from JSON.

A material with ``simulation:`` has no finished table: demid runs the command once per run of a
wave.  The command is split like a shell line (:func:`shlex.split`) and executed *without* a shell;
placeholders are filled word by word with numbers and the run's folder, so neither the config's
values nor anything the pipeline writes can become shell syntax.  A run that exits non-zero, times
out, or leaves no valid responses is recorded as ``failed`` (with the reason); the analysis keeps
the row, as for a transcribed table with a failed run.  A run stopped by a signal (Ctrl-C) or by the
end of the workflow that started it ends its command's processes and leaves no record, so that the
next invocation runs it again.  ``params.json``, ``run.json`` and ``log`` in the run's folder are
demid's: ``run.json`` carries the digest of the ``params.json`` written beside it.
"""

from __future__ import annotations

import hashlib
import json
import math
import numbers
import os
import re
import shlex
import signal
import subprocess
import tempfile
import threading
import time
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from .errors import InputError

if TYPE_CHECKING:
    import pandas as pd

# A run's job imports nothing but the standard library from here (numpy and pandas load inside the
# functions that need them): its start-up is paid once per simulation.

#: ``{name}`` in a command word; ``{{`` and ``}}`` are literal braces.
_PLACEHOLDER = re.compile(r"\{\{|\}\}|\{([^{}]*)\}")
#: The placeholders every run has besides its factors.
RUN_PLACEHOLDERS = ("run", "wave", "seed", "run_dir")
#: Run outcomes in the record (``run.json``) and the table's ``status`` column.
OK, FAILED = "ok", "failed"


@dataclass(frozen=True)
class Simulation:
    """A material's ``simulation:`` block (schema defaults filled)."""

    command: str
    responses_file: str
    threads: int
    mem_mb: int
    runtime_min: float
    retries: int
    seed: int

    @classmethod
    def from_material(cls, material: dict) -> "Simulation":
        """The block of a schema-validated ``materials`` entry (its defaults filled in)."""
        block = material["simulation"]
        return cls(command=block["command"], responses_file=block["responses_file"], threads=int(block["threads"]),
                   mem_mb=int(block["mem_mb"]), runtime_min=float(block["runtime_min"]),
                   retries=int(block["retries"]), seed=int(block["seed"]))

    @property
    def timeout_s(self) -> float:
        return 60.0 * self.runtime_min

    @property
    def runtime_resource(self) -> int:
        """Minutes the job asks of a scheduler: the command's limit rounded up, and a minute for demid."""
        return math.ceil(self.runtime_min) + 1


def command_words(command: str, key: str = "simulation.command") -> list[str]:
    """The command split like a shell line; an unbalanced quote is a config error naming the key."""
    try:
        words = shlex.split(command)
    except ValueError as exc:
        raise InputError(f"config key {key}: cannot split the command into words ({exc})") from None
    if not words:
        raise InputError(f"config key {key}: the command is empty")
    return words


def placeholders(word: str) -> list[str]:
    return [m.group(1) for m in _PLACEHOLDER.finditer(word) if m.group(1) is not None]


def check_command(command: str, factors, key: str) -> None:
    """Every placeholder of the command is a factor or a run placeholder; raises InputError naming the key."""
    known = list(factors) + list(RUN_PLACEHOLDERS)
    for word in command_words(command, key):
        for name in placeholders(word):
            if name not in known:
                raise InputError(f"config key {key}: unknown placeholder '{{{name}}}' (known: "
                                 + ", ".join(f"{{{k}}}" for k in known) + "; write {{ and }} for literal braces)")
        rest = _PLACEHOLDER.sub("", word)
        if "{" in rest or "}" in rest:
            raise InputError(f"config key {key}: unbalanced brace in '{word}' (write {{{{ and }}}} for literal braces)")


def format_value(value) -> str:
    """A placeholder's text: integers as integers, floats in their shortest exact form."""
    if isinstance(value, numbers.Integral) and not isinstance(value, bool):
        return str(int(value))
    if isinstance(value, numbers.Real):
        return repr(float(value))
    return str(value)


def fill_command(command: str, values: dict) -> list[str]:
    """The argument list of one run: the command's words with their placeholders replaced.

    Substitution happens after splitting, inside each word, so a value never adds a word, a quote,
    a pipe or a ``$(...)``: with no shell, such characters would reach the program as plain text anyway.
    """
    text = {name: format_value(v) for name, v in values.items()}

    def replace(match):
        if match.group(1) is None:
            return match.group(0)[0]
        return text[match.group(1)]

    return [_PLACEHOLDER.sub(replace, word) for word in command_words(command)]


def run_seed(material: str, wave: int, run: int, base: int = 1) -> int:
    """A seed fixed by the material, wave, run and the configured base seed (below 2^31, for any simulator)."""
    digest = hashlib.sha256(f"{base}/{material}/{int(wave)}/{int(run)}".encode("utf-8")).digest()
    return int.from_bytes(digest[:4], "big") & 0x7FFFFFFF


def run_parameters(material: str, wave: int, run: int, factor_values: dict, simulation: Simulation) -> dict:
    """What one run is: the values written to params.json and passed to the job (Snakemake reruns a run
    whose parameters changed; the time limit, threads and retries are not among them, so raising a
    limit does not rerun finished runs)."""
    return {"material": material, "wave": int(wave), "run": int(run),
            "seed": run_seed(material, wave, run, simulation.seed),
            "factors": {name: float(v) for name, v in factor_values.items()},
            "command": simulation.command, "responses_file": simulation.responses_file}


#: Largest responses file read: a JSON object of a few numbers is far smaller.
MAX_RESPONSES_BYTES = 1_000_000
#: Seconds a stopped or timed-out command has to end after SIGTERM before it is killed.
STOP_GRACE_S = 5.0
#: Seconds between looks at the command, the time limit, a stop signal and the workflow.
_POLL_S = 0.2
#: Environment variable marking every process a run's command starts (found even in a new session).
RUN_MARKER = "DEMID_RUN_MARKER"
#: The files demid writes into a run's folder (the command's responses file cannot be one of them).
OWN_FILES = ("params.json", "run.json", "log")


def reserved_file(name: str) -> bool:
    """Whether ``name`` is one of demid's own files in a run's folder (its log's attempts and the
    temporary files of its atomic writes included)."""
    return name in OWN_FILES or name.startswith(("log.", ".params.json.", ".run.json."))


class RunStopped(Exception):
    """The run was stopped before its command ended (a signal, or the workflow gone): no record."""


def _read_responses(path: Path, responses) -> tuple[dict, str]:
    """(responses, reason): the values of every response, or an empty dict and why not.  Whatever the
    file holds, the answer is one of these two: never an exception."""
    from .numbers import LARGEST, SMALLEST

    if not path.is_file():
        return {}, f"the command wrote no {path.name}"
    try:
        with open(path, "rb") as source:
            data = source.read(MAX_RESPONSES_BYTES + 1)
    except OSError as exc:
        return {}, f"{path.name} cannot be read ({exc.strerror or exc})"
    if len(data) > MAX_RESPONSES_BYTES:
        return {}, f"{path.name} is larger than {MAX_RESPONSES_BYTES} bytes (a JSON object of the responses)"
    try:
        document = json.loads(data.decode("utf-8"))
    except (UnicodeDecodeError, ValueError, RecursionError) as exc:
        return {}, f"{path.name} is not valid JSON ({str(exc)[:200]})"
    if not isinstance(document, dict):
        return {}, f"{path.name} holds no JSON object {{response: value}}"
    values = {}
    for name in responses:
        value = document.get(name)
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            shown = "missing" if name not in document else repr(value)[:80]
            return {}, f"{path.name}: response '{name}' is {shown}"
        try:
            number = float(value)
        except OverflowError:
            return {}, (f"{path.name}: response '{name}' is an integer of {len(str(abs(value)))} digits, "
                        "too large for a float")
        if not math.isfinite(number):
            return {}, f"{path.name}: response '{name}' is {number} (not a finite number)"
        if number != 0 and not SMALLEST <= abs(number) <= LARGEST:
            return {}, (f"{path.name}: response '{name}' is {number:g}, outside the magnitudes demid computes "
                        f"with (0, or {SMALLEST:g} to {LARGEST:g})")
        values[name] = number
    return values, ""


def params_digest(document: dict) -> str:
    """The SHA-256 of params.json as demid writes it: run.json carries it, tying the record to the
    parameters of its run."""
    return hashlib.sha256(_json_text(document).encode("utf-8")).hexdigest()


def execute(parameters: dict, run_dir: Path | str, responses, log, timeout_s: float) -> dict:
    """Run one simulation and return its record ``{status, reason, responses, params_sha256}``.

    Writes the run's ``params.json`` first.  ``log``: an open text file receiving the command line, its
    output and the outcome; ``timeout_s``: the run's time limit in seconds.  The responses file of an
    earlier attempt is removed first, so a failed retry cannot pass off stale values.  SIGINT, SIGTERM
    or SIGHUP, or the workflow that started this job going away, stop the command with everything it
    started and raise :class:`RunStopped` (no record: the run is left for the next invocation).
    """
    run_dir = Path(run_dir).resolve()
    run_dir.mkdir(parents=True, exist_ok=True)
    params_path = run_dir / "params.json"
    write_run_json(parameters, params_path)
    digest = params_digest(parameters)
    values = dict(parameters["factors"], run=parameters["run"], wave=parameters["wave"], seed=parameters["seed"],
                  run_dir=str(run_dir))
    argv = fill_command(parameters["command"], values)
    out = run_dir / parameters["responses_file"]
    out.unlink(missing_ok=True)
    log.write("command: " + shlex.join(argv) + "\n")
    log.flush()

    def record(status, reason, found):
        return _record(status, reason, found, digest, log)

    marker = os.urandom(16).hex()
    try:
        # its own session, so that a time-out or a stop ends whatever the command started too
        process = subprocess.Popen(argv, stdout=log, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                                   start_new_session=True, env=dict(os.environ, **{RUN_MARKER: marker}))
    except OSError as exc:
        return record(FAILED, f"could not start the command ({exc.strerror or exc})", {})
    outcome, stopped = _wait(process, timeout_s, marker)
    if outcome == "stopped":
        log.write(f"stopped: {stopped}; the run is left for the next invocation\n")
        log.flush()
        # none of the run's outputs left behind: Snakemake, stopped too, would call them incomplete
        for leftover in (out, params_path):
            leftover.unlink(missing_ok=True)
        raise RunStopped(stopped)
    if _file_digest(params_path) != digest:
        write_run_json(parameters, params_path)
        return record(FAILED, "the command wrote params.json, demid's own file in {run_dir} (write only the "
                              "responses file there)", {})
    if outcome == "timed out":
        return record(FAILED, f"timed out after {timeout_s:g} s", {})
    if process.returncode != 0:
        return record(FAILED, f"the command exited with status {process.returncode}", {})
    found, reason = _read_responses(out, responses)
    return record(FAILED, reason, {}) if reason else record(OK, "", found)


def _wait(process: subprocess.Popen, timeout_s: float, marker: str) -> tuple[str, str]:
    """Wait for the command: ("ended", ""), ("timed out", "") or ("stopped", why); after a time-out or
    a stop, everything the command started that can be found has been ended."""
    received = []
    handlers = {}
    if threading.current_thread() is threading.main_thread():  # only there can Python take a signal
        for signum in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
            handlers[signum] = signal.signal(signum, lambda number, frame: received.append(number))
    parent = os.getppid()
    deadline = time.monotonic() + timeout_s
    try:
        while True:
            try:
                process.wait(timeout=_POLL_S)
                return "ended", ""
            except subprocess.TimeoutExpired:
                pass
            if received:
                why = f"{signal.Signals(received[0]).name} received"
            elif os.getppid() != parent:
                why = "the workflow that started the run has ended"
            elif time.monotonic() >= deadline:
                why = ""
            else:
                continue
            end_processes(process, marker)
            return ("stopped", why) if why else ("timed out", "")
    finally:
        for signum, handler in handlers.items():
            signal.signal(signum, handler)


def end_processes(process: subprocess.Popen, marker: str, grace_s: float = STOP_GRACE_S) -> None:
    """End the command and everything it started that can be found: its session, and any process
    carrying the run's environment marker (a daemon in a session of its own); SIGTERM first, SIGKILL
    to whatever is left after ``grace_s`` seconds.  The command is reaped."""
    for signum, wait_s in ((signal.SIGTERM, grace_s), (signal.SIGKILL, 5.0)):
        pids = _run_processes(process.pid, marker) | ({process.pid} if process.poll() is None else set())
        for pid in pids:
            try:
                os.kill(pid, signum)
            except (ProcessLookupError, PermissionError):
                pass
        deadline = time.monotonic() + wait_s
        while time.monotonic() < deadline:
            process.poll()
            if not _run_processes(process.pid, marker) and process.returncode is not None:
                return
            time.sleep(0.05)
    process.wait()


def _run_processes(session: int, marker: str) -> set[int]:
    """Live processes in session ``session`` or whose environment carries ``marker`` (Linux /proc;
    elsewhere the command's process group only)."""
    proc = Path("/proc")
    if not proc.is_dir():
        try:
            os.killpg(session, 0)
            return {session}
        except OSError:
            return set()
    tag = f"{RUN_MARKER}={marker}".encode("ascii") + b"\0"
    found = set()
    for entry in proc.iterdir():
        if not entry.name.isdigit() or int(entry.name) == os.getpid():
            continue
        try:
            stat = (entry / "stat").read_text(encoding="ascii", errors="replace")
            fields = stat[stat.rindex(")") + 2:].split()
            if fields[0] == "Z":  # ended; only its exit status is left for its parent
                continue
            if int(fields[3]) == session or tag in (entry / "environ").read_bytes():
                found.add(int(entry.name))
        except (OSError, ValueError, IndexError):
            continue
    return found


def _file_digest(path: Path) -> str:
    try:
        return hashlib.sha256(path.read_bytes()).hexdigest()
    except OSError:
        return ""


def _record(status: str, reason: str, responses: dict, digest: str, log) -> dict:
    log.write(f"status: {status}" + (f" ({reason})" if reason else "") + "\n")
    return {"status": status, "reason": reason, "responses": responses, "params_sha256": digest}


def read_run(params_path: Path | str, record_path: Path | str) -> tuple[dict, dict]:
    """A run's parameters and record, as its job wrote them: the record must carry the digest of the
    parameters beside it.  A pair changed since (a command writing into another run's folder) raises
    InputError naming the folder, and its run.json is removed so that the next invocation runs it again."""
    params_path, record_path = Path(params_path), Path(record_path)
    try:
        params_bytes = params_path.read_bytes()
        record = json.loads(record_path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, ValueError, RecursionError):
        record = None
    if not (isinstance(record, dict) and record.get("params_sha256") == hashlib.sha256(params_bytes).hexdigest()
            and record.get("status") in (OK, FAILED) and isinstance(record.get("responses"), dict)):
        record_path.unlink(missing_ok=True)
        raise InputError(f"{record_path.parent}: run.json does not match the params.json beside it (changed after "
                         "the run's job wrote them, by a command writing into a folder not its own?, or written "
                         "by an earlier demid); run.json removed, the next invocation runs this run again")
    return json.loads(params_bytes.decode("utf-8")), record


def assemble_table(records, factors, responses) -> pd.DataFrame:
    """The material's table from its runs' parameters and records: ``run``, ``wave``, one column per factor
    and response, ``status`` (``failed`` runs with empty responses); sorted by run."""
    import numpy as np
    import pandas as pd

    rows = []
    for parameters, record in records:
        row = {"run": int(parameters["run"]), "wave": int(parameters["wave"])}
        row.update({f: float(parameters["factors"][f]) for f in factors})
        ok = record["status"] == OK
        row.update({r: float(record["responses"][r]) if ok else np.nan for r in responses})
        row["status"] = OK if ok else FAILED
        rows.append(row)
    frame = pd.DataFrame(rows, columns=["run", "wave", *factors, *responses, "status"])
    return frame.sort_values("run", kind="stable").reset_index(drop=True)


def _json_text(document: dict) -> str:
    return json.dumps(document, sort_keys=True, indent=2, ensure_ascii=False, allow_nan=False) + "\n"


def write_run_json(document: dict, path: Path | str) -> None:
    """A run's JSON file (params.json, run.json) as :func:`demid.io.write_json` lays it out (sorted keys,
    two-space indent), written atomically with the standard library alone."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".json", dir=path.parent)
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as out:
            out.write(_json_text(document))
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise

"""Running a material's simulations: one run = one command, its responses read back from JSON.

A material with ``simulation:`` has no finished table: demid runs the command once per run of a
wave.  The command is split like a shell line (:func:`shlex.split`) and executed *without* a shell;
placeholders are filled word by word with numbers and the run's folder, so neither the config's
values nor anything the pipeline writes can become shell syntax.  A run that exits non-zero, times
out, or leaves no valid responses is recorded as ``failed`` (with the reason); the analysis keeps
the row, as for a transcribed table with a failed run.
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


def _read_responses(path: Path, responses) -> tuple[dict, str]:
    """(responses, reason): the values of every response, or an empty dict and why not."""
    if not path.is_file():
        return {}, f"the command wrote no {path.name}"
    try:
        document = json.loads(path.read_text(encoding="utf-8"))
    except (UnicodeDecodeError, ValueError) as exc:
        return {}, f"{path.name} is not valid JSON ({exc})"
    if not isinstance(document, dict):
        return {}, f"{path.name} holds no JSON object {{response: value}}"
    values = {}
    for name in responses:
        value = document.get(name)
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            return {}, f"{path.name}: response '{name}' is {'missing' if name not in document else repr(value)}"
        if not math.isfinite(value):
            return {}, f"{path.name}: response '{name}' is {value} (not a finite number)"
        values[name] = float(value)
    return values, ""


def execute(parameters: dict, run_dir: Path | str, responses, log, timeout_s: float) -> dict:
    """Run one simulation and return its record ``{status, reason, responses}``.

    ``log``: an open text file receiving the command line, its output and the outcome; ``timeout_s``:
    the run's time limit in seconds.  The responses file of an earlier attempt is removed first, so a
    failed retry cannot pass off stale values.
    """
    run_dir = Path(run_dir).resolve()
    run_dir.mkdir(parents=True, exist_ok=True)
    values = dict(parameters["factors"], run=parameters["run"], wave=parameters["wave"], seed=parameters["seed"],
                  run_dir=str(run_dir))
    argv = fill_command(parameters["command"], values)
    out = run_dir / parameters["responses_file"]
    out.unlink(missing_ok=True)
    log.write("command: " + shlex.join(argv) + "\n")
    log.flush()
    try:
        # its own process group, so that a timeout stops whatever the command started too
        process = subprocess.Popen(argv, stdout=log, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                                   start_new_session=True)
    except OSError as exc:
        return _record(FAILED, f"could not start the command ({exc.strerror or exc})", {}, log)
    try:
        returncode = process.wait(timeout=timeout_s)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        process.wait()
        return _record(FAILED, f"timed out after {timeout_s:g} s", {}, log)
    if returncode != 0:
        return _record(FAILED, f"the command exited with status {returncode}", {}, log)
    values, reason = _read_responses(out, responses)
    return _record(FAILED, reason, {}, log) if reason else _record(OK, "", values, log)


def _record(status: str, reason: str, responses: dict, log) -> dict:
    log.write(f"status: {status}" + (f" ({reason})" if reason else "") + "\n")
    return {"status": status, "reason": reason, "responses": responses}


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


def write_run_json(document: dict, path: Path | str) -> None:
    """A run's JSON file (params.json, run.json) as :func:`demid.io.write_json` lays it out (sorted keys,
    two-space indent), written atomically with the standard library alone."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".json", dir=path.parent)
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as out:
            out.write(json.dumps(document, sort_keys=True, indent=2, ensure_ascii=False, allow_nan=False) + "\n")
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise

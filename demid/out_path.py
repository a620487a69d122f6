"""Where a command may write: never onto its own input, a folder, a device or someone else's file.

Every ``--out`` (and ``--config-out``) of the command line passes :func:`check_out_path` before anything
is computed.  An existing file is replaced only when it is demid's own output (the JSON of fit, criticize or
check-transcription, an unfilled run sheet, a generated config fragment), or with ``--force``.
"""

from __future__ import annotations

import csv
import json
import os
import stat
from pathlib import Path

from .errors import InputError

#: Keys every JSON a command writes carries (fit: per response; the others at the top level).
_FIT_KEYS = {"n_runs", "r2", "coefficients", "coefficients_coded"}
_CRITICIZE_KEYS = {"response", "baseline", "findings", "catalogue", "verdict"}
_TRANSCRIPTION_KEYS = {"response", "published", "reproduced"}
#: The header comment of a config fragment written by ``demid design --config-out``.
FRAGMENT_HEADER = "# Generated with the run sheet;"
_MOST_LEVELS = 5  # a factor column of a generated sheet (CCD: -α, -1, 0, 1, α)


def _json(path: Path):
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, ValueError):
        return None


def is_fit_json(path: Path) -> bool:
    data = _json(path)
    return isinstance(data, dict) and bool(data) and all(isinstance(v, dict) and _FIT_KEYS <= set(v)
                                                         for v in data.values())


def is_criticism_json(path: Path) -> bool:
    data = _json(path)
    return isinstance(data, dict) and _CRITICIZE_KEYS <= set(data)


def is_transcription_json(path: Path) -> bool:
    data = _json(path)
    return isinstance(data, dict) and _TRANSCRIPTION_KEYS <= set(data)


def is_demid_json(path: Path) -> bool:
    """A JSON any of demid's commands writes (fit, criticize, check-transcription): demid's own output."""
    return is_fit_json(path) or is_criticism_json(path) or is_transcription_json(path)


def is_unfilled_run_sheet(path: Path) -> bool:
    """A sheet as ``demid design`` writes it: ``run, std_order``, factor columns of a few levels, response
    columns still empty.  A cell filled in (a simulated result) makes it the user's data."""
    try:
        with open(path, newline="", encoding="utf-8") as fh:
            rows = list(csv.reader(fh))
    except (OSError, UnicodeDecodeError, csv.Error):
        return False
    if len(rows) < 2 or rows[0][:2] != ["run", "std_order"]:
        return False
    for j in range(2, len(rows[0])):
        cells = [r[j].strip() if j < len(r) else "" for r in rows[1:]]
        filled = [c for c in cells if c]
        if filled and (len(filled) < len(cells) or len(set(filled)) > _MOST_LEVELS):
            return False
    return True


def is_config_fragment(path: Path) -> bool:
    """A fragment as ``demid design --config-out`` writes it, before targets and scenarios are added."""
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError):
        return False
    body = "\n".join(ln for ln in text.splitlines() if not ln.lstrip().startswith("#"))
    return text.startswith(FRAGMENT_HEADER) and "target:" not in body and "scenarios:" not in body


def check_out_path(out: str, option: str, inputs=(), *, force: bool = False, is_own=None) -> None:
    """Refuse ``out`` (given as ``option``) when it names one of ``inputs``, is anything but a regular file
    or a new path (a folder, a device, a pipe), or is an existing file that ``is_own`` does not recognise
    as demid's own output and ``force`` is not given."""
    path = Path(out)
    for given in inputs:
        if given and _same_file(path, Path(given)):
            raise InputError(f"{option}: '{out}' is an input of this command ({given}); it would be overwritten, "
                             "name another file")
    try:
        mode = os.stat(path).st_mode
    except FileNotFoundError:
        return
    except OSError as err:
        raise InputError(f"{option}: '{out}' cannot be checked ({err.strerror}); name another file") from None
    if stat.S_ISDIR(mode):
        raise InputError(f"{out}: is a folder; name the file to write")
    if not stat.S_ISREG(mode):
        raise InputError(f"{option}: '{out}' is not a regular file (a device, pipe or socket); name a file to write")
    if force or (is_own is not None and is_own(path)):
        return
    raise InputError(f"{option}: '{out}' exists and is not a file demid wrote; it would be replaced. "
                     "Name another file, or add --force to replace it")


def _same_file(a: Path, b: Path) -> bool:
    try:
        return a.exists() and b.exists() and os.path.samefile(a, b)
    except OSError:
        return False


#: The file in a results_dir naming the study folder whose results it holds.
STUDY_MARKER = ".demid_study"


def results_owner_problem(results_dir: Path | str, study_dir: Path | str) -> str:
    """The error line when ``results_dir`` holds the results of another study folder (that still exists),
    or ""."""
    marker = Path(results_dir) / STUDY_MARKER
    try:
        owner = marker.read_text(encoding="utf-8").strip()
    except (OSError, UnicodeDecodeError):
        return ""
    study = str(Path(study_dir).resolve())
    if not owner or owner == study or not Path(owner).is_dir():  # a study moved or deleted leaves its claim
        return ""
    if (Path(study_dir) / results_dir).resolve().is_relative_to(study):
        return ""  # a results folder inside the study folder is its own: a copied study folder takes its copy over
    return (f"config key results_dir: '{results_dir}' holds the results of the study in {owner}; two studies "
            f"writing one results_dir overwrite each other, so give this one its own (or delete {marker} if "
            "that study is gone)")


def claim_results_dir(results_dir: Path | str, study_dir: Path | str) -> str:
    """Mark ``results_dir`` as the results of ``study_dir`` before a run writes into it; the error line of
    :func:`results_owner_problem` when another study holds it (also when two start at once: the marker is
    created exclusively), or ""."""
    problem = results_owner_problem(results_dir, study_dir)
    if problem:
        return problem
    marker = Path(results_dir) / STUDY_MARKER
    study = str(Path(study_dir).resolve())
    marker.parent.mkdir(parents=True, exist_ok=True)
    if marker.is_file() and marker.read_text(encoding="utf-8", errors="replace").strip() == study:
        return ""
    tmp = marker.with_name(f"{STUDY_MARKER}.{os.getpid()}")
    tmp.write_text(study + "\n", encoding="utf-8")
    try:
        os.link(tmp, marker)  # fails when another study created it meanwhile
    except FileExistsError:
        if results_owner_problem(results_dir, study_dir):
            return results_owner_problem(results_dir, study_dir)
        os.replace(tmp, marker)  # a stale claim (its study gone): taken over
        return ""
    finally:
        tmp.unlink(missing_ok=True)
    return ""

"""Reading and validating a transcribed design table.

Every problem is reported as one ``InputError`` line naming the file, the run
and the column, saying what was found and what is expected.  The raw file is
only ever read.  Part of the input layer: the material arrives as its
:class:`~demid.spec.MaterialSpec`; the likely-typo stop is
:func:`demid.transcription.typos.refuse_likely_typos`.
"""

from __future__ import annotations

import difflib
import math
import re
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from .blocks import BLOCK_COLUMN, label_text
from .csv_cells import is_number, parse_number, read_raw, read_raw_numbered
from .design import Coding, factor_levels, model_matrix, model_units, quadratic_terms, snap_to_factor_levels
from .design_check import check_design, odd_level_values
from .errors import InputError
from .estimability import require_estimable
from .precision import PRINTED_PLACE, printed_place

if TYPE_CHECKING:
    from .spec import Factor, MaterialSpec

_FAILED = {"failed", "fail", "error", "crashed", "timeout", "diverged", "aborted", "killed", "unstable"}
_OK = {"", "ok", "done", "success", "succeeded", "completed", "complete", "finished", "converged", "valid"}
_NONFINITE = {"nan", "inf", "+inf", "-inf", "infinity", "-infinity"}


def _run_failed(status: str, status_column: str, src: str, run: int) -> bool:
    """Whether a run's status says its simulation failed ('failed (timeout)' does); a status that is neither
    an ok nor a failure word is bad input, since guessing either way would fit or drop the run wrongly."""
    word = re.split(r"[^a-z]+", status, maxsplit=1)[0]
    if status in _OK or status == "nan" or (word and word in _OK):  # "nan": an empty cell written by pandas
        return False
    if status in _FAILED or word in _FAILED or status.startswith("time"):
        return True
    raise InputError(f"status '{status}' is neither ok nor failed; write failed for a simulation that did not "
                     f"finish (understood: {', '.join(sorted(_FAILED))}) or ok for one that did (or "
                     f"{', '.join(sorted(w for w in _OK if w))})", source=src, run=run, column=status_column)


@dataclass
class ValidatedTable:
    """A checked table plus what the checks found (warnings are not errors)."""

    table: pd.DataFrame
    coding: Coding
    point_types: np.ndarray
    warnings: list[str] = field(default_factory=list)
    failed: dict[str, list] = field(default_factory=dict)
    log_factors: tuple[str, ...] = ()

    def summary(self, material: str) -> dict:
        counts = {t: int(np.sum(self.point_types == t)) for t in sorted(set(self.point_types))}
        return {
            "material": material,
            "n_runs": int(len(self.table)),
            "point_types": counts,
            "coding": {f: {"center": c, "unit": u}
                       for f, c, u in zip(self.coding.factors, self.coding.center, self.coding.unit)},
            "failed_runs": self.failed,
            "warnings": list(self.warnings),
        }

    def to_frame(self) -> pd.DataFrame:
        out = self.table.copy()
        factors = list(self.coding.factors)
        coded = self.coding.to_coded(model_units(out[factors].to_numpy(), factors, self.log_factors))
        for i, f in enumerate(self.coding.factors):
            out[f"coded:{f}"] = coded[:, i]
        out["point_type"] = self.point_types
        return out


def check_header(header: list[str], factors, responses, src: str) -> None:
    """The header names each column once, and names the run, every factor and every response."""
    needed = ["run"] + list(factors) + list(responses)
    missing = [col for col in needed if col not in header]
    dup_cols = {h for h in header if header.count(h) > 1}
    if dup_cols:
        # a header typed over (d5,d10,d10 for d5,d10,d15): the repeat, then the column it likely stands for
        named = " or ".join(f"'{m}'" for m in missing)
        hint = (f"; {named} {'is' if len(missing) == 1 else 'are'} missing: is one of them {named}?"
                if missing else "")
        raise InputError(f"column appears more than once in the header{hint}", source=src, column=sorted(dup_cols)[0])
    for col in missing:
        same = [h for h in header if h.casefold() == col.casefold()]
        # a column the table needs under its own name is no misspelling of another
        spare = [h for h in header if h not in needed]
        close = same or difflib.get_close_matches(col, spare, n=1, cutoff=0.6)
        hint = (f"; found '{same[0]}', which differs only in upper/lower case" if same
                else f"; found '{close[0]}' — misspelled?" if close else f"; columns found: {', '.join(header)}")
        raise InputError(f"missing column (expected columns: {', '.join(needed)}){hint}", source=src, column=col)
    for col in ("status", "block"):
        # 'Block' or 'STATUS' would otherwise be read as an unlisted column and its meaning silently lost
        same = [h for h in header if h != col and h.casefold() == col.casefold() and h not in needed]
        if same and col not in header:
            raise InputError(f"differs only in upper/lower case from the reserved column "
                             f"'{col}': rename it to '{col}'", source=src, column=same[0])


def read_table(path: Path | str, factors: list[str], responses: list[str],
               status_column: str = "status") -> tuple[pd.DataFrame, list[str]]:
    """Parse a design table into floats.  Returns (table, warnings).

    Empty or non-finite response cells are allowed only for runs marked as
    failed in ``status_column`` (or written explicitly as NaN/inf): those
    responses become NaN and are excluded from the fit.
    """
    src = str(path)
    header, rows, line_numbers = read_raw_numbered(path)
    check_header(header, factors, responses, src)
    idx = {h: i for i, h in enumerate(header)}
    has_status = status_column in idx
    warnings: list[str] = []
    records = []
    seen_runs: dict[int, int] = {}
    for line_no, row in zip(line_numbers, rows):
        if len(row) != len(header):
            raise InputError(f"line {line_no} has {len(row)} cells, the header has {len(header)}", source=src)
        run_cell = row[idx["run"]].strip()
        try:
            run_val = parse_number(run_cell)
        except ValueError as exc:
            raise InputError(f"line {line_no}: {exc}; expected an integer run number", source=src,
                             column="run") from None
        if not float(run_val).is_integer() or abs(run_val) >= 2 ** 53:  # exact as a float and in parquet
            raise InputError(f"line {line_no}: found '{run_cell}', expected an integer run number"
                             + (" below 2^53" if float(run_val).is_integer() else ""), source=src, column="run")
        run = int(run_val)
        if run in seen_runs:
            raise InputError(f"duplicate run number (lines {seen_runs[run]} and {line_no})", source=src,
                             run=run, column="run")
        seen_runs[run] = line_no
        status = row[idx[status_column]].strip().lower() if has_status else ""
        failed = _run_failed(status, status_column, src, run)
        rec = {"run": run}
        for col in factors:
            try:
                value = parse_number(row[idx[col]])
            except ValueError as exc:
                raise InputError(str(exc), source=src, run=run, column=col) from None
            if not math.isfinite(value):
                raise InputError(f"found '{row[idx[col]].strip()}', factor values must be finite numbers",
                                 source=src, run=run, column=col)
            rec[col] = value
        for col in responses:
            rec[col] = _response_value(row[idx[col]].strip(), status if failed else None, status_column,
                                       has_status, warnings, source=src, run=run, column=col)
        if failed:
            warnings.append(f"{src}, run {run}: marked '{status}' in column '{status_column}'; its missing "
                            f"responses are excluded from the fits")
        rec["status"] = "failed" if failed else "ok"
        if BLOCK_COLUMN in idx:  # runs made in blocks (demid.blocks): the label as written
            label = row[idx[BLOCK_COLUMN]].strip()
            if not label:
                raise InputError("empty block label; give every run its block (any label, e.g. 1 and 2)",
                                 source=src, run=run, column=BLOCK_COLUMN)
            rec[BLOCK_COLUMN] = label_text(parse_number(label)) if is_number(label) else label
        records.append(rec)
    if not records:
        raise InputError("the table has a header but no runs", source=src)
    table = pd.DataFrame.from_records(records)
    table = table.sort_values("run", kind="stable").reset_index(drop=True)
    # the design check judges a level within the print's own rounding, which only the text shows
    table.attrs[PRINTED_PLACE] = {col: printed_place(row[idx[col]] for row in rows) for col in factors}
    return table, warnings


def _response_value(cell: str, failed_status: str | None, status_column: str, has_status: bool,
                    warnings: list[str], *, source: str, run: int, column: str) -> float:
    """A response cell as a number: NaN where the run is marked failed (``failed_status``, as written) and the
    cell is empty or non-finite, or where the cell holds NaN/inf (with a warning); one clear line otherwise."""
    if failed_status is not None and (cell == "" or cell.lower() in _NONFINITE):
        return np.nan
    if failed_status is not None:
        raise InputError(f"the run is marked '{failed_status}' in column '{status_column}' but this cell holds "
                         f"'{cell}'; empty the cell if the simulation failed (if only some responses "
                         "failed, clear the status and write NaN in their cells)",
                         source=source, run=run, column=column)
    if cell.lower() in _NONFINITE:
        warnings.append(f"{source}, run {run}, column '{column}': value '{cell}' treated as a failed simulation")
        return np.nan
    try:
        return parse_number(cell)
    except ValueError as exc:
        hint = ("" if cell != "" else f"; if this simulation failed, write failed in its '{status_column}' "
                f"cell" if has_status else f"; if this simulation failed, add a '{status_column}' column with "
                f"'failed'")
        raise InputError(f"{exc}{hint}", source=source, run=run, column=column) from None


def read_printed(path: Path | str, table: pd.DataFrame) -> pd.DataFrame:
    """The table's cells as printed (strings, trailing zeros kept), in ``table``'s row order."""
    header, rows, _ = read_raw(path)
    printed = pd.DataFrame(rows, columns=header).apply(lambda col: col.str.strip())
    printed["run"] = [str(int(parse_number(v))) for v in printed["run"]]
    order = {str(r): i for i, r in enumerate(printed["run"])}
    return printed.iloc[[order[str(int(r))] for r in table["run"]]].reset_index(drop=True)


#: A target of the runs' sign off from the nearest simulated value by at least this factor, which a power of ten
#: brings inside the simulated range, reads as a unit slip even when the runs spread widely (0.6 for 6 where the
#: runs give 5 to 60): nearer the range than this, a target a power of ten away may just lie below or above it.
UNIT_SLIP_RATIO = 3.0


def _power_of_ten_repair(target: float, lo: float, hi: float) -> tuple[float, float] | None:
    for power in sorted((p for p in range(-6, 7) if p), key=abs):
        value = float(target) * 10.0 ** power
        if lo <= value <= hi:
            return 10.0 ** power, value
    return None


def _off_by_a_ratio(target: float, lo: float, hi: float) -> bool:
    """The target lies outside the runs' range by at least :data:`UNIT_SLIP_RATIO`.  Asked only of a target
    that a power of ten brings inside the range, so of the runs' sign when the range holds no zero; a range
    from below zero to above it is no unit slip's."""
    if lo > 0:
        return target * UNIT_SLIP_RATIO <= lo or target >= hi * UNIT_SLIP_RATIO
    if hi < 0:
        return _off_by_a_ratio(-target, -hi, -lo)
    return False


def implausible_targets(table: pd.DataFrame, targets: dict) -> dict[str, dict]:
    """Targets farther outside every simulated value of their response than the simulated values spread
    (more than one range beyond the nearest run), or off from them by a power of ten (a factor of
    :data:`UNIT_SLIP_RATIO` or more beyond the range, which a power of ten brings inside it): per response
    ``lo``, ``hi`` (the simulated range), ``far`` (more than one range beyond the runs) and, where a power of
    ten brings the target inside that range (a unit or typing slip: 1.505 g cm^-3 for 1505 kg m^-3),
    ``factor`` and ``repaired``."""
    out = {}
    for response, target in targets.items():
        if response not in table:
            continue
        y = table[response].to_numpy(dtype=float)
        y = y[np.isfinite(y)]
        if not len(y):
            continue
        lo, hi = float(y.min()), float(y.max())
        if lo == hi or lo <= target <= hi:
            continue
        repair = _power_of_ten_repair(target, lo, hi)
        far = not (lo - (hi - lo) <= target <= hi + (hi - lo))
        if not far and not (repair and _off_by_a_ratio(float(target), lo, hi)):
            continue
        found = {"lo": lo, "hi": hi, "factor": None, "repaired": None, "far": far}
        if repair:
            found.update(factor=repair[0], repaired=repair[1])
        out[response] = found
    return out


def power_of_ten_repair(found: dict) -> str:
    """``×1000 → 1505 lies inside the simulated range (1474 to 1534)`` for one implausible target."""
    factor = found["factor"]
    times = f"×{factor:g}" if factor >= 1 else f"÷{1 / factor:g}"
    return (f"{times} → {found['repaired']:.6g} lies inside the simulated range ({found['lo']:.4g} to "
            f"{found['hi']:.4g})")


def far_target_warnings(table: pd.DataFrame, targets: dict, src: str, material: str | None = None) -> list[str]:
    """Targets farther outside every simulated value of their response than the simulated values spread
    (more than one range beyond the nearest run), naming the config key, a power of ten (a unit slip) or a
    one-keystroke slip that would bring the target among the simulated values (264 for 26.4).  A constant
    column is warned of on its own."""
    from .transcription.typos import SLIP_WORDS, single_cell_slips

    out = []
    for response, found in implausible_targets(table, targets).items():
        target, lo, hi = targets[response], found["lo"], found["hi"]
        key = f" (config key materials.{material}.responses.{response}.target)" if material else ""
        where = (f"{src}, column '{response}': the target {target:.6g} lies far outside every simulated value "
                 f"({lo:.4g} to {hi:.4g}){key}")
        slips = [(value, kind) for kind, _, value in single_cell_slips(repr(float(target)))
                 if kind in _BOUND_SLIPS and lo <= value <= hi]
        repair = f"; repair: {power_of_ten_repair(found)}" if found["factor"] is not None else ""
        if slips:
            if found["repaired"] is not None:  # the point shift the repair names first: one value in one sentence
                slips.sort(key=lambda s: not math.isclose(s[0], found["repaired"]))
            value, kind = slips[0]
            out.append(f"{where} and looks like {value:.6g} with {SLIP_WORDS[kind]}{repair}; check the target. As "
                       "given, no simulated setting comes near it and level 2 will report a discrepancy.")
        elif repair:
            out.append(f"{where} and looks like {found['repaired']:.6g} in another unit (or with the decimal point "
                       f"shifted){repair}; check the target's unit. As given, no simulated setting comes near it "
                       "and level 2 will report a discrepancy.")
        else:
            out.append(f"{where}; no simulated setting comes near it, so level 2 will report a discrepancy "
                       "between simulation and measurement, not a calibration.")
    return out


def check_bounds(table: pd.DataFrame, factors: tuple[Factor, ...], src: str, rel_tol: float = 1e-6) -> None:
    """Every factor value lies within its factor's bounds (up to ``rel_tol`` of the range)."""
    for factor in factors:
        f, lo, hi = factor.name, factor.lower, factor.upper
        slack = rel_tol * (hi - lo)
        bad = table[(table[f] < lo - slack) | (table[f] > hi + slack)]
        if len(bad):
            r = bad.iloc[0]
            raise InputError(f"value {r[f]:g} lies outside the declared bounds [{lo:g}, {hi:g}] "
                             f"(config factors.{f})", source=src, run=int(r["run"]), column=f)


#: The slips that move a bound or a target far (point, swap, sign): a bound rounded outwards is none of them.
_BOUND_SLIPS = ("decimal_shift", "transposition", "sign_lost")


def check_bound_slips(table: pd.DataFrame, material: str, factors: tuple[Factor, ...], src: str) -> None:
    """A search bound beyond the runs that a one-keystroke slip turns into the runs' own extreme value
    (upper 9.24264 where the largest run is 0.924264) is a typo, not a wider search: refuse it.  Only
    bounds beyond the runs by a tenth of their range are considered (a bound rounded outwards, 2.9289 for
    2.92893, is no slip), and only the slips that move a value far: point, swap, sign."""
    from .transcription.typos import SLIP_WORDS, single_cell_slips

    for factor in factors:
        f = factor.name
        values = table[f].to_numpy(dtype=float)
        margin = 0.1 * (values.max() - values.min())
        for side, bound, extreme in (("lower", factor.lower, values.min()), ("upper", factor.upper, values.max())):
            if (bound > extreme - margin) if side == "lower" else (bound < extreme + margin):
                continue
            for kind, _, value in single_cell_slips(repr(float(bound))):
                if kind in _BOUND_SLIPS and np.isclose(value, extreme, rtol=1e-6, atol=0.0):
                    raise InputError(f"config key materials.{material}.factors.{f}.{side}: {bound:g} lies beyond the "
                                     f"runs, whose {'smallest' if side == 'lower' else 'largest'} {f} is {extreme:g}, "
                                     f"and looks like {value:g} with {SLIP_WORDS[kind]}; fix the bound", source=src)


def _block_notes(table: pd.DataFrame, factors: list[str], coding: Coding, log_factors, src: str) -> list[str]:
    """How the runs' blocks sit in the design (demid.blocks): a block term that cannot be estimated stops;
    a block without centre runs and non-orthogonal blocking are said."""
    from .blocks import block_labels, check_blocks

    labels = block_labels(table)
    if labels is None:
        return []
    coded = coding.to_coded(model_units(table[factors].to_numpy(), factors, log_factors))
    check = check_blocks(coded, labels, model_matrix(coded, quadratic_terms(len(factors))))
    if check.problems:
        raise InputError(check.problems[0], source=src, column=BLOCK_COLUMN)
    notes = [n for n in check.notes if not (check.orthogonal and n.startswith("blocking is orthogonal"))]
    return [f"{src}, column '{BLOCK_COLUMN}': {note}" for note in notes]


@contextmanager
def content_hidden_outside(data: str | Path, base_dir: Path | str = "."):
    """Errors about a table lying outside the study folder ``base_dir`` (its real path: symlinks followed)
    show none of its content: a config naming another file of the machine (``/etc/passwd``) must not get
    its lines printed back.  The table is still read when it is valid."""
    try:
        yield
    except InputError:
        real, study = (Path(base_dir) / data).resolve(), Path(base_dir).resolve()
        if real.is_relative_to(study):
            raise
        raise InputError(f"not a valid table of this material, and its content is not shown: it lies outside the "
                         f"study folder {study} (at {real}); copy the table into the study folder to see what is "
                         "wrong", source=str(data)) from None


def check_table_columns(spec: MaterialSpec, base_dir: Path | str = ".") -> None:
    """The cheap part of :func:`validate_material`, for the workflow's start-up: the table can be read and its
    header names the run, every factor and every response.  Its cells, its design and its likely typos are
    checked once, in the material's job.  Raises InputError."""
    header, _, _ = read_raw_numbered(Path(base_dir) / spec.data)
    check_header(header, spec.factor_names, spec.response_names, str(Path(spec.data)))


def validate_material(spec: MaterialSpec, base_dir: Path | str = ".") -> ValidatedTable:
    """Read a material's table (``spec.data``, relative to ``base_dir``) and run every check of its cells and
    design; raises InputError."""
    material = spec.name
    src = str(Path(spec.data))
    path = Path(base_dir) / spec.data
    factors = list(spec.factor_names)
    responses = list(spec.response_names)
    log_factors = spec.log_factors
    table, warnings = read_table(path, factors, responses, spec.status_column)
    table = table[["run"] + factors + responses + ["status"] + [c for c in (BLOCK_COLUMN,) if c in table.columns]]
    for f in log_factors:
        bad = table[table[f] <= 0]
        if len(bad):
            raise InputError("a log-scale factor needs positive values", source=src,
                             run=int(bad["run"].iloc[0]), column=f)
    check_bounds(table, spec.factors, src)
    check_bound_slips(table, material, spec.factors, src)
    problem = spec.limits_problem()  # after the bounds' slips: a slipped bound is named as such
    if problem:
        raise InputError(problem, source=src)
    p = len(quadratic_terms(len(factors)))
    for r in responses:
        ok = np.isfinite(table[r].to_numpy())
        if ok.sum() <= p:
            raise InputError(f"only {int(ok.sum())} usable runs for a quadratic model with {p} coefficients; "
                             f"at least {p + 1} are needed", source=src, column=r)
    coding, types = check_design(table, factors, spec.design, src, f"materials.{material}", log_factors)
    warnings.extend(_block_notes(table, factors, coding, log_factors, src))
    coded = coding.to_coded(model_units(table[factors].to_numpy(), factors, log_factors))
    levels = factor_levels(spec.design_type, spec.alpha, len(factors))
    if len(levels[0]):
        snapped = snap_to_factor_levels(coded, levels)
        warnings.extend(odd_level_values(table, factors, snapped, src))
    for r in responses:
        require_estimable(coded, np.isfinite(table[r].to_numpy()), types, src, r, factors)
    for r in responses:
        values = table[r].to_numpy(dtype=float)
        values = values[np.isfinite(values)]
        if len(values) and np.ptp(values) == 0:
            warnings.append(f"{src}, column '{r}': the same value ({values[0]:g}) in every run, so it cannot "
                            "identify any factor (a column filled in by mistake?)")
    warnings.extend(far_target_warnings(table, spec.targets, src, material))
    failed: dict[str, list] = {}
    for r in responses:
        ok = np.isfinite(table[r].to_numpy())
        if (~ok).any():
            lost = table.loc[~ok, "run"].tolist()
            failed[r] = lost
            centre_ok = int(np.sum((types == "center") & ok))
            note = " — pure error is no longer available" if centre_ok < 2 <= int(np.sum(types == "center")) else ""
            warnings.append(f"{src}, column '{r}': run(s) {', '.join(map(str, lost))} excluded from the fit "
                            f"(failed simulation){note}")
    return ValidatedTable(table=table, coding=coding, point_types=types, warnings=warnings, failed=failed,
                          log_factors=log_factors)

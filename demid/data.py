"""Reading and validating a transcribed design table.

Every problem is reported as one ``InputError`` line naming the file, the run
and the column, saying what was found and what is expected.  The raw file is
only ever read.
"""

from __future__ import annotations

import csv
import io
import difflib
import math
import re
from itertools import combinations, product
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd

from .blocks import BLOCK_COLUMN, label_text
from .design import (Coding, axial_distances, box_behnken_points, ccd_points, classify_points, factor_levels,
                     model_matrix, model_units, quadratic_terms, rotatable_alpha, snap_to_factor_levels, term_name)
from .precision import printed_quantum
from .errors import InputError
from .numbers import unusable_number
from .spec import as_spec

UNICODE_MINUS = "\u2212"
_DECIMAL_COMMA = re.compile(r"^[+-]?\d*,\d+$")
_THOUSANDS_OR_DECIMAL = re.compile(r"^[+-]?[1-9]\d{0,2},\d{3}$")
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


def _sniff_delimiter(header: str) -> str:
    counts = {d: header.count(d) for d in (",", ";", "\t")}
    return max(counts, key=lambda d: (counts[d], d == ","))


def read_raw_numbered(path: Path | str) -> tuple[list[str], list[list[str]], list[int]]:
    """Header, string cells and each row's line number in the file (comment and blank lines skipped)."""
    path = Path(path)
    if not path.is_file():
        raise InputError("data file does not exist", source=str(path))
    try:
        text = path.read_bytes().decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise InputError(f"not UTF-8 text (byte {exc.start}); save the table as UTF-8 CSV", source=str(path)) from None
    numbered = _records(text)
    if not numbered:
        raise InputError("the file is empty", source=str(path))
    delim = _sniff_delimiter(numbered[0][1])
    rows = []
    for no, record in numbered:
        try:
            rows.append(next(csv.reader(io.StringIO(record, newline=""), delimiter=delim)))
        except csv.Error as exc:  # e.g. a cell beyond the csv module's field size limit
            raise InputError(f"line {no}: not readable as CSV ({exc})", source=str(path)) from None
    header, rows = _drop_trailing_empty_columns([h.strip() for h in rows[0]], rows[1:])
    return header, rows, [no for no, _ in numbered[1:]]


def _records(text: str) -> list[tuple[int, str]]:
    """(first line number, text) of each CSV record, comment and blank lines skipped.  A quoted cell may
    hold a line break (valid CSV): its record continues on the next lines until the quote closes; a quote
    never closed leaves every line its own record (the cell count then names the line)."""
    lines = text.splitlines()
    out: list[tuple[int, str]] = []
    no = 0
    while no < len(lines):
        line = lines[no]
        if not line.strip() or line.lstrip().startswith("#"):
            no += 1
            continue
        end, quotes = no, line.count('"')
        while quotes % 2 and end + 1 < len(lines):
            end += 1
            quotes += lines[end].count('"')
        if quotes % 2:  # unclosed to the end of the file
            end = no
        out.append((no + 1, "\n".join(lines[no:end + 1])))
        no = end + 1
    return out


def _drop_trailing_empty_columns(header: list[str], rows: list[list[str]]) -> tuple[list[str], list[list[str]]]:
    """Spreadsheets often export empty columns after the last one used (``run,a,b,,``): columns at the end
    with no name and no value in any row are not part of the table."""
    width = len(header)
    while width and header[width - 1] == "" and all(len(r) < width or not r[width - 1].strip() for r in rows):
        width -= 1
    if width == len(header):
        return header, rows
    # a row with a value beyond the header keeps its length, so that its cell count is refused as before
    return header[:width], [r[:width] if not any(c.strip() for c in r[width:]) else r for r in rows]


def read_raw(path: Path | str) -> tuple[list[str], list[list[str]], str]:
    """Header and string cells; a UTF-8 BOM is dropped, delimiter sniffed from the header."""
    header, rows, _ = read_raw_numbered(path)
    lines = Path(path).read_bytes().decode("utf-8-sig").splitlines()
    first = next(ln for ln in lines if ln.strip() and not ln.lstrip().startswith("#"))
    return header, rows, _sniff_delimiter(first)


def parse_number(cell: str) -> float:
    """Parse one cell; Unicode minus is accepted.  Raises ValueError with a readable reason."""
    s = cell.strip().replace(UNICODE_MINUS, "-")
    if s == "":
        raise ValueError("empty cell")
    if _THOUSANDS_OR_DECIMAL.match(s):
        raise ValueError(f"found '{cell.strip()}': a thousands separator ({s.replace(',', '')}) or a decimal "
                         f"comma ({s.replace(',', '.')})? write the number with a decimal point and no separator")
    if _DECIMAL_COMMA.match(s):
        raise ValueError(f"found '{cell.strip()}', a decimal comma; expected a decimal point, e.g. "
                         f"'{s.replace(',', '.')}'")
    if "_" in s:  # Python reads 1_29.3 as 129.3; a table cell with an underscore is a slip
        raise ValueError(f"found '{cell.strip()}', a number with an underscore; expected digits only")
    try:
        value = float(s)
    except ValueError:
        raise ValueError(f"found '{cell.strip()}', expected a number") from None
    problem = unusable_number(value, cell) if s.lower().lstrip("+-") not in ("nan", "inf", "infinity") else ""
    if problem:  # spelled-out nan/inf keep their meaning (a failed run) to the caller
        raise ValueError(problem)
    return value


def _is_number(text: str) -> bool:
    try:
        parse_number(text)
    except ValueError:
        return False
    return True


def read_table(path: Path | str, factors: list[str], responses: list[str],
               status_column: str = "status") -> tuple[pd.DataFrame, list[str]]:
    """Parse a design table into floats.  Returns (table, warnings).

    Empty or non-finite response cells are allowed only for runs marked as
    failed in ``status_column`` (or written explicitly as NaN/inf): those
    responses become NaN and are excluded from the fit.
    """
    src = str(path)
    header, rows, line_numbers = read_raw_numbered(path)
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
            cell = row[idx[col]].strip()
            if failed and (cell == "" or cell.lower() in _NONFINITE):
                rec[col] = np.nan
                continue
            if failed:
                raise InputError(f"the run is marked '{status}' in column '{status_column}' but this cell holds "
                                 f"'{cell}'; empty the cell if the simulation failed (if only some responses "
                                 "failed, clear the status and write NaN in their cells)",
                                 source=src, run=run, column=col)
            if cell.lower() in _NONFINITE:
                rec[col] = np.nan
                warnings.append(f"{src}, run {run}, column '{col}': value '{cell}' treated as a failed simulation")
                continue
            try:
                rec[col] = parse_number(cell)
            except ValueError as exc:
                hint = ("" if cell != "" else f"; if this simulation failed, write failed in its '{status_column}' "
                        f"cell" if has_status else f"; if this simulation failed, add a '{status_column}' column with "
                        f"'failed'")
                raise InputError(f"{exc}{hint}", source=src, run=run, column=col) from None
        if failed:
            warnings.append(f"{src}, run {run}: marked '{status}' in column '{status_column}'; its missing "
                            f"responses are excluded from the fits")
        rec["status"] = "failed" if failed else "ok"
        if BLOCK_COLUMN in idx:  # runs made in blocks (demid.blocks): the label as written
            label = row[idx[BLOCK_COLUMN]].strip()
            if not label:
                raise InputError("empty block label; give every run its block (any label, e.g. 1 and 2)",
                                 source=src, run=run, column=BLOCK_COLUMN)
            rec[BLOCK_COLUMN] = label_text(parse_number(label)) if _is_number(label) else label
        records.append(rec)
    if not records:
        raise InputError("the table has a header but no runs", source=src)
    table = pd.DataFrame.from_records(records)
    table = table.sort_values("run", kind="stable").reset_index(drop=True)
    return table, warnings


def read_printed(path: Path | str, table: pd.DataFrame) -> pd.DataFrame:
    """The table's cells as printed (strings, trailing zeros kept), in ``table``'s row order."""
    header, rows, _ = read_raw(path)
    printed = pd.DataFrame(rows, columns=header).apply(lambda col: col.str.strip())
    printed["run"] = [str(int(parse_number(v))) for v in printed["run"]]
    order = {str(r): i for i, r in enumerate(printed["run"])}
    return printed.iloc[[order[str(int(r))] for r in table["run"]]].reset_index(drop=True)


def _level_coding(values: np.ndarray, counts: np.ndarray, levels: np.ndarray,
                  tol: float = 0.02) -> tuple[float, float] | None:
    """Centre and unit that put the most runs on the nominal ``levels`` (coded units).

    Every pair of distinct values is tried against every pair of levels; ties go to the most
    symmetric placement (lowest and highest level found equally far from the centre), then the narrowest.  A single
    mistyped cell sits on no level, so it cannot move the coding; no value is privileged by how
    often it occurs (a 3x3 factorial or a CCD with one centre run is coded like any other).
    """
    best, best_key = None, None
    for i, j in combinations(range(len(values)), 2):
        for a, b in combinations(range(len(levels)), 2):
            unit = (values[j] - values[i]) / (levels[b] - levels[a])
            centre = values[i] - unit * levels[a]
            coded = (values - centre) / unit
            nearest = np.abs(coded[:, None] - levels[None, :]).argmin(axis=1)
            on = np.abs(coded - levels[nearest]) <= tol
            # Last, the narrowest placement: three values of a CCD factor are its factorial levels and the
            # centre (a CCD has no factor without factorial points), not its axial levels.
            key = (int(counts[on].sum()), -round(abs(coded[on].max() + coded[on].min()), 6), int(on.sum()),
                   -round(float(np.abs(coded[on]).max()), 6))
            if best_key is None or key > best_key:
                best_key, best = key, (on, levels[nearest])
    if best is None:
        return None
    on, assigned = best
    vals, lev = values[on], assigned[on]
    # Exact printed values where the design has them: the centre run, the +-1 pair.
    centre = vals[lev == 0][0] if np.any(lev == 0) else None
    if np.any(lev == 1) and np.any(lev == -1):
        unit = (vals[lev == 1][0] - vals[lev == -1][0]) / 2.0
        centre = centre if centre is not None else (vals[lev == 1][0] + vals[lev == -1][0]) / 2.0
    else:
        unit, fitted_centre = np.polyfit(lev, vals, 1)
        centre = centre if centre is not None else fitted_centre
    return float(centre), float(unit)


def infer_coding(table: pd.DataFrame, factors: list[str], design: dict, src: str,
                 log_factors=()) -> Coding:
    """Centre and unit per factor from the design's geometry: the placement of the declared design's
    nominal levels that puts the most runs on a level (see :func:`_level_coding`)."""
    dtype = design["type"]
    alpha = axial_distances(design.get("alpha", 1.0), len(factors))
    z = model_units(table[factors].to_numpy(), factors, log_factors)
    if dtype == "custom":
        return Coding.from_levels(factors, z, alpha)
    levels = factor_levels(dtype, alpha, len(factors))
    centers, units = [], []
    for i, f in enumerate(factors):
        values, counts = np.unique(_round_to_scale(z[:, i], 11), return_counts=True)
        found = _level_coding(values, counts, levels[i]) if len(values) > 1 else None
        if found is None:
            raise InputError(f"the factor takes the single value {values[0]:g} in every run; a {dtype} design "
                             "varies each factor over at least two levels", source=src, column=f)
        centers.append(found[0])
        units.append(found[1])
    return Coding(tuple(factors), tuple(centers), tuple(units))


def _round_to_scale(x: np.ndarray, digits: int) -> np.ndarray:
    """x rounded to ``digits`` decimals below its largest magnitude's leading digit (12 decimals for values
    about 0.5 at digits 11): printed levels that differ only by round-off merge, whatever the factor's
    units (a Hamaker constant of 1e-20 J as much as a friction coefficient)."""
    scale = float(np.max(np.abs(x))) if x.size else 0.0
    if not np.isfinite(scale) or scale == 0.0:
        return x
    quantum = 10.0 ** (np.floor(np.log10(scale)) - digits)
    return np.round(x / quantum) * quantum


def _ccd_alpha_of_table(table: pd.DataFrame, factors: list[str], log_factors=()) -> float | None:
    """The axial distance the runs themselves show, when every factor has the five (or three) levels of
    a CCD, symmetric about the centre, with one ratio of axial to factorial half-range; else None."""
    z = model_units(table[factors].to_numpy(), factors, log_factors)
    ratios = []
    off_centre = np.zeros(z.shape, dtype=bool)
    for i in range(len(factors)):
        values = np.unique(_round_to_scale(z[:, i], 8))
        if len(values) not in (3, 5):
            return None
        spread = values[-1] - values[0]
        centre = values[len(values) // 2]
        if not spread > 0 or abs(values[0] + values[-1] - 2 * centre) > 1e-3 * spread:
            return None
        inner = values[3] - values[1] if len(values) == 5 else spread
        ratios.append(spread / inner)
        off_centre[:, i] = np.abs(z[:, i] - centre) > 1e-3 * spread
    if max(ratios) - min(ratios) > 1e-3 * max(ratios):
        return None
    # Three levels per factor without a run off the centre in one factor alone are a two-level factorial
    # with centre runs, not a face-centred CCD: no alpha would make them a CCD.
    if not np.any(off_centre.sum(axis=1) == 1):
        return None
    return float(np.mean(ratios))


def check_design(table: pd.DataFrame, factors: list[str], design: dict, src: str, config_key: str | None,
                 log_factors=(), level_tol: float = 0.02, counts: bool = True) -> tuple[Coding, np.ndarray]:
    """Check that factor values sit on the declared design's levels, every run is a point of the design
    and (``counts``) the point counts match.  ``config_key`` None: the design came from the command line."""
    args = (table, factors, design, src, config_key, log_factors, level_tol, counts)
    try:
        return _check_design(*args)
    except InputError as error:
        if design.get("inferred"):
            raise  # nothing was declared: the inferred design's own refusal is the line to show
        _refuse_wrong_scale(*args)
        shown = _ccd_alpha_of_table(table, factors, log_factors) if design["type"] == "ccd" else None
        declared = float(design.get("alpha", 1.0))
        # A wrong design.alpha puts every axial run off its level: name the key, not the first such cell.
        # Counts are not required of the probe: a wrong centre-run count is said once alpha is right.
        # Printed (rounded) levels blur the design's own value (1.41432 from 4 decimals, 1.42857 from 2):
        # the rotatable alpha is told when the runs sit on its levels too.
        if shown is not None:
            rotatable = round(rotatable_alpha(len(factors)), 5)
            shown = next((a for a in (rotatable, shown) if abs(a - shown) <= 0.05 * shown and _passes(
                table, factors, {**design, "alpha": a}, src, config_key, log_factors, level_tol, False)), None)
        if shown is None or abs(shown - declared) <= 1e-3 * shown:
            raise error
    geometry = ("the axial runs sit on the faces, at the factorial levels" if abs(shown - 1) < 1e-3 else
                f"in every factor the axial levels lie {shown:.6g} times as far from the centre as the factorial ones")
    key, fix = ((f"config key {config_key}.design.alpha", f"set design.alpha: {shown:.6g}") if config_key else
                ("--alpha", f"pass --alpha {shown:.6g}"))
    raise InputError(f"{key}: the runs form a CCD with alpha = {shown:.6g} ({geometry}), not the declared "
                     f"{declared:g}; {fix}", source=src)


def _refuse_wrong_scale(table, factors, design, src, config_key, log_factors, level_tol, counts) -> None:
    """A factor whose levels are evenly spaced on the other scale (log10 when declared linear, linear when
    declared log) puts its runs off every level: name its scale key, not the first such cell."""
    for f in factors:
        values = table[f].to_numpy(dtype=float)
        if f in log_factors:
            flipped, scale = tuple(g for g in log_factors if g != f), "linear"
        elif np.all(values > 0):
            flipped, scale = (*log_factors, f), "log"
        else:
            continue
        if _passes(table, factors, design, src, config_key, flipped, level_tol, False):
            where = f"config key {config_key}.factors.{f}.scale" if config_key else f"factor '{f}'"
            fix = (f"set scale: {scale}" if scale == "log" else "remove scale: log") if config_key else \
                "fit it in log10 units" if scale == "log" else "fit it in its own units"
            raise InputError(f"{where}: the levels of {f} are evenly spaced on a {scale} scale, not the declared "
                             f"{'log' if scale == 'linear' else 'linear'} one; {fix}", source=src)


def _said(design: dict) -> str:
    """How the design came to be checked against: declared (config, --design) or inferred from the table."""
    return "inferred" if design.get("inferred") else "declared"


def _level_tolerance(values: np.ndarray, unit: float, level_tol: float, log_scale: bool) -> float:
    """Coded distance within which a value of one factor reads as a level: ``level_tol`` of that factor's coded
    unit, or half the last printed digit of its column where printing rounded more than that (a CCD's axial
    level 0.851 printed as 0.85).  Log-scale factors keep ``level_tol``: their print is in other units."""
    if log_scale or not unit:
        return level_tol
    quantum = printed_quantum(values)
    return max(level_tol, 0.5 * float(np.max(quantum, initial=0.0)) / abs(unit))


def _passes(*args) -> bool:
    try:
        _check_design(*args)
    except InputError:
        return False
    return True


def _check_design(table: pd.DataFrame, factors: list[str], design: dict, src: str, config_key: str | None,
                  log_factors=(), level_tol: float = 0.02, counts: bool = True) -> tuple[Coding, np.ndarray]:
    dtype = design["type"]
    k = len(factors)
    alpha = axial_distances(design.get("alpha", 1.0), k)
    coding = infer_coding(table, factors, design, src, log_factors)
    z = model_units(table[factors].to_numpy(), factors, log_factors)
    coded = coding.to_coded(z)
    if dtype == "custom":
        return coding, np.array(["other"] * len(table))
    levels_of = factor_levels(dtype, alpha, k)
    for i, f in enumerate(factors):
        levels = levels_of[i]
        tolerance = _level_tolerance(table[f].to_numpy(dtype=float), coding.unit[i], level_tol, f in log_factors)
        for r, c in zip(table["run"], coded[:, i]):
            dist = np.abs(levels - c)
            if dist.min() > tolerance:
                nearest = levels[np.argmin(dist)]
                near_actual = coding.to_actual(np.where(np.arange(len(factors)) == i, nearest, 0.0))[i]
                if f in log_factors:
                    near_actual = 10 ** near_actual
                printed = table[f].to_numpy(dtype=float)[np.abs(coded[:, i] - nearest) <= level_tol]
                near_actual = printed[0] if printed.size else near_actual  # as the other runs print it
                found = table.loc[table["run"] == r, f].iloc[0]
                raise InputError(f"value {found:g} is not a level of the {_said(design)} {dtype} design "
                                 f"(coded {c:+.3f}); nearest valid level: {near_actual:.6g} (coded {nearest:+.4g})",
                                 source=src, run=int(r), column=f)
    snapped = snap_to_factor_levels(coded, levels_of)
    types = classify_points(snapped, alpha)
    _refuse_misplaced_points(table, factors, design, snapped, types, levels_of, coding, log_factors, src)
    if not counts:
        return coding, types
    if dtype == "ccd":
        expected = {"factorial": 2 ** k, "axial": 2 * k,
                    "center": int(design.get("center_runs", 0))}
        found = {t: int(np.sum(types == t)) for t in expected}
        if found["axial"] == 0:
            raise InputError(f"config key {config_key}.design: the table has no axial runs: its runs are a two-level "
                             f"factorial with {found['center']} centre run(s), on which the squared terms of the "
                             f"quadratic cannot be estimated; add the {2 * k} axial runs of a CCD, or run the 3^{k} "
                             f"factorial (design type factorial)", source=src)
        for t, n in expected.items():
            if found[t] > n and found[t] % n == 0 and t != "center":
                raise InputError(f"config key {config_key}.design: the table has {found[t]} {_POINT_WORDS[t]} runs "
                                 f"where a {k}-factor CCD has {n}: replicated points? A replicated design is not a "
                                 "plain ccd; declare design type custom to fit it as it is", source=src)
        _refuse_missing_or_repeated_points(table, factors, design, snapped, coding, log_factors, src)
        for t, n in expected.items():
            if found[t] != n:
                key, what = (("design.center_runs", "") if t == "center" else
                             ("design", f" with {_n_center_text(design)}"))
                raise InputError(f"config key {config_key}.{key}: expected {n} {_POINT_WORDS[t]} run(s) for a "
                                 f"{k}-factor CCD{what}, found {found[t]} ({len(table)} runs in the table)", source=src)
    elif dtype == "factorial":
        _refuse_incomplete_factorial(factors, snapped, config_key, src)
        n_center = int(np.sum(types == "center"))
        if n_center != int(design.get("center_runs", 0)):
            raise InputError(f"config key {config_key}.design.center_runs: expected "
                             f"{design.get('center_runs', 0)} centre runs, found {n_center}", source=src)
    elif dtype == "box_behnken":
        n_edge, n_center = int(np.sum(types == "edge")), int(np.sum(types == "center"))
        edges = _expected_counts(design, k)["edge"]
        if n_edge > edges and n_edge % edges == 0:
            raise InputError(f"config key {config_key}.design: the table has {n_edge} edge-midpoint runs where a "
                             f"{k}-factor Box-Behnken design has {edges}: replicated points? A replicated "
                             "design is not a plain box_behnken; declare design type custom to fit it as it is",
                             source=src)
        _refuse_missing_or_repeated_points(table, factors, design, snapped, coding, log_factors, src)
        if n_center != int(design.get("center_runs", 0)):
            raise InputError(f"config key {config_key}.design.center_runs: expected "
                             f"{design.get('center_runs', 0)} centre runs, found {n_center}", source=src)
    return coding, types


def _design_points(design: dict, k: int) -> np.ndarray:
    """The coded non-centre points of a CCD or Box-Behnken design, each once."""
    if design["type"] == "ccd":
        return ccd_points(k, axial_distances(design.get("alpha", 1.0), k), center_runs=0)
    return box_behnken_points(k, 0)


def _refuse_missing_or_repeated_points(table, factors, design, snapped, coding, log_factors, src,
                                       slips_only: bool = False) -> None:
    """Each factorial, axial or edge point of a CCD or Box-Behnken design is run once.  A run on another run's
    point with the design's point beside it empty is a factor value typed as another level (15 typed 5): the
    point counts still match, and the two runs would be fitted as replicates.  Name both runs, the empty point
    and, where one factor tells them apart, the column and the value that restores the design.  With
    ``slips_only`` (a table whose failed runs may be left out) only that slip is refused."""
    k = len(factors)
    key = [tuple(np.round(p, 6)) for p in snapped]
    expected = [tuple(np.round(p, 6)) for p in _design_points(design, k)]
    rows_at = {p: [i for i, q in enumerate(key) if q == p] for p in expected}
    missing = [p for p in expected if not rows_at[p]]
    repeated = [p for p in expected if len(rows_at[p]) > 1]
    if not missing and not repeated:
        return
    runs = table["run"].to_numpy()

    def shown(point) -> str:
        return ", ".join(f"{f} {_printed_level(table, f, j, snapped, point[j], coding, log_factors):.6g}"
                         for j, f in enumerate(factors))

    name = {"ccd": "CCD", "box_behnken": "Box-Behnken design"}[design["type"]]

    def runs_at(point) -> tuple[list[int], str]:
        at = [int(runs[i]) for i in rows_at[point]]
        return at, (f"{'both' if len(at) == 2 else f'all {len(at)}'} are the point ({shown(point)}), which a {name} "
                    "runs once")

    # A slip moves one run: each repeat (a pair) has an empty point beside it.  More repeats than empty points,
    # or a point run three times, is a replicated design, not a slip.
    slip_like = len(repeated) <= len(missing) and (len(repeated) == 1 or not slips_only)
    for point in repeated if slip_like else []:
        near = [p for p in missing if sum(a != b for a, b in zip(p, point)) == 1]
        if len(near) == 1 and len(rows_at[point]) == 2:
            j = next(j for j in range(k) if near[0][j] != point[j])
            value = _printed_level(table, factors[j], j, snapped, near[0][j], coding, log_factors)
            at, what = runs_at(point)
            raise InputError(f"{what}, and the design's point ({shown(near[0])}) has no run: in one of them "
                             f"{factors[j]} is likely {value:.6g}, typed as another level", source=src, run=at,
                             column=factors[j])
    if slips_only:
        return
    if repeated:
        at, what = runs_at(repeated[0])
        tail = (f"; the design's point ({shown(missing[0])})" + (f" and {len(missing) - 1} more" if len(missing) > 1
                else "") + " has no run" if missing else
                "; a replicated point makes it another design: declare design type custom to fit it as it is")
        raise InputError(f"{what}{tail}", source=src, run=at)
    more = f" and {len(missing) - 1} more" if len(missing) > 1 else ""
    raise InputError(f"the {name}'s point ({shown(missing[0])}){more} has no run ({len(table)} runs in the table); "
                     "keep a failed run in the table with status failed, or declare design type custom to fit the "
                     "runs as they are", source=src)


def factor_slip_warning(table: pd.DataFrame, factors: list[str], design: dict, coding: Coding, src: str,
                        log_factors=()) -> str | None:
    """Where runs may be left out of a table (the command line), two runs on one point beside an empty point
    are a factor value typed as another level — or a replicated point beside a run left out, which the table
    cannot tell apart: a warning, not an error."""
    if design["type"] not in _DESIGN_POINTS:
        return None
    levels = factor_levels(design["type"], design.get("alpha", 1.0), len(factors))
    coded = coding.to_coded(model_units(table[factors].to_numpy(dtype=float), factors, log_factors))
    snapped = snap_to_factor_levels(coded, levels)
    try:
        _refuse_missing_or_repeated_points(table, factors, design, snapped, coding, log_factors, src,
                                           slips_only=True)
    except InputError as slip:
        return f"{slip} (or a replicated point beside a run left out of the table)"
    return None


def _printed_level(table, f, j, snapped, level, coding, log_factors) -> float:
    """A coded level of factor ``f`` in its units, as the runs at that level print it."""
    printed = table[f].to_numpy(dtype=float)[np.isclose(snapped[:, j], level)]
    if printed.size:
        return float(printed[0])
    point = np.zeros(snapped.shape[1])
    point[j] = level
    value = coding.to_actual(point)[j]
    # the level an axial run alone holds, from an alpha printed to 5 decimals: 5 digits are all it knows
    return float(f"{10 ** value if f in log_factors else value:.5g}")


def _n_center_text(design: dict) -> str:
    n = int(design.get("center_runs", 0))
    return f"{n} centre run{'s' if n != 1 else ''}"


def _refuse_incomplete_factorial(factors: list[str], snapped: np.ndarray, config_key: str, src: str) -> None:
    """A 3^k factorial has every combination of the three levels.  Runs on a subset of them are another
    design: a Box-Behnken design (the edge midpoints) is named; a two-level factorial with centre runs is
    left to the rank check, which says why its squares cannot be fitted."""
    k = len(factors)
    present = {tuple(p) for p in np.round(snapped).astype(int).tolist() if any(p)}
    full = {p for p in product((-1, 0, 1), repeat=k) if any(p)}
    missing = sorted(full - present)
    if not missing or all(0 not in p for p in present):
        return
    edges = {p for p in full if sum(v != 0 for v in p) == 2}
    if present == edges:
        raise InputError(f"config key {config_key}.design.type: the runs are the edge midpoints of a Box-Behnken "
                         f"design (two factors at their extremes, the others at the centre), not the 3^{k} "
                         f"factorial; set design type: box_behnken", source=src)
    example = ", ".join(f"{f}={v:+d}" for f, v in zip(factors, missing[0]))
    raise InputError(f"config key {config_key}.design: a 3^{k} factorial has {len(full)} non-centre points, the "
                     f"table has {len(present)}; missing {len(missing)}, e.g. the point ({example}) in coded "
                     f"units. Keep a failed run in the table with status failed, or declare the design that was "
                     f"run (design type custom fits any runs)", source=src)


_DESIGN_POINTS = {"ccd": ("factorial", "axial", "center"), "box_behnken": ("edge", "center")}
_POINT_WORDS = {"factorial": "factorial", "axial": "axial", "center": "centre", "edge": "edge-midpoint"}


def _expected_counts(design: dict, k: int) -> dict[str, int]:
    centre = int(design.get("center_runs", 0))
    if design["type"] == "ccd":
        return {"factorial": 2 ** k, "axial": 2 * k, "center": centre}
    return {"edge": 2 * k * (k - 1), "center": centre}


def _refuse_misplaced_points(table, factors, design, snapped, types, levels, coding, log_factors, src) -> None:
    """A run whose factor levels make no point of the declared design (a centre run with one factor at a
    factorial level): one line naming the run and, where exactly one factor value would restore a point
    the design is short of, that column and value (another run's level typed by mistake)."""
    allowed = _DESIGN_POINTS.get(design["type"])
    if allowed is None:
        return
    bad = np.flatnonzero(~np.isin(types, allowed))
    if not len(bad):
        return
    i = int(bad[0])
    counts = {t: int(np.sum(types == t)) for t in allowed}
    short = {t for t, n in _expected_counts(design, len(factors)).items() if counts.get(t, 0) < n}
    alpha = axial_distances(design.get("alpha", 1.0), len(factors))
    repairs = []
    for j, f in enumerate(factors):
        for level in levels[j]:
            point = snapped[i].copy()
            point[j] = level
            kind = classify_points(point[None, :], alpha)[0]
            # a factorial, axial or edge point appears once in the design: one already present is no repair
            present = kind != "center" and np.any(np.all(np.isclose(np.delete(snapped, i, axis=0), point), axis=1))
            if level != snapped[i, j] and kind in short and not present:
                value = coding.to_actual(point)[j]
                repairs.append((f, 10 ** value if f in log_factors else value, kind))
    where = ", ".join(f"{f} {table[f].iloc[i]:g}" for f in factors)
    names = [_POINT_WORDS[t] for t in allowed]
    article = "an" if names[0][0] in "aeiou" else "a"
    what = (f"the point ({where}) is not {article} {', '.join(names[:-1])} or {names[-1]} point of the {_said(design)} "
            f"{design['type']} design")
    run = int(table["run"].iloc[i])
    if len(repairs) == 1:
        f, value, kind = repairs[0]
        raise InputError(f"{what}; with {f} = {value:.6g} it would be the {_POINT_WORDS[kind]} run the "
                         "design is short of (another run's level typed by mistake?)", source=src, run=run, column=f)
    raise InputError(what, source=src, run=run)


def _odd_level_values(table: pd.DataFrame, factors: list[str], snapped: np.ndarray, src: str) -> list[str]:
    """A factor value that differs from the value the other runs at its level have (0.5003 where four others
    read 0.5): close enough to be the level, so it is fitted as recorded, but likely a typo.  A level with one
    run (an axial point) has nothing to compare with."""
    out = []
    for j, f in enumerate(factors):
        values = table[f].to_numpy(dtype=float)
        for level in np.unique(snapped[:, j]):
            rows = np.flatnonzero(snapped[:, j] == level)
            distinct, counts = np.unique(values[rows], return_counts=True)
            if len(distinct) < 2 or counts.max() < 2 or (counts == counts.max()).sum() > 1:
                continue
            usual = distinct[np.argmax(counts)]
            for i in rows[values[rows] != usual]:
                out.append(f"{src}, run {int(table['run'].iloc[i])}, column '{f}': {values[i]:.10g}, where the other "
                           f"{int(counts.max())} runs at this level read {usual:.10g} (fitted as recorded; a typo?)")
    return out


def implausible_targets(table: pd.DataFrame, targets: dict) -> dict[str, dict]:
    """Targets farther outside every simulated value of their response than the simulated values spread
    (more than one range beyond the nearest run): per response ``lo``, ``hi`` (the simulated range) and,
    where a power of ten brings the target inside that range (a unit or typing slip: 1.505 g cm^-3 for
    1505 kg m^-3), ``factor`` and ``repaired``."""
    out = {}
    for response, target in targets.items():
        if response not in table:
            continue
        y = table[response].to_numpy(dtype=float)
        y = y[np.isfinite(y)]
        if not len(y):
            continue
        lo, hi = float(y.min()), float(y.max())
        if lo == hi or lo - (hi - lo) <= target <= hi + (hi - lo):
            continue
        found = {"lo": lo, "hi": hi, "factor": None, "repaired": None}
        for power in sorted((p for p in range(-6, 7) if p), key=abs):
            value = float(target) * 10.0 ** power
            if lo <= value <= hi:
                found.update(factor=10.0 ** power, repaired=value)
                break
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


def check_bounds(table: pd.DataFrame, factors_cfg: dict, src: str, rel_tol: float = 1e-6) -> None:
    for f, fc in factors_cfg.items():
        lo, hi = float(fc["lower"]), float(fc["upper"])
        slack = rel_tol * (hi - lo)
        bad = table[(table[f] < lo - slack) | (table[f] > hi + slack)]
        if len(bad):
            r = bad.iloc[0]
            raise InputError(f"value {r[f]:g} lies outside the declared bounds [{lo:g}, {hi:g}] "
                             f"(config factors.{f})", source=src, run=int(r["run"]), column=f)


#: The slips that move a bound or a target far (point, swap, sign): a bound rounded outwards is none of them.
_BOUND_SLIPS = ("decimal_shift", "transposition", "sign_lost")


def check_bound_slips(table: pd.DataFrame, material: str, factors_cfg: dict, src: str) -> None:
    """A search bound beyond the runs that a one-keystroke slip turns into the runs' own extreme value
    (upper 9.24264 where the largest run is 0.924264) is a typo, not a wider search: refuse it.  Only
    bounds beyond the runs by a tenth of their range are considered (a bound rounded outwards, 2.9289 for
    2.92893, is no slip), and only the slips that move a value far: point, swap, sign."""
    from .transcription.typos import SLIP_WORDS, single_cell_slips

    for f, fc in factors_cfg.items():
        values = table[f].to_numpy(dtype=float)
        margin = 0.1 * (values.max() - values.min())
        for side, bound, extreme in (("lower", fc["lower"], values.min()), ("upper", fc["upper"], values.max())):
            if (bound > extreme - margin) if side == "lower" else (bound < extreme + margin):
                continue
            for kind, _, value in single_cell_slips(repr(float(bound))):
                if kind in _BOUND_SLIPS and np.isclose(value, extreme, rtol=1e-6, atol=0.0):
                    raise InputError(f"config key materials.{material}.factors.{f}.{side}: {bound:g} lies beyond the "
                                     f"runs, whose {'smallest' if side == 'lower' else 'largest'} {f} is {extreme:g}, "
                                     f"and looks like {value:g} with {SLIP_WORDS[kind]}; fix the bound", source=src)


def require_estimable(coded: np.ndarray, usable: np.ndarray, point_types: np.ndarray | None, src: str,
                      column: str, factors: list[str] | None = None) -> None:
    """The full quadratic must be estimable, with residual degrees of freedom, from the usable runs.

    Runs that all lie on one sphere about the design centre (a spherical CCD whose centre runs
    failed or were never made) cannot tell the intercept from the squared terms; a fit would
    return arbitrary coefficients without complaint.
    """
    k = coded.shape[1]
    terms = quadratic_terms(k)
    x = coded[usable]
    n, p = len(x), len(terms)
    if n <= p:
        raise InputError(f"only {n} usable runs for a quadratic model with {p} coefficients; at least {p + 1} "
                         f"are needed (with {p} the fit is saturated and says nothing about its error)",
                         source=src, column=column)
    radius = np.sum(x ** 2, axis=1)
    # Printed (rounded) levels put a spherical design only *nearly* on its sphere: test the geometry,
    # not the numerical rank, or the fit returns arbitrary coefficients from the rounding noise.
    if np.ptp(radius) <= 0.01 * max(radius.max(), 1e-300):
        why = ("every usable run lies at the same distance from the design centre, so the intercept and the "
               "squared terms cannot be told apart")
        n_centre = int(np.sum(point_types == "center")) if point_types is not None else 0
        why += (f" (all {n_centre} centre run(s) failed); at least one centre run is needed" if n_centre
                else "; the design needs at least one centre run")
        raise InputError(f"the quadratic model cannot be estimated: {why}", source=src, column=column)
    if point_types is not None and np.any(point_types == "axial"):
        centre = point_types == "center"
        if centre.any() and not np.any(centre & usable):
            # Off the sphere the fit still runs, but its centre is extrapolated from runs at radius >= 1.
            raise InputError(f"the quadratic model cannot be trusted: all {int(centre.sum())} centre run(s) failed, "
                             "so its value at the design centre would be extrapolated from the factorial and axial "
                             "runs; at least one centre run is needed", source=src, column=column)
    matrix = model_matrix(x, terms)
    _, singular, vt = np.linalg.svd(matrix, full_matrices=False)  # n x n left vectors: 800 MB at 10,000 runs
    rank = int(np.sum(singular > 1e-8 * singular[0]))
    if rank < p:
        raise InputError(f"the quadratic model cannot be estimated (rank {rank} of {p} terms): "
                         f"{_confounded_terms(vt[rank:], terms, x, factors)}", source=src, column=column)


def _confounded_terms(null_space: np.ndarray, terms, coded: np.ndarray, factors: list[str] | None) -> str:
    """Which terms the runs cannot tell apart, and what design change would separate them."""
    factors = factors or [f"x{i + 1}" for i in range(coded.shape[1])]
    names = ["intercept" if sum(t) == 0 else term_name(t, factors) for t in terms]
    involved = [n for n, w in zip(names, np.abs(null_space).max(axis=0)) if w > 1e-6]
    few = [f for i, f in enumerate(factors) if len(np.unique(np.round(coded[:, i], 6))) < 3]
    listed = ", ".join(involved[:-1]) + f" and {involved[-1]}" if len(involved) > 1 else involved[0]
    text = f"the usable runs cannot tell {listed} apart"
    if few:
        return text + f" ({', '.join(few)} at fewer than three levels: a squared term needs three)"
    squares = [n for n in involved if n.endswith("^2")]
    if len(squares) > 1:
        return text + (" (every run away from the centre has its squared terms equal, as in a two-level factorial "
                       "with centre runs); axial runs (a CCD) or a three-level factorial separate them")
    return text


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


def validate_material(material: str, mat_cfg: dict, base_dir: Path | str = ".") -> ValidatedTable:
    """Read a material's table and run every transcription check; raises InputError."""
    src = str(Path(mat_cfg["data"]))
    path = Path(base_dir) / mat_cfg["data"]
    factors = list(mat_cfg["factors"])
    responses = list(mat_cfg["responses"])
    log_factors = as_spec(mat_cfg, material).log_factors
    table, warnings = read_table(path, factors, responses, mat_cfg.get("status_column", "status"))
    table = table[["run"] + factors + responses + ["status"] + [c for c in (BLOCK_COLUMN,) if c in table.columns]]
    for f in log_factors:
        bad = table[table[f] <= 0]
        if len(bad):
            raise InputError("a log-scale factor needs positive values", source=src,
                             run=int(bad["run"].iloc[0]), column=f)
    check_bounds(table, mat_cfg["factors"], src)
    check_bound_slips(table, material, mat_cfg["factors"], src)
    p = len(quadratic_terms(len(factors)))
    for r in responses:
        ok = np.isfinite(table[r].to_numpy())
        if ok.sum() <= p:
            raise InputError(f"only {int(ok.sum())} usable runs for a quadratic model with {p} coefficients; "
                             f"at least {p + 1} are needed", source=src, column=r)
    coding, types = check_design(table, factors, mat_cfg["design"], src, f"materials.{material}", log_factors)
    warnings.extend(_block_notes(table, factors, coding, log_factors, src))
    coded = coding.to_coded(model_units(table[factors].to_numpy(), factors, log_factors))
    levels = factor_levels(mat_cfg["design"]["type"], mat_cfg["design"].get("alpha", 1.0), len(factors))
    if len(levels[0]):
        snapped = snap_to_factor_levels(coded, levels)
        warnings.extend(_odd_level_values(table, factors, snapped, src))
    for r in responses:
        require_estimable(coded, np.isfinite(table[r].to_numpy()), types, src, r, factors)
    for r in responses:
        values = table[r].to_numpy(dtype=float)
        values = values[np.isfinite(values)]
        if len(values) and np.ptp(values) == 0:
            warnings.append(f"{src}, column '{r}': the same value ({values[0]:g}) in every run, so it cannot "
                            "identify any factor (a column filled in by mistake?)")
    targets = {r: float(c["target"]) for r, c in mat_cfg["responses"].items() if c.get("target") is not None}
    warnings.extend(far_target_warnings(table, targets, src, material))
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


def _shortest(value: float) -> str:
    return np.format_float_positional(float(value), trim="-")


def _repair_explains(flag: dict, share: float = 0.2) -> bool:
    """The repair removes most of the run's miss: a large slip, not a digit shuffle of a noisy value."""
    predicted = flag["predicted_from_other_runs"]
    return abs(flag["suggested"] - predicted) <= share * abs(flag["found"] - predicted)


def refuse_likely_typos(validated: ValidatedTable, material: str, mat_cfg: dict,
                        base_dir: Path | str = ".") -> list[dict]:
    """Stop on a response cell that is far off the other runs' fit *and* reads like a digit-level slip.

    A value the user has confirmed under ``confirmed_values`` passes; the confirmed flags are
    returned so they can still be shown.  Raises InputError naming the file, run and column.
    """
    from .transcription import likely_typos
    from .transcription.typos import SLIP_WORDS

    src = str(Path(mat_cfg["data"]))
    key = f"materials.{material}.confirmed_values"
    spec = as_spec(mat_cfg, material)
    runs = set(int(r) for r in validated.table["run"])
    for run, column in spec.confirmed_values:
        if column not in spec.response_names:
            raise InputError(f"config key {key}: '{column}' is not a response of this material "
                             f"(responses: {', '.join(spec.response_names)})", source=src)
        if run not in runs:
            raise InputError(f"config key {key}: run {run} is not in the table", source=src)
    confirmed = set(spec.confirmed_values)
    printed = read_printed(Path(base_dir) / mat_cfg["data"], validated.table)
    # Stopping a run needs stronger evidence than the report's warning (family-wise 1 %, not 5 %).
    # A dropped digit stops the run too (29.4 for 129.4); the report's screen keeps its three kinds.
    flags = likely_typos(validated, spec, printed, family_alpha=0.01,
                         kinds=("transposition", "decimal_shift", "sign_lost", "digit_dropped"))
    for flag in flags:
        run, column = int(flag["run"]), flag["column"]
        if (run, column) in confirmed or not _repair_explains(flag):
            continue
        found = printed.loc[validated.table["run"].to_numpy() == run, column].iloc[0]
        raise InputError(f"{found} looks like {_shortest(flag['suggested'])} "
                         f"with {SLIP_WORDS[flag['kind']]}; fix the cell{_other_repairs_text(flag)}, or confirm "
                         f"the value with confirmed_values: [{{run: {run}, column: {column}}}]",
                         source=src, run=run, column=column)
    return flags


def _other_repairs_text(flag: dict) -> str:
    """Other repairs that fit the other runs as well, so that a user does not type in a guess: 10.91154 reads
    as 109.1154 with the point shifted, but 100.91154 with a 0 dropped fits better."""
    from .transcription.typos import SLIP_WORDS

    others = flag.get("other_repairs", [])
    if not others:
        return ""
    named = [f"{_shortest(c['value'])} ({SLIP_WORDS[c['kind']]})" for c in others[:2]]
    shown = (", ".join(named) + f" and {len(others) - 2} more" if len(others) > 2 else " and ".join(named))
    return (f" after checking it against the source: {shown} {'fits' if len(others) == 1 else 'fit'} the other "
            f"runs as well (predicted {flag['predicted_from_other_runs']:.4g})")

"""Reading and validating a transcribed design table.

Every problem is reported as one ``InputError`` line naming the file, the run
and the column, saying what was found and what is expected.  The raw file is
only ever read.
"""

from __future__ import annotations

import csv
import difflib
import io
import math
import re
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd

from .design import Coding, classify_points, model_units, nominal_levels, quadratic_terms
from .errors import InputError

UNICODE_MINUS = "\u2212"
_DECIMAL_COMMA = re.compile(r"^[+-]?\d*,\d+$")
_FAILED = {"failed", "fail", "error", "crashed"}
_NONFINITE = {"nan", "inf", "+inf", "-inf", "infinity", "-infinity"}


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


def read_raw(path: Path | str) -> tuple[list[str], list[list[str]], str]:
    """Header and string cells; a UTF-8 BOM is dropped, delimiter sniffed from the header."""
    path = Path(path)
    if not path.is_file():
        raise InputError("data file does not exist", source=str(path))
    try:
        text = path.read_bytes().decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise InputError(f"not UTF-8 text (byte {exc.start}); save the table as UTF-8 CSV", source=str(path)) from None
    lines = [ln for ln in text.splitlines() if ln.strip() and not ln.lstrip().startswith("#")]
    if not lines:
        raise InputError("the file is empty", source=str(path))
    delim = _sniff_delimiter(lines[0])
    rows = list(csv.reader(io.StringIO("\n".join(lines)), delimiter=delim))
    header = [h.strip() for h in rows[0]]
    return header, rows[1:], delim


def parse_number(cell: str) -> float:
    """Parse one cell; Unicode minus is accepted.  Raises ValueError with a readable reason."""
    s = cell.strip().replace(UNICODE_MINUS, "-")
    if s == "":
        raise ValueError("empty cell")
    if _DECIMAL_COMMA.match(s):
        raise ValueError(f"found '{cell.strip()}', a decimal comma; expected a decimal point, e.g. "
                         f"'{s.replace(',', '.')}'")
    try:
        return float(s)
    except ValueError:
        raise ValueError(f"found '{cell.strip()}', expected a number") from None


def read_table(path: Path | str, factors: list[str], responses: list[str],
               status_column: str = "status") -> tuple[pd.DataFrame, list[str]]:
    """Parse a design table into floats.  Returns (table, warnings).

    Empty or non-finite response cells are allowed only for runs marked as
    failed in ``status_column`` (or written explicitly as NaN/inf): those
    responses become NaN and are excluded from the fit.
    """
    src = str(path)
    header, rows, _ = read_raw(path)
    needed = ["run"] + list(factors) + list(responses)
    for col in needed:
        if col not in header:
            close = difflib.get_close_matches(col, header, n=1, cutoff=0.6)
            hint = f"; found '{close[0]}' — misspelled?" if close else f"; columns found: {', '.join(header)}"
            raise InputError(f"missing column (expected columns: {', '.join(needed)}){hint}", source=src, column=col)
    dup_cols = {h for h in header if header.count(h) > 1}
    if dup_cols:
        raise InputError("column appears more than once", source=src, column=sorted(dup_cols)[0])
    idx = {h: i for i, h in enumerate(header)}
    has_status = status_column in idx
    warnings: list[str] = []
    records = []
    seen_runs: dict[int, int] = {}
    for line_no, row in enumerate(rows, start=2):
        if len(row) != len(header):
            raise InputError(f"line {line_no} has {len(row)} cells, the header has {len(header)}", source=src)
        run_cell = row[idx["run"]].strip()
        try:
            run_val = parse_number(run_cell)
        except ValueError as exc:
            raise InputError(f"line {line_no}: {exc}; expected an integer run number", source=src,
                             column="run") from None
        if not float(run_val).is_integer():
            raise InputError(f"line {line_no}: found '{run_cell}', expected an integer run number", source=src,
                             column="run")
        run = int(run_val)
        if run in seen_runs:
            raise InputError(f"duplicate run number (lines {seen_runs[run]} and {line_no})", source=src,
                             run=run, column="run")
        seen_runs[run] = line_no
        status = row[idx[status_column]].strip().lower() if has_status else ""
        failed = status in _FAILED
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
            if cell.lower() in _NONFINITE:
                rec[col] = np.nan
                warnings.append(f"{src}, run {run}, column '{col}': value '{cell}' treated as a failed simulation")
                continue
            try:
                rec[col] = parse_number(cell)
            except ValueError as exc:
                hint = (f"; if this simulation failed, add a '{status_column}' column with 'failed'"
                        if cell == "" else "")
                raise InputError(f"{exc}{hint}", source=src, run=run, column=col) from None
        if failed:
            warnings.append(f"{src}, run {run}: marked '{status}' in column '{status_column}'; its missing "
                            f"responses are excluded from the fits")
        rec["status"] = "failed" if failed else "ok"
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


def infer_coding(table: pd.DataFrame, factors: list[str], design: dict, src: str,
                 log_factors=()) -> Coding:
    """Centre = most frequent level, unit = half the distance between the two next most frequent."""
    dtype = design["type"]
    alpha = float(design.get("alpha", 1.0))
    z = model_units(table[factors].to_numpy(), factors, log_factors)
    if dtype == "custom":
        return Coding.from_levels(factors, z, alpha)
    centers, units = [], []
    for i, f in enumerate(factors):
        values, counts = np.unique(np.round(z[:, i], 12), return_counts=True)
        center = values[np.lexsort((values, -counts))[0]]
        count = dict(zip(values, counts))
        span = values.max() - values.min()
        # The +-1 levels: the pair symmetric about the centre that most runs sit on (a single
        # mistyped cell has no symmetric partner, so it cannot hijack the coding).
        best = None
        for lo in values[values < center]:
            for hi in values[values > center]:
                if abs((hi - center) - (center - lo)) <= 5e-3 * max(span, 1e-300):
                    key = (count[lo] + count[hi], -(hi - lo))
                    if best is None or key > best[0]:
                        best = (key, lo, hi)
        if best is None:
            raise InputError(f"cannot find design levels placed symmetrically about the centre value {center:g}",
                             source=src, column=f)
        centers.append(float(center))
        units.append(float((best[2] - best[1]) / 2.0))
    return Coding(tuple(factors), tuple(centers), tuple(units))


def check_design(table: pd.DataFrame, factors: list[str], design: dict, src: str, config_key: str,
                 log_factors=(), level_tol: float = 0.02) -> tuple[Coding, np.ndarray]:
    """Check that factor values sit on the declared design's levels and the point counts match."""
    dtype = design["type"]
    alpha = float(design.get("alpha", 1.0))
    coding = infer_coding(table, factors, design, src, log_factors)
    z = model_units(table[factors].to_numpy(), factors, log_factors)
    coded = coding.to_coded(z)
    if dtype == "custom":
        return coding, np.array(["other"] * len(table))
    levels = nominal_levels(dtype, alpha)
    for i, f in enumerate(factors):
        for r, c in zip(table["run"], coded[:, i]):
            dist = np.abs(levels - c)
            if dist.min() > level_tol:
                nearest = levels[np.argmin(dist)]
                near_actual = coding.to_actual(np.where(np.arange(len(factors)) == i, nearest, 0.0))[i]
                if f in log_factors:
                    near_actual = 10 ** near_actual
                found = table.loc[table["run"] == r, f].iloc[0]
                raise InputError(f"value {found:g} is not a level of the declared {dtype} design "
                                 f"(coded {c:+.3f}); nearest valid level: {near_actual:.6g} (coded {nearest:+.4g})",
                                 source=src, run=int(r), column=f)
    snapped = np.array([[levels[np.argmin(np.abs(levels - c))] for c in row] for row in coded])
    types = classify_points(snapped, alpha)
    k = len(factors)
    if dtype == "ccd":
        expected = {"factorial": 2 ** k, "axial": 2 * k,
                    "center": int(design.get("center_runs", 0))}
        found = {t: int(np.sum(types == t)) for t in expected}
        for t, n in expected.items():
            if found[t] != n:
                raise InputError(f"config key {config_key}.design: expected {n} {t} run(s) for a {k}-factor CCD "
                                 f"with {design.get('center_runs', 0)} centre runs, found {found[t]} "
                                 f"({len(table)} runs in the table)", source=src)
        bad = np.flatnonzero(~np.isin(types, ["factorial", "axial", "center"]))
        if len(bad):
            raise InputError("point is neither factorial, axial nor centre in the declared CCD", source=src,
                             run=int(table["run"].iloc[bad[0]]))
    elif dtype == "factorial":
        n_center = int(np.sum(types == "center"))
        if n_center != int(design.get("center_runs", 0)):
            raise InputError(f"config key {config_key}.design.center_runs: expected "
                             f"{design.get('center_runs', 0)} centre runs, found {n_center}", source=src)
    elif dtype == "box_behnken":
        n_center = int(np.sum(types == "center"))
        if n_center != int(design.get("center_runs", 0)):
            raise InputError(f"config key {config_key}.design.center_runs: expected "
                             f"{design.get('center_runs', 0)} centre runs, found {n_center}", source=src)
    return coding, types


def check_bounds(table: pd.DataFrame, factors_cfg: dict, src: str, rel_tol: float = 1e-6) -> None:
    for f, fc in factors_cfg.items():
        lo, hi = float(fc["lower"]), float(fc["upper"])
        slack = rel_tol * (hi - lo)
        bad = table[(table[f] < lo - slack) | (table[f] > hi + slack)]
        if len(bad):
            r = bad.iloc[0]
            raise InputError(f"value {r[f]:g} lies outside the declared bounds [{lo:g}, {hi:g}] "
                             f"(config factors.{f})", source=src, run=int(r["run"]), column=f)


def validate_material(material: str, mat_cfg: dict, base_dir: Path | str = ".") -> ValidatedTable:
    """Read a material's table and run every transcription check; raises InputError."""
    src = str(Path(mat_cfg["data"]))
    path = Path(base_dir) / mat_cfg["data"]
    factors = list(mat_cfg["factors"])
    responses = list(mat_cfg["responses"])
    log_factors = tuple(f for f, c in mat_cfg["factors"].items() if c.get("scale") == "log")
    table, warnings = read_table(path, factors, responses, mat_cfg.get("status_column", "status"))
    table = table[["run"] + factors + responses + ["status"]]
    for f in log_factors:
        bad = table[table[f] <= 0]
        if len(bad):
            raise InputError("a log-scale factor needs positive values", source=src,
                             run=int(bad["run"].iloc[0]), column=f)
    check_bounds(table, mat_cfg["factors"], src)
    p = len(quadratic_terms(len(factors)))
    for r in responses:
        ok = np.isfinite(table[r].to_numpy())
        if ok.sum() <= p:
            raise InputError(f"only {int(ok.sum())} usable runs for a quadratic model with {p} coefficients; "
                             f"at least {p + 1} are needed", source=src, column=r)
    coding, types = check_design(table, factors, mat_cfg["design"], src, f"materials.{material}", log_factors)
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


_SLIP_WORDING = {
    "decimal_shift": "with the decimal point shifted",
    "transposition": "with two adjacent digits swapped",
    "sign_lost": "with its sign lost",
}


def _shortest(value: float) -> str:
    return np.format_float_positional(float(value), trim="-")


def refuse_likely_typos(validated: ValidatedTable, material: str, mat_cfg: dict,
                        base_dir: Path | str = ".") -> list[dict]:
    """Stop on a response cell that is far off the other runs' fit *and* reads like a digit-level slip.

    A value the user has confirmed under ``confirmed_values`` passes; the confirmed flags are
    returned so they can still be shown.  Raises InputError naming the file, run and column.
    """
    from .transcription import likely_typos

    src = str(Path(mat_cfg["data"]))
    key = f"materials.{material}.confirmed_values"
    confirmed = set()
    runs = set(int(r) for r in validated.table["run"])
    for item in mat_cfg.get("confirmed_values") or []:
        if item["column"] not in mat_cfg["responses"]:
            raise InputError(f"config key {key}: '{item['column']}' is not a response of this material "
                             f"(responses: {', '.join(mat_cfg['responses'])})", source=src)
        if int(item["run"]) not in runs:
            raise InputError(f"config key {key}: run {item['run']} is not in the table", source=src)
        confirmed.add((int(item["run"]), item["column"]))
    printed = read_printed(Path(base_dir) / mat_cfg["data"], validated.table)
    flags = likely_typos(validated, mat_cfg, printed)
    for flag in flags:
        run, column = int(flag["run"]), flag["column"]
        if (run, column) in confirmed:
            continue
        found = printed.loc[validated.table["run"].to_numpy() == run, column].iloc[0]
        raise InputError(f"{found} looks like {_shortest(flag['suggested'])} "
                         f"{_SLIP_WORDING.get(flag['kind'], 'mistyped')}; fix the cell, or confirm the value "
                         f"with confirmed_values: [{{run: {run}, column: {column}}}]",
                         source=src, run=run, column=column)
    return flags

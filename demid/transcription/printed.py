"""Printed values: how a source's numbers were printed, what interval each stands for,
and the published statistics of a material read into that form (see the package docstring,
"Agreement rule").
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from decimal import Decimal, InvalidOperation
from itertools import product
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from ..design import parse_term, term_name
from ..errors import InputError
from ..formulas import f_tail
from ..published_values import out_of_range

if TYPE_CHECKING:
    from ..design import Term


STATISTICS = ("r2", "adj_r2", "rmse", "resid_std", "q2", "lof_f", "lof_p",
              "ss_model", "ss_residual", "ss_lof", "ss_pure_error", "ss_total")


_MISFIT_CAP = 1e6  # distance charged for a statistic that cannot be reproduced (NaN)

#: Published statistics with a bounded range: (lowest, highest, name).  R² of a least-squares fit with an
#: intercept and a p-value lie in [0, 1]; adjusted R² and Q² can be negative but never exceed 1.
_PUBLISHED_RANGES = {"r2": (0.0, 1.0, "R²"), "adj_r2": (-np.inf, 1.0, "adjusted R²"), "q2": (-np.inf, 1.0, "Q²"),
                     "lof_p": (0.0, 1.0, "lack-of-fit p-value"),
                     **{stat: (0.0, np.inf, name) for stat, name in (
                         ("rmse", "RMSE"), ("resid_std", "residual standard deviation"), ("lof_f", "lack-of-fit F"),
                         ("ss_model", "model sum of squares"), ("ss_residual", "residual sum of squares"),
                         ("ss_lof", "lack-of-fit sum of squares"), ("ss_pure_error", "pure-error sum of squares"),
                         ("ss_total", "total sum of squares"))}}


# --------------------------------------------------------------------------- printed values
@dataclass(frozen=True)
class PrintedValue:
    """A published number as printed: value, decimals and relation (``=``, ``<`` or ``>``)."""

    text: str
    value: float
    decimals: int
    relation: str = "="

    @property
    def half_width(self) -> float:
        return 0.5 * 10.0 ** (-self.decimals)

    def agrees(self, reproduced) -> np.ndarray:
        x = np.asarray(reproduced, dtype=float)
        slack = self.half_width * 1e-6
        with np.errstate(invalid="ignore"):
            if self.relation == "<":
                ok = x <= self.value + slack
            elif self.relation == ">":
                ok = x >= self.value - slack
            else:
                ok = np.abs(x - self.value) <= self.half_width + slack
        return ok & np.isfinite(x)

    def misfit(self, reproduced) -> np.ndarray:
        """Distance from the printed value in units of the rounding half-width (0 when agreeing)."""
        x = np.asarray(reproduced, dtype=float)
        with np.errstate(invalid="ignore"):
            if self.relation == "<":
                gap = np.maximum(x - self.value, 0.0)
            elif self.relation == ">":
                gap = np.maximum(self.value - x, 0.0)
            else:
                gap = np.abs(x - self.value)
        out = np.minimum(gap / self.half_width, _MISFIT_CAP)
        return np.where(np.isfinite(out), out, _MISFIT_CAP)


def _decimals_of(text: str) -> int:
    exponent = Decimal(text).as_tuple().exponent
    return -int(exponent)


def parse_printed(value, decimals: int | None = None, *, where: str = "published") -> PrintedValue:
    """Read a published number and the decimals it was printed with.

    Strings keep trailing zeros (``"0.970"`` has 3 decimals) and may be a bound
    (``"<0.0001"``) or a percentage (``"98.27%"`` is 0.9827 with 4 decimals).
    Floats, e.g. from YAML, give their decimals by ``repr`` (0.97 -> 2), which
    loses trailing zeros: pass a string or ``decimals`` to keep them.
    Raises :class:`InputError` for anything that is not a number.
    """
    if isinstance(value, dict):
        if "value" not in value:
            raise InputError("expected a number or {value: ..., decimals: ...}", source=where)
        return parse_printed(value["value"], value.get("decimals", decimals), where=where)
    if isinstance(value, bool) or value is None:
        raise InputError(f"expected a number, got {value!r}", source=where)
    if isinstance(value, (int, np.integer)):
        text = str(int(value))
    elif isinstance(value, (float, np.floating)):
        if not math.isfinite(value):
            raise InputError(f"expected a finite number, got {value!r}", source=where)
        text = repr(float(value))
        if "e" in text or "E" in text:
            text = np.format_float_positional(float(value), trim="-")
    elif isinstance(value, str):
        text = value.strip()
    else:
        raise InputError(f"expected a number, got {value!r}", source=where)
    relation = "="
    body = text.replace(" ", "").replace("\u2212", "-")  # a typeset minus, as the schema and the tables allow
    for prefix, rel in (("<=", "<"), (">=", ">"), ("≤", "<"), ("≥", ">"), ("<", "<"), (">", ">")):
        if body.startswith(prefix):
            relation, body = rel, body[len(prefix):]
            break
    percent = body.endswith("%")
    if percent:
        body = body[:-1]
    try:
        number = Decimal(body)
    except InvalidOperation:
        raise InputError(f"cannot read {value!r} as a number", source=where) from None
    if not number.is_finite():
        raise InputError(f"expected a finite number, got {value!r}", source=where)
    inferred = _decimals_of(body)
    if percent:
        number, inferred = number.scaleb(-2), inferred + 2
    if decimals is not None:
        if isinstance(decimals, bool) or not isinstance(decimals, (int, np.integer)):
            raise InputError(f"decimals must be an integer, got {decimals!r}", source=where)
        inferred = int(decimals)
    return PrintedValue(text=text, value=float(number), decimals=inferred, relation=relation)


def _coefficient_key(units: str, name: str) -> str:
    return f"coef_{units}[{name}]"


def _parse_published(published: dict, decimals: dict | None, factors: list[str], terms: list[Term],
                     source: str) -> tuple[dict[str, PrintedValue], dict[str, tuple[str, int]]]:
    """Flatten ``published`` into {statistic: PrintedValue}; coefficients map to (units, term index)."""
    if not isinstance(published, dict):  # an empty mapping is refused below, with no statistic parsed
        raise InputError("no published statistics given", source=source)
    decimals = dict(decimals or {})
    inline = published.get("decimals")
    if inline is not None:
        if not isinstance(inline, dict):
            raise InputError("'decimals' must map statistic names to integers", source=source)
        decimals = {**inline, **decimals}
    targets: dict[str, PrintedValue] = {}
    coefficients: dict[str, tuple[str, int]] = {}
    for name, value in published.items():
        if name == "decimals":
            continue
        if name == "coefficients":
            if not isinstance(value, dict) or "values" not in value:
                raise InputError("coefficients need {units: coded|actual, values: {term: value}}", source=source)
            units = value.get("units", "coded")
            if units not in ("coded", "actual"):
                raise InputError(f"coefficient units must be 'coded' or 'actual', not {units!r}", source=source)
            coef_decimals = decimals.get("coefficients")
            for term, number in dict(value["values"]).items():
                try:
                    index = terms.index(parse_term(str(term), factors))
                except ValueError:
                    raise InputError(f"coefficient '{term}' is not a term of the quadratic model in "
                                     f"{', '.join(factors)}", source=source) from None
                key = _coefficient_key(units, term_name(terms[index], factors))
                digits = coef_decimals.get(term) if isinstance(coef_decimals, dict) else coef_decimals
                digits = decimals.get(key, digits)
                targets[key] = parse_printed(number, digits, where=f"{source}, coefficient '{term}'")
                coefficients[key] = (units, index)
            continue
        if name not in STATISTICS:
            raise InputError(f"unknown statistic '{name}' (expected one of {', '.join(STATISTICS)}, "
                             "coefficients)", source=source)
        targets[name] = parse_printed(value, decimals.get(name), where=f"{source}, '{name}'")
    if not targets:
        raise InputError("no published statistics given", source=source)
    return targets, coefficients


# --------------------------------------------------------------------------- single-cell slips
def positional(value: float) -> str:
    """A number as Python prints it, without an exponent (1e-05 reads 0.00001)."""
    text = repr(float(value))
    return np.format_float_positional(float(value), trim="-") if ("e" in text or "E" in text) else text


def _printed_column(values: np.ndarray) -> list[str | None]:
    """Reconstruct a numeric column's printed form: every cell with the column's largest decimals."""
    texts = [positional(v) if np.isfinite(v) else None for v in values]
    places = max((len(t.partition(".")[2]) for t in texts if t is not None), default=0)
    return [None if t is None else f"{float(v):.{places}f}" for t, v in zip(texts, values)]


def _precision(text: str) -> int:
    """Decimals the number needs (trailing zeros dropped): '0.2000' -> 1, '0.0757' -> 4."""
    if "e" in text.lower():
        text = format(Decimal(text), "f")
    return len(text.partition(".")[2].rstrip("0"))


def _irregularity(found_text: str, suggested_text: str, column_precision: int) -> int:
    """-1 when a repair brings a cell printed with more decimals than its column back in line,
    +1 when the repair needs more decimals than the column shows, else 0."""
    if _precision(suggested_text) > column_precision:
        return 1
    return -1 if _precision(found_text) > column_precision else 0


def _precision_elsewhere(texts: list[str | None]) -> np.ndarray:
    """Per cell: the largest precision among the column's *other* cells (how the column is printed)."""
    prec = np.array([_precision(t) if t is not None else -1 for t in texts])
    if prec.size < 2:
        return np.maximum(prec, 0)
    top = np.sort(prec)[::-1]
    out = np.where(prec == top[0], top[1], top[0])
    return np.maximum(out, 0)


def _jsonable(value):
    if isinstance(value, (np.integer,)):
        return int(value)
    if isinstance(value, (float, np.floating)):
        return float(value) if math.isfinite(value) else None
    return value


# A statistic the source computed from numbers it printed rounded: (statistic, printed inputs,
# value from the inputs and the table's degrees of freedom, how the inputs are read).  "interval": any
# value of the inputs within their rounding (F, p and R² from sums a source rounded less than it printed:
# Montgomery's p = 0.2897); each function is monotonic in every input, so the range is spanned by the
# corners.  "as printed": the printed inputs themselves (adjusted R², residual SD, RMSE): over the
# rounding interval of the sums, a root or an n-1/n-p scaling spans ten times their printed precision
# and would excuse a real slip in a table cell.
def _f_ratio(ss_a, ss_b, df_a, df_b):
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where((df_a > 0) & (df_b > 0) & (ss_b > 0), (ss_a / df_a) / (ss_b / df_b), np.nan)


def _adjusted_r2(ss_residual, ss_total, v):
    df, n = v["_df_model_resid"], v["_n"]
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where((df > 0) & (n > 1) & (ss_total > 0), 1.0 - (ss_residual / df) / (ss_total / (n - 1)), np.nan)


def _root_mean_square(ss_residual, df):
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where((df > 0) & (ss_residual >= 0), np.sqrt(np.maximum(ss_residual, 0.0) / df), np.nan)


_FROM_PRINTED = (
    ("lof_f", ("ss_lof", "ss_pure_error"), lambda a, b, v: _f_ratio(a, b, v["_df_lof"], v["_df_pe"]), "interval"),
    ("lof_p", ("lof_f",), lambda f, v: f_tail(f, v["_df_lof"], v["_df_pe"]), "interval"),
    ("lof_p", ("ss_lof", "ss_pure_error"),
     lambda a, b, v: f_tail(_f_ratio(a, b, v["_df_lof"], v["_df_pe"]), v["_df_lof"], v["_df_pe"]), "interval"),
    ("r2", ("ss_model", "ss_total"), lambda a, b, v: np.full(np.shape(v["_df_pe"]), a / b if b > 0 else np.nan),
     "interval"),
    ("r2", ("ss_residual", "ss_total"),
     lambda a, b, v: np.full(np.shape(v["_df_pe"]), 1.0 - a / b if b > 0 else np.nan), "interval"),
    ("adj_r2", ("ss_residual", "ss_total"), _adjusted_r2, "as printed"),
    ("adj_r2", ("ss_model", "ss_total"), lambda a, b, v: _adjusted_r2(b - a, b, v), "as printed"),
    ("resid_std", ("ss_residual",), lambda a, v: _root_mean_square(a, v["_df_model_resid"]), "as printed"),
    ("rmse", ("ss_residual",), lambda a, v: _root_mean_square(a, v["_n"]), "as printed"),
)


def _agreement(targets: dict[str, PrintedValue], values: dict[str, np.ndarray]) -> tuple[dict, set]:
    """Per statistic, per hypothesis: does the printed value agree?  A statistic agrees when the refit
    rounds to it, or when it is what the source's own printed, rounded inputs give (any value of the
    inputs within their rounding) and those inputs agree with the refit.  Returns (agrees, names
    that agree only through their printed inputs, for any hypothesis)."""
    agrees = {name: np.atleast_1d(targets[name].agrees(values[name])) for name in targets}
    via_inputs: set[str] = set()
    for name, inputs, function, reading in _FROM_PRINTED:
        if name not in targets or targets[name].relation != "=" or any(
                i not in targets or targets[i].relation != "=" for i in inputs):
            continue
        inputs_ok = np.logical_and.reduce([agrees[i] for i in inputs])
        widths = [targets[i].half_width if reading == "interval" else 0.0 for i in inputs]
        corners = np.array([function(*[targets[i].value + sign * w for i, sign, w in zip(inputs, signs, widths)],
                                     values)
                            for signs in product((-1.0, 1.0), repeat=len(inputs))], dtype=float)
        lo = np.min(np.where(np.isnan(corners), np.inf, corners), axis=0)
        hi = np.max(np.where(np.isnan(corners), -np.inf, corners), axis=0)
        target = targets[name]
        slack = target.half_width * (1 + 1e-6)
        consistent = (target.value + slack >= lo) & (target.value - slack <= hi)
        extra = inputs_ok & consistent & ~agrees[name]
        if np.any(extra):
            via_inputs.add(name)
        agrees[name] = agrees[name] | extra
    return agrees, via_inputs


def _format(value: float) -> str:
    return "NaN" if not np.isfinite(value) else f"{value:.6g}"


def _cell_texts(table: pd.DataFrame, printed: pd.DataFrame | None, columns: list[str],
                source: str) -> dict[str, list[str | None]]:
    """Printed form of every cell: from ``printed`` when given, else reconstructed per column."""
    out = {}
    for name in columns:
        values = pd.to_numeric(table[name], errors="coerce").to_numpy(dtype=float)
        if printed is not None:
            if name not in printed.columns or len(printed) != len(table):
                raise InputError(f"printed table does not match the table in column '{name}'", source=source)
            texts = []
            for cell, value in zip(printed[name].tolist(), values):
                text = None if cell is None or (isinstance(cell, float) and np.isnan(cell)) else str(cell).strip()
                texts.append(text if text and np.isfinite(value) else None)
            out[name] = texts
        else:
            out[name] = _printed_column(values)
    return out


def impossible_published(stat: str, raw, *, where: str) -> str:
    """Why a published statistic cannot be what the source printed ("" when it can): a value outside its
    range (an R² of 95.5, often a percentage).  Read as the transcription check reads it ("98.9%" is 0.989,
    "<0.0001" its bound); unreadable values raise :class:`InputError` naming ``where``."""
    if stat not in STATISTICS:
        return ""  # coefficients and decimals are read with the coefficients
    value = parse_printed(raw, where=where).value
    low, high, name = _PUBLISHED_RANGES.get(stat, (-np.inf, np.inf, stat))
    return out_of_range(raw, value, low, high, name)

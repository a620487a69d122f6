"""Transcription check: hold a hand-typed table against the statistics its source published.

A source usually publishes more than its design table: R², RMSE or the residual
standard deviation, an ANOVA with lack of fit and pure error, sometimes the
fitted equation.  :func:`check_transcription` refits the full quadratic model
(in coded units, exactly as :func:`demid.surrogate.fit_response` does) and asks
whether every refit statistic *rounds to the printed value*.  When some do not,
it searches every single-cell slip a typist makes -- a digit substituted, two
adjacent digits transposed, the decimal point shifted, a sign lost, a digit
dropped or doubled -- in every response cell and every factor cell, and ranks
the repairs by how many published statistics they restore.

Statistics (all as defined in :mod:`demid.surrogate`): ``r2``, ``adj_r2``,
``rmse`` = sqrt(SSE/n), ``resid_std`` = sqrt(SSE/(n-p)), ``q2`` = 1 - PRESS/SST,
``lof_f``, ``lof_p`` (lack of fit against pure error from replicated points;
NaN without replicates), ``ss_model``, ``ss_residual``, ``ss_lof``,
``ss_pure_error``, ``ss_total`` and the model ``coefficients`` in coded or
actual units.

Agreement rule.  A value printed with ``d`` decimals stands for the interval
``[v - h, v + h]`` with ``h = 0.5 * 10**-d``; the refit agrees when it lies in
that closed interval (widened by one part in a million of ``h`` for
floating-point noise).  Both ends are included, so a source that rounds half
up, half down or half to even is accepted alike.  A printed bound such as
``"< 0.0001"`` agrees when the refit satisfies it.

Ranking of repairs.  By the number of published statistics the repaired table
reproduces (``restores``, more first); then by how the repair fits the way the
column is printed (a repair of a cell that stands out -- more decimals than the
rest of its column, or a factor value off every design level -- first; a repair
that needs more decimals than the column shows last); then by the summed
distance of the repaired statistics from the printed values, each in units of
its rounding half-width ``h`` (closer first); then by the kind of slip (sign
lost, decimal shift, transposition, doubled, dropped, substituted digit: the
order of :data:`KINDS`); then by table row and column order.  All repairs that
restore every statistic are reported (at most ``max_suspects``); when none
does, the verdict says so plainly and the best partial repairs (restoring more
statistics than the table as found) are listed as leads.

Candidates.  Each cell's printed string (``printed``, or reconstructed from the
number with the column's largest number of decimals) is edited by every slip
of every kind; a repair that gives the same number under several kinds is kept
under the first kind in :data:`KINDS`.  A factor repair must land on a level of
the declared design: a level another cell of the column prints exactly as
printed there, a level no other cell shows (an axial point) within the
column's printing precision.  The declared coding is the one that puts the most
cells on the design's nominal levels, so a mistyped extreme does not move the
levels; pass ``coding`` to fix it instead.  Repaired tables are coded with
``Coding.from_levels`` as :func:`~demid.surrogate.fit_response` would code them.

Speed.  A response cell enters the fit linearly, so every response hypothesis
is one column of a matrix ``Y`` and all are evaluated at once from the
pseudo-inverse, the hat matrix and the replicate-group projection of the
table's design.  A factor cell changes the design; the repairs that land on a
design level are refitted together in one batched SVD.  A 20-run, 3-factor
table (about 2,000 response and 140 factor hypotheses) takes a few hundredths
of a second.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from decimal import Decimal, InvalidOperation
from itertools import combinations, product

import numpy as np
import pandas as pd
from scipy import stats

from .design import Coding, Term, model_matrix, nominal_levels, parse_term, quadratic_terms, replicate_groups, term_name
from .errors import InputError

STATISTICS = ("r2", "adj_r2", "rmse", "resid_std", "q2", "lof_f", "lof_p",
              "ss_model", "ss_residual", "ss_lof", "ss_pure_error", "ss_total")

# Priority order (fewer keystrokes first); also the tie-break among equal repairs.
KINDS = ("sign_lost", "decimal_shift", "transposition", "digit_doubled", "digit_dropped", "digit_substitution")
_KIND_RANK = {kind: i for i, kind in enumerate(KINDS)}

_MISFIT_CAP = 1e6  # distance charged for a statistic that cannot be reproduced (NaN)
_ALPHA_SLACK = 3e-4  # coded units: a table printed from alpha = 1.41421 against a declared 1.414
_ALL_DIGITS = "0123456789"


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
    body = text.replace(" ", "")
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
    if not isinstance(published, dict) or not published:
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
def _positional(value: float) -> str:
    text = repr(float(value))
    return np.format_float_positional(float(value), trim="-") if ("e" in text or "E" in text) else text


def _printed_column(values: np.ndarray) -> list[str | None]:
    """Reconstruct a numeric column's printed form: every cell with the column's largest decimals."""
    texts = [_positional(v) if np.isfinite(v) else None for v in values]
    places = max((len(t.partition(".")[2]) for t in texts if t is not None), default=0)
    return [None if t is None else f"{float(v):.{places}f}" for t, v in zip(texts, values)]


def single_cell_slips(text: str) -> list[tuple[str, str, float]]:
    """All repairs ``(kind, suggested_text, suggested_value)`` of a cell printed as ``text``.

    ``kind`` names the slip that would turn the suggestion into ``text``:
    ``digit_dropped`` inserts a digit, ``digit_doubled`` removes one of two equal
    neighbours, ``sign_lost`` restores a lost minus (or removes a stray one),
    ``decimal_shift`` moves the point by 1 or 2 places.  Repairs that give the
    same number are kept once, under the kind listed first in :data:`KINDS`.
    """
    raw = text.strip()
    try:
        found = Decimal(raw)
    except InvalidOperation:
        return []
    if not found.is_finite():
        return []
    if "e" in raw.lower():
        raw = format(found, "f")
    sign, body = ("-", raw[1:]) if raw.startswith("-") else ("", raw.lstrip("+"))
    out: list[tuple[str, str]] = []
    digit_at = [ch.isdigit() for ch in body]
    for i, ch in enumerate(body):
        if digit_at[i]:
            out += [("digit_substitution", sign + body[:i] + d + body[i + 1:]) for d in _ALL_DIGITS if d != ch]
    for i in range(len(body) - 1):
        if not (digit_at[i] and digit_at[i + 1]):
            continue
        if body[i] != body[i + 1]:
            out.append(("transposition", sign + body[:i] + body[i + 1] + body[i] + body[i + 2:]))
        else:
            out.append(("digit_doubled", sign + body[:i] + body[i + 1:]))
    for shift in (-2, -1, 1, 2):
        out.append(("decimal_shift", format(found.scaleb(shift), "f")))
    if found != 0:
        out.append(("sign_lost", body if sign else "-" + body))
    for i in range(len(body) + 1):
        out += [("digit_dropped", sign + body[:i] + d + body[i:]) for d in _ALL_DIGITS]
    best: dict[float, tuple[str, str]] = {}
    found_value = float(found)
    for kind, candidate in out:
        try:
            number = Decimal(candidate)
        except InvalidOperation:
            continue
        value = float(number)
        if value == found_value or not math.isfinite(value):
            continue
        if value not in best or _KIND_RANK[kind] < _KIND_RANK[best[value][0]]:
            best[value] = (kind, candidate)
    return [(kind, candidate, value) for value, (kind, candidate) in best.items()]


# --------------------------------------------------------------------------- fitting engine
def _coded_to_actual_matrix(coding: Coding, terms: list[Term]) -> np.ndarray:
    """beta_actual = M @ beta_coded; same construction as SurrogateFit._coded_to_actual_matrix."""
    k = len(coding.factors)
    degree = max(max(t) for t in terms) if terms else 0
    levels = np.linspace(-1, 1, degree + 1)
    pts = np.array(np.meshgrid(*[levels] * k, indexing="ij")).reshape(k, -1).T
    return np.linalg.lstsq(model_matrix(coding.to_actual(pts), terms), model_matrix(pts, terms), rcond=None)[0]


def _lack_of_fit_p(out: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
    lof_f = np.asarray(out["lof_f"], dtype=float)
    lof_p = np.full(lof_f.shape, np.nan)
    ok = np.isfinite(lof_f)
    if ok.any():
        lof_p[ok] = stats.f.sf(lof_f[ok], out["_df_lof"][ok], out["_df_pe"][ok])
    out["lof_p"] = lof_p
    return out


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


def _statistics(sse, sst, press, ss_pe, n, p, rank, df_pe) -> dict[str, np.ndarray]:
    """The published statistics from the sums of squares; arrays over hypotheses, definitions as in
    :meth:`demid.surrogate.SurrogateFit.statistics` and :meth:`~demid.surrogate.SurrogateFit.anova`."""
    sse, sst, press, ss_pe = np.broadcast_arrays(*(np.asarray(a, dtype=float) for a in (sse, sst, press, ss_pe)))
    n = np.broadcast_to(n, sse.shape)
    df_res = n - np.broadcast_to(rank, sse.shape)
    df_pe = np.broadcast_to(df_pe, sse.shape)
    df_lof = df_res - df_pe
    with np.errstate(divide="ignore", invalid="ignore"):
        sst_ok = sst > 0
        has_df = n > p
        return {
            "r2": np.where(sst_ok, 1.0 - sse / sst, np.nan),
            "adj_r2": np.where(sst_ok & has_df, 1.0 - (sse / (n - p)) / (sst / (n - 1)), np.nan),
            "rmse": np.sqrt(sse / n),
            "resid_std": np.where(has_df, np.sqrt(sse / (n - p)), np.nan),
            "q2": np.where(sst_ok, 1.0 - press / sst, np.nan),
            "ss_model": sst - sse, "ss_residual": sse, "ss_lof": sse - ss_pe,
            "ss_pure_error": ss_pe, "ss_total": sst,
            "lof_f": np.where((df_lof > 0) & (df_pe > 0) & (ss_pe > 0),
                              ((sse - ss_pe) / df_lof) / (ss_pe / df_pe), np.nan),
            # lof_p is filled in by _lack_of_fit_p, in one vectorised call over all hypotheses.
            "_df_lof": df_lof.astype(float), "_df_pe": df_pe.astype(float),
        }


def _add_coefficients(out: dict, beta: np.ndarray, to_actual: list | np.ndarray | None,
                      coefficients: dict[str, tuple[str, int]]) -> dict:
    """beta: (p, m) coded coefficients; to_actual: (p, p) map or one per hypothesis."""
    if not coefficients:
        return out
    actual = None
    if any(units == "actual" for units, _ in coefficients.values()):
        if isinstance(to_actual, np.ndarray):
            actual = to_actual @ beta
        else:
            actual = np.stack([m @ beta[:, i] for i, m in enumerate(to_actual)], axis=1)
    for key, (units, index) in coefficients.items():
        out[key] = (beta if units == "coded" else actual)[index]
    return out


class _DesignFit:
    """One design (factor settings) and everything the statistics need about it.

    ``evaluate(Y)`` returns the statistics for every column of ``Y`` (responses
    on this design) at once: the fit is linear in y, so residuals, PRESS
    residuals, pure-error deviations and coefficients are matrix products with
    the pseudo-inverse, the hat matrix and the replicate-group projection.
    """

    def __init__(self, coded: np.ndarray, terms: list[Term], coding: Coding, need_actual: bool):
        x = model_matrix(coded, terms)
        n, p = x.shape
        u, s, vt = np.linalg.svd(x, full_matrices=False)
        tol = (s.max() if s.size else 0.0) * max(n, p) * np.finfo(float).eps  # numpy.linalg.matrix_rank's
        rank = int(np.sum(s > tol))
        self.x = x
        self.pinv = vt[:rank].T @ (u[:, :rank].T / s[:rank, None])
        self.hat = np.sum(u[:, :rank] ** 2, axis=1)
        groups = replicate_groups(coded) if n else np.zeros(0, dtype=int)
        n_groups = int(groups.max()) + 1 if n else 0
        onehot = np.zeros((n, n_groups))
        onehot[np.arange(n), groups] = 1.0
        self.group_mean = onehot @ (onehot.T / onehot.sum(axis=0)[:, None]) if n else np.zeros((0, 0))
        self.n, self.p, self.rank = n, p, rank
        self.df_pe = n - n_groups
        self.to_actual = _coded_to_actual_matrix(coding, terms) if need_actual else None

    def evaluate(self, y: np.ndarray, coefficients: dict[str, tuple[str, int]]) -> dict[str, np.ndarray]:
        y = np.asarray(y, dtype=float)
        beta = self.pinv @ y
        resid = y - self.x @ beta
        sse = np.sum(resid ** 2, axis=0)
        sst = np.sum((y - y.mean(axis=0)) ** 2, axis=0)
        ss_pe = np.sum((y - self.group_mean @ y) ** 2, axis=0)
        if np.all(self.hat < 1 - 1e-10):
            press = np.sum((resid / (1.0 - self.hat)[:, None]) ** 2, axis=0)
        else:
            press = np.full(sse.shape, np.nan)
        out = _statistics(sse, sst, press, ss_pe, self.n, self.p, self.rank, self.df_pe)
        return _add_coefficients(out, beta, self.to_actual, coefficients)


def _evaluate_designs(coded: np.ndarray, y: np.ndarray, terms: list[Term], to_actual: list | None,
                      coefficients: dict[str, tuple[str, int]]) -> dict[str, np.ndarray]:
    """Statistics of one response ``y`` (n,) on many designs ``coded`` (m, n, k), in one batched SVD."""
    m, n, _ = coded.shape
    x = np.stack([model_matrix(c, terms) for c in coded])
    p = x.shape[2]
    u, s, vt = np.linalg.svd(x, full_matrices=False)
    keep = s > s.max(axis=1, keepdims=True) * max(n, p) * np.finfo(float).eps
    rank = keep.sum(axis=1)
    u = u * keep[:, None, :]
    uty = np.einsum("mnq,n->mq", u, y)
    with np.errstate(divide="ignore"):
        s_inv = np.where(keep, 1.0 / s, 0.0)
    beta = np.einsum("mqp,mq->pm", vt, s_inv * uty)
    resid = y[None, :] - np.einsum("mnq,mq->mn", u, uty)
    hat = np.sum(u ** 2, axis=2)
    sse = np.sum(resid ** 2, axis=1)
    sst = np.full(m, np.sum((y - y.mean()) ** 2))
    with np.errstate(divide="ignore", invalid="ignore"):
        press = np.where(np.all(hat < 1 - 1e-10, axis=1), np.sum((resid / (1.0 - hat)) ** 2, axis=1), np.nan)
    # Replicates: same coded point after rounding to 6 decimals, as demid.design.replicate_groups.
    keys = np.round(coded, 6)
    same = np.all(keys[:, :, None, :] == keys[:, None, :, :], axis=3)
    size = same.sum(axis=2)
    ss_pe = np.sum((y[None, :] - (same @ y) / size) ** 2, axis=1)
    df_pe = n - np.rint(np.sum(1.0 / size, axis=1)).astype(int)
    out = _statistics(sse, sst, press, ss_pe, n, p, rank, df_pe)
    return _add_coefficients(out, beta, to_actual, coefficients)


# --------------------------------------------------------------------------- design levels
def _estimate_coding(column: np.ndarray, nominal: np.ndarray, alpha: float, decimals: int) -> tuple[float, float]:
    """(centre, unit) that puts the most cells of a factor column on the nominal coded levels.

    Starts from the table's mid-range coding (Coding.from_levels) and tries every
    pair of distinct values on every pair of levels, so that one mistyped extreme
    does not shift the levels a repair may take.  A cell is on a level when it is
    within its printing precision (``decimals``) of it, plus ``_ALPHA_SLACK``;
    among codings with equally many cells on levels, the smallest squared
    deviation wins, then the mid-range coding.
    """
    lo, hi = float(column.min()), float(column.max())
    default = ((lo + hi) / 2, (hi - lo) / (2 * alpha) if hi > lo else 1.0)
    distinct = np.unique(column)
    if len(nominal) < 2 or len(distinct) < 2 or len(distinct) > 15:
        return default
    options = [default]
    for (ua, ub), (la, lb) in ((u, lv) for u in combinations(distinct, 2) for lv in combinations(nominal, 2)):
        unit = (ub - ua) / (lb - la)
        options.append((ua - la * unit, unit))
    centre = np.array([o[0] for o in options])[:, None]
    unit = np.array([o[1] for o in options])[:, None]
    coded = (column[None, :] - centre) / unit
    deviation = np.min(np.abs(coded[:, :, None] - nominal[None, None, :]), axis=2)
    hit = deviation <= 0.5 * 10.0 ** (-decimals) / np.abs(unit) + _ALPHA_SLACK
    hits = hit.sum(axis=1)
    spread = np.where(hit, deviation ** 2, 0.0).sum(axis=1)
    best = int(np.lexsort((np.arange(len(options)), np.round(spread, 12), -hits))[0])
    return float(centre[best, 0]), float(unit[best, 0])


def _design_levels(column: np.ndarray, design_type: str, alpha: float, decimals: int,
                   fixed: tuple[float, float] | None) -> tuple[np.ndarray, float]:
    """Nominal levels of the declared design for one factor column (model units), and its unit."""
    nominal = nominal_levels(design_type, alpha)
    centre, unit = fixed if fixed is not None else _estimate_coding(column, nominal, alpha, decimals)
    return centre + unit * nominal, abs(unit)


def _levels_for_cell(column: np.ndarray, row: int, nominal: np.ndarray, tolerance: float):
    """Values a cell may be repaired to: (exact, approximate) levels.

    A nominal level that another cell of the column prints is only reachable as
    exactly that printed value; a nominal level no other cell shows (an axial
    point, say) is reachable within ``tolerance``.  Values the other cells repeat
    are exact levels too (designs off the nominal grid).
    """
    others = np.delete(column, row)
    exact, loose = [], []
    for level in nominal:
        near = others[np.abs(others - level) <= tolerance]
        if near.size:
            values, counts = np.unique(near, return_counts=True)
            exact.append(values[np.argmax(counts)])
        else:
            loose.append(level)
    values, counts = np.unique(others, return_counts=True)
    exact.extend(values[counts >= 2])
    return np.unique(np.array(exact, dtype=float)), np.array(loose, dtype=float)


# --------------------------------------------------------------------------- results
@dataclass(frozen=True)
class Suspect:
    """One single-cell repair: ``found`` in (run, column) was probably ``suggested``."""

    run: object
    column: str
    found: float
    suggested: float
    kind: str
    restores: int
    found_text: str = ""
    suggested_text: str = ""
    misfit: float = 0.0

    def to_dict(self) -> dict:
        return {"run": _jsonable(self.run), "column": self.column, "found": float(self.found),
                "suggested": float(self.suggested), "kind": self.kind, "restores": int(self.restores)}


@dataclass
class TranscriptionResult:
    """Verdict of :func:`check_transcription` for one response.

    ``published``/``reproduced``/``agrees`` are keyed by statistic (coefficients as
    ``coef_coded[a:b]`` or ``coef_actual[a:b]``); ``printed`` keeps each published
    value as printed.  ``explained`` is None when consistent, True when a
    single-cell repair restores every published statistic, False otherwise.
    ``n_candidates`` counts the single-cell hypotheses evaluated.
    """

    response: str
    consistent: bool
    published: dict[str, float]
    reproduced: dict[str, float]
    agrees: dict[str, bool]
    suspects: list[Suspect]
    explained: bool | None
    message: str
    printed: dict[str, str] = field(default_factory=dict)
    n_candidates: int = 0

    @property
    def n_published(self) -> int:
        return len(self.published)

    def to_json(self) -> dict:
        return {
            "consistent": bool(self.consistent),
            "published": {k: _jsonable(v) for k, v in self.published.items()},
            "reproduced": {k: _jsonable(v) for k, v in self.reproduced.items()},
            "suspects": [s.to_dict() for s in self.suspects],
            "response": self.response,
            "agrees": {k: bool(v) for k, v in self.agrees.items()},
            "printed": dict(self.printed),
            "n_published": self.n_published,
            "explained": self.explained,
            "message": self.message,
        }

    def to_frame(self) -> pd.DataFrame:
        """One row per published statistic: response, statistic, published, reproduced, agrees, printed."""
        rows = [(self.response, name, self.published[name], self.reproduced[name], bool(self.agrees[name]),
                 self.printed.get(name, "")) for name in self.published]
        return pd.DataFrame(rows, columns=["response", "statistic", "published", "reproduced", "agrees", "printed"])


def _jsonable(value):
    if isinstance(value, (np.integer,)):
        return int(value)
    if isinstance(value, (float, np.floating)):
        return float(value) if math.isfinite(value) else None
    return value


# A statistic the source computed from numbers it printed rounded: (statistic, printed inputs,
# value from the inputs and the table's degrees of freedom).  Each function is monotonic in every input,
# so its range over the inputs' rounding intervals is spanned by the corners.
def _f_ratio(ss_a, ss_b, df_a, df_b):
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where((df_a > 0) & (df_b > 0) & (ss_b > 0), (ss_a / df_a) / (ss_b / df_b), np.nan)


def _f_tail(f, df_a, df_b):
    with np.errstate(invalid="ignore"):
        return np.where((df_a > 0) & (df_b > 0) & np.isfinite(f), stats.f.sf(f, np.maximum(df_a, 1),
                                                                           np.maximum(df_b, 1)), np.nan)


_FROM_PRINTED = (
    ("lof_f", ("ss_lof", "ss_pure_error"), lambda a, b, v: _f_ratio(a, b, v["_df_lof"], v["_df_pe"])),
    ("lof_p", ("lof_f",), lambda f, v: _f_tail(f, v["_df_lof"], v["_df_pe"])),
    ("lof_p", ("ss_lof", "ss_pure_error"),
     lambda a, b, v: _f_tail(_f_ratio(a, b, v["_df_lof"], v["_df_pe"]), v["_df_lof"], v["_df_pe"])),
    ("r2", ("ss_model", "ss_total"), lambda a, b, v: np.full(np.shape(v["_df_pe"]), a / b if b > 0 else np.nan)),
    ("r2", ("ss_residual", "ss_total"),
     lambda a, b, v: np.full(np.shape(v["_df_pe"]), 1.0 - a / b if b > 0 else np.nan)),
)


def _agreement(targets: dict[str, PrintedValue], values: dict[str, np.ndarray]) -> tuple[dict, set]:
    """Per statistic, per hypothesis: does the printed value agree?  A statistic agrees when the refit
    rounds to it, or when it is what the source's own printed, rounded inputs give (any value of the
    inputs within their rounding) and those inputs agree with the refit.  Returns (agrees, names
    that agree only through their printed inputs, for any hypothesis)."""
    agrees = {name: np.atleast_1d(targets[name].agrees(values[name])) for name in targets}
    via_inputs: set[str] = set()
    for name, inputs, function in _FROM_PRINTED:
        if name not in targets or targets[name].relation != "=" or any(
                i not in targets or targets[i].relation != "=" for i in inputs):
            continue
        inputs_ok = np.logical_and.reduce([agrees[i] for i in inputs])
        corners = np.array([function(*[targets[i].value + sign * targets[i].half_width
                                       for i, sign in zip(inputs, signs)], values)
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


# --------------------------------------------------------------------------- the check
def check_transcription(table: pd.DataFrame, factors: list[str], response: str, published: dict, *,
                        alpha: float = 1.0, decimals: dict | None = None, design_type: str = "ccd",
                        coding: Coding | None = None, log_factors: tuple[str, ...] = (),
                        printed: pd.DataFrame | None = None, max_suspects: int = 10,
                        source: str | None = None) -> TranscriptionResult:
    """Compare the refit of ``response`` with the ``published`` statistics; locate a single-cell slip.

    ``published`` holds any of :data:`STATISTICS` and optionally
    ``coefficients: {units: coded|actual, values: {term: value}}`` (term names as
    :func:`demid.design.term_name` gives them); values may be strings to keep the
    printed decimals, and ``decimals`` (or a ``decimals`` entry inside
    ``published``) overrides them.  The model is the full quadratic in coded
    units, coded with ``Coding.from_levels(..., alpha)`` unless ``coding`` is given,
    exactly as :func:`demid.surrogate.fit_response` fits it (runs with a missing
    response are dropped); the reproduced statistics equal that fit's (tested).

    ``printed`` is the table as printed (strings, e.g. ``pd.read_csv(path,
    dtype=str)``); without it each numeric column is printed with its largest
    number of decimals.  A factor repair is considered only when it lands on a
    valid level of the declared design (``design_type``: ``ccd``, ``box_behnken``
    or ``factorial``, with ``alpha``; or a level the column repeats).
    ``log_factors`` are fitted in log10 units (``coding``, when given, is in those
    model units), as in :func:`~demid.surrogate.fit_response`.  Returns a
    :class:`TranscriptionResult`; raises :class:`InputError` for unusable input.
    """
    source = source or f"published statistics for '{response}'"
    factors = list(factors)
    missing = [c for c in [*factors, response] if c not in table.columns]
    if missing:
        raise InputError(f"column(s) {', '.join(repr(c) for c in missing)} not in the table", source=source)
    terms = quadratic_terms(len(factors))
    targets, coef_index = _parse_published(published, decimals, factors, terms, source)
    need_actual = any(units == "actual" for units, _ in coef_index.values())

    x_actual = _numeric(table, factors, source)
    y_all = _numeric(table, [response], source)[:, 0]
    if not np.all(np.isfinite(x_actual)):
        row, col = np.argwhere(~np.isfinite(x_actual))[0]
        raise InputError("factor value is missing", source=source, run=_runs(table)[row], column=factors[col])
    z = x_actual.copy()
    for j, name in enumerate(factors):
        if name in log_factors:
            if np.any(z[:, j] <= 0):
                raise InputError("log-scale factor must be positive", source=source, column=name)
            z[:, j] = np.log10(z[:, j])
    fit_rows = np.isfinite(y_all)
    y = y_all[fit_rows]
    runs = _runs(table)

    table_coding = coding if coding is not None else Coding.from_levels(factors, z, alpha)
    table_design = _DesignFit(table_coding.to_coded(z[fit_rows]), terms, table_coding, need_actual)
    base = _lack_of_fit_p(table_design.evaluate(y[:, None], coef_index))
    reproduced = {name: float(base[name][0]) for name in targets}
    base_agrees, via_inputs = _agreement(targets, base)
    agrees = {name: bool(base_agrees[name][0]) for name in targets}
    published_values = {name: t.value for name, t in targets.items()}
    printed_text = {name: t.text for name, t in targets.items()}
    n_pub = len(targets)
    n_agree = sum(agrees.values())

    def result(consistent, suspects, explained, message, n_candidates=0):
        return TranscriptionResult(response, consistent, published_values, reproduced, agrees, suspects,
                                   explained, message, printed_text, n_candidates)

    if n_agree == n_pub:
        note = (f" ({', '.join(sorted(via_inputs))} as computed from the source's own printed, rounded "
                "inputs)" if via_inputs else "")
        return result(True, [], None, f"the table reproduces all {n_pub} published statistics "
                                      f"of '{response}' to the printed decimals{note}")

    texts = _cell_texts(table, printed, [*factors, response], source)
    column_order = {name: i for i, name in enumerate(table.columns)}
    # (row, column, found_text, found, suggested_text, suggested, kind, _irregularity)
    records: list[tuple] = []
    blocks: list[dict[str, np.ndarray]] = []

    # Response cells: one column of Y per hypothesis, all evaluated at once.
    precision = _precision_elsewhere(texts[response])
    y_columns = []
    for i, row in enumerate(np.flatnonzero(fit_rows)):
        text = texts[response][row]
        if text is None:
            continue
        for kind, cand_text, value in single_cell_slips(text):
            y_columns.append((i, value))
            records.append((row, response, text, y_all[row], cand_text, value, kind,
                            _irregularity(text, cand_text, precision[row])))
    if y_columns:
        ymat = np.repeat(y[:, None], len(y_columns), axis=1)
        ymat[[i for i, _ in y_columns], np.arange(len(y_columns))] = [v for _, v in y_columns]
        blocks.append(table_design.evaluate(ymat, coef_index))

    # Factor cells: refit (batched) only repairs that land on a valid design level.
    repaired: list[np.ndarray] = []
    repaired_codings: list[Coding] = []
    for j, name in enumerate(factors):
        precision = _precision_elsewhere(texts[name])
        fixed = (float(coding.center[j]), float(coding.unit[j])) if coding is not None else None
        column_precision = int(np.sort(precision)[len(precision) // 2]) if len(precision) else 0
        nominal, unit = _design_levels(z[:, j], design_type, alpha, column_precision, fixed)
        is_log = name in log_factors
        for row in range(len(z)):
            text = texts[name][row]
            if text is None:
                continue
            # Printed levels are off by up to half a unit in the column's last place,
            # plus _ALPHA_SLACK for an alpha given to fewer digits than the table.
            half = 0.5 * 10.0 ** (-precision[row])
            if is_log:
                half /= max(float(x_actual[row, j]), 1e-300) * math.log(10)
            exact, loose = _levels_for_cell(z[:, j], row, nominal, half + _ALPHA_SLACK * unit)
            slips = [sl for sl in single_cell_slips(text) if not is_log or sl[2] > 0]
            if not slips or exact.size + loose.size == 0:
                continue
            values = np.array([value for _, _, value in slips])
            model_values = np.log10(values) if is_log else values
            levels = np.concatenate([exact, loose])
            tolerance = np.concatenate([1e-12 * np.maximum(1.0, np.abs(exact)),
                                        np.full(loose.size, half + _ALPHA_SLACK * unit)])
            gaps = np.abs(model_values[:, None] - levels[None, :])
            ok = gaps <= tolerance[None, :]
            # A cell found off every design level is itself irregular: its repairs come first in ties.
            off_grid = bool(np.all(np.abs(z[row, j] - levels) > tolerance))
            # One repair per design level: printed like the column, then nearest the level, then kind.
            per_level: dict[int, tuple] = {}
            for c, level in zip(*np.nonzero(ok)):
                kind, cand_text, value = slips[c]
                over = _irregularity(text, cand_text, precision[row])
                if off_grid and over == 0:
                    over = -1
                key = (over, gaps[c, level], _KIND_RANK[kind])
                if level not in per_level or key < per_level[level][0]:
                    per_level[level] = (key, kind, cand_text, value, float(model_values[c]), over)
            for _, kind, cand_text, value, model_value, over in per_level.values():
                z_new = z.copy()
                z_new[row, j] = model_value
                code = coding if coding is not None else Coding.from_levels(factors, z_new, alpha)
                repaired.append(code.to_coded(z_new[fit_rows]))
                repaired_codings.append(code)
                records.append((row, name, text, x_actual[row, j], cand_text, value, kind, over))
    if repaired:
        to_actual = [_coded_to_actual_matrix(c, terms) for c in repaired_codings] if need_actual else None
        blocks.append(_evaluate_designs(np.stack(repaired), y, terms, to_actual, coef_index))

    if not records:
        return result(False, [], False, _unexplained_message(response, targets, reproduced, agrees, 0, 0), 0)
    values = _lack_of_fit_p({key: np.concatenate([np.atleast_1d(b[key]) for b in blocks]) for key in blocks[0]})
    restores = np.zeros(len(records), dtype=int)
    misfit = np.zeros(len(records))
    candidate_agrees, _ = _agreement(targets, values)
    for name in targets:
        restores += candidate_agrees[name]
        misfit += np.where(candidate_agrees[name], 0.0, targets[name].misfit(values[name]))
    # Round the continuous tie-break so that symmetric repairs fall through to kind, row and column.
    order = np.lexsort((
        [column_order[r[1]] for r in records],
        [r[0] for r in records],
        [_KIND_RANK[r[6]] for r in records],
        np.round(misfit, 9),
        [r[7] for r in records],
        -restores,
    ))

    full = order[restores[order] == n_pub]
    explained = bool(full.size)
    chosen = full if explained else order[restores[order] > n_agree]
    chosen = chosen[: max_suspects if explained else min(max_suspects, 5)]
    suspects = [Suspect(run=runs[records[c][0]], column=records[c][1], found=float(records[c][3]),
                        suggested=float(records[c][5]), kind=records[c][6], restores=int(restores[c]),
                        found_text=records[c][2], suggested_text=records[c][4], misfit=float(misfit[c]))
                for c in chosen]
    if explained:
        best = suspects[0]
        message = (f"the table does not reproduce {n_pub - n_agree} of {n_pub} published statistics of "
                   f"'{response}'; a single-cell slip explains it: run {best.run}, column '{best.column}' "
                   f"reads {best.found_text} where {best.suggested_text} restores all {n_pub} "
                   f"({best.kind.replace('_', ' ')})")
        if full.size > 1:
            message += (f"; {full.size} single-cell repairs restore all of them, so the published statistics "
                        "do not single one out (best match to the printed values first)")
    else:
        message = _unexplained_message(response, targets, reproduced, agrees, len(suspects),
                                       int(restores.max()))
    return result(False, suspects, explained, message, len(records))


def _unexplained_message(response, targets, reproduced, agrees, n_partial, best_restores) -> str:
    off = [f"{name} {_format(reproduced[name])} vs printed {targets[name].text}"
           for name in targets if not agrees[name]]
    message = (f"'{response}' disagrees with the source ({'; '.join(off)}). No single-cell slip explains the "
               "disagreement: the table or the model differs from the source's in a bigger way "
               "(a different model, a dropped run, more than one typo)")
    unreproducible = [name for name in targets if not np.isfinite(reproduced[name])]
    if unreproducible:
        message += (f"; {', '.join(unreproducible)} cannot be computed from this table "
                    "(e.g. no replicated runs for lack of fit)")
    if n_partial:
        message += (f"; the closest single-cell repairs restore only {best_restores} of {len(targets)} "
                    "statistics and are listed as leads")
    return message


def _runs(table: pd.DataFrame) -> list:
    if "run" in table.columns:
        return [_jsonable(v) for v in table["run"].tolist()]
    return list(range(1, len(table) + 1))


def _numeric(table: pd.DataFrame, columns: list[str], source: str) -> np.ndarray:
    out = np.empty((len(table), len(columns)))
    for j, name in enumerate(columns):
        values = pd.to_numeric(table[name], errors="coerce").to_numpy(dtype=float)
        bad = np.flatnonzero(np.isnan(values) & table[name].notna().to_numpy())
        if bad.size:
            raise InputError(f"not a number: {table[name].iloc[bad[0]]!r}", source=source,
                             run=_runs(table)[bad[0]], column=name)
        out[:, j] = values
    return out


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


def check_table(table: pd.DataFrame, factors: list[str], responses_cfg: dict, *, alpha: float = 1.0,
                design_type: str = "ccd", **options) -> list[TranscriptionResult]:
    """:func:`check_transcription` for every response whose config has a ``published`` block.

    ``responses_cfg`` is a material's ``responses`` mapping (config.yaml); extra
    keyword ``options`` (coding, log_factors, printed, source) are passed on.
    """
    results = []
    for response, cfg in responses_cfg.items():
        block = (cfg or {}).get("published")
        if not block:
            continue
        results.append(check_transcription(table, factors, response, block, alpha=alpha,
                                           design_type=design_type, **options))
    return results


def check_material(validated, material_cfg: dict, printed: pd.DataFrame | None = None) -> list[TranscriptionResult]:
    """The transcription check of a validated material table against its config's ``published`` blocks.

    Uses the validated table's design coding, so the check and the fits share one coding.
    """
    factors = list(material_cfg["factors"])
    log_factors = tuple(f for f, c in material_cfg["factors"].items() if c.get("scale") == "log")
    design = material_cfg["design"]
    table = validated.table
    return check_table(table, factors, material_cfg["responses"], alpha=float(design.get("alpha", 1.0)),
                       design_type=design["type"], coding=validated.coding, log_factors=log_factors,
                       printed=printed, source=material_cfg["data"])


def transcription_frame(results: list[TranscriptionResult]) -> pd.DataFrame:
    """Rows of tables/transcription_check.csv (without the material column)."""
    columns = ["response", "statistic", "published", "reproduced", "agrees", "printed"]
    frames = [r.to_frame() for r in results]
    return pd.concat(frames, ignore_index=True) if frames else pd.DataFrame(columns=columns)


def likely_typos(validated, material_cfg: dict, printed: pd.DataFrame | None = None, *,
                 family_alpha: float = 0.05, kinds=("transposition", "decimal_shift", "sign_lost")) -> list[dict]:
    """Response cells that look mistyped even without published statistics.

    A run is flagged when its externally studentised residual is extreme after a
    Bonferroni correction over the runs (family-wise ``family_alpha``) *and* a digit
    swap, misplaced decimal point or lost sign of the printed cell lands within three
    leave-one-out standard errors of the prediction from the other runs.  Both
    conditions together keep this silent on clean tables.
    """
    from scipy import stats as _stats

    from .surrogate import fit_response

    factors = list(material_cfg["factors"])
    log_factors = tuple(f for f, c in material_cfg["factors"].items() if c.get("scale") == "log")
    table = validated.table
    flags = []
    for response in material_cfg["responses"]:
        fit = fit_response(table, factors, response, coding=validated.coding, log_factors=log_factors)
        n, p = fit.n_runs, fit.n_params
        df = n - p - 1
        if df < 1:
            continue
        infl = fit.influence()
        pvals = 2 * _stats.t.sf(np.abs(infl["student_resid"].to_numpy()), df) * n
        for i in np.flatnonzero(pvals < family_alpha):
            row = infl.iloc[i]
            h = row["leverage"]
            loo_pred = row["observed"] - row["residual"] / (1 - h)
            s_loo = abs(row["residual"] / row["student_resid"]) / np.sqrt(1 - h) if row["student_resid"] else 0.0
            se = s_loo * np.sqrt(1 + h / (1 - h))  # prediction error of the run from the others
            run = row["run"]
            if printed is not None:
                text = printed.loc[table["run"].to_numpy() == run, response].iloc[0]
            else:
                text = repr(float(row["observed"]))
            best = None
            for kind, suggested_text, value in single_cell_slips(str(text)):
                if kind not in kinds:
                    continue
                distance = abs(value - loo_pred)
                if distance <= 3 * se and (best is None or distance < best[0]):
                    best = (distance, kind, value)
            if best is not None:
                flags.append({"run": _jsonable(run), "column": response, "found": float(row["observed"]),
                              "suggested": best[2], "kind": best[1], "student_resid": float(row["student_resid"]),
                              "predicted_from_other_runs": float(loo_pred),
                              "message": f"{material_cfg['data']}, run {_jsonable(run)}, column '{response}': "
                                         f"{text} is far from the fit of the other runs (studentised residual "
                                         f"{row['student_resid']:.1f}, predicted {loo_pred:.4g}); "
                                         f"{best[2]:g} ({best[1].replace('_', ' ')}) would fit — likely typo"})
    return flags

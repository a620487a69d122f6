"""The transcription check of one response, of a table, and of a configured material."""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from ..design import Coding, quadratic_terms
from ..errors import InputError
from ..io import CSV_SIGNIFICANT_DIGITS
from .engine import (_ALPHA_SLACK, DesignFit, _coded_to_actual_matrix, _design_levels, evaluate_designs,
                     lack_of_fit_p, _levels_for_cell, _numeric, _runs)
from .printed import (_agreement, _cell_texts, _format, _irregularity, _jsonable, _parse_published,
                      _precision_elsewhere, parse_printed)
from .typos import _KIND_RANK, KINDS, SLIP_WORDS, single_cell_slips

if TYPE_CHECKING:
    from ..spec import MaterialSpec


#: Response hypotheses are evaluated in blocks of at most this many cells (runs x hypotheses): 32 MB.
_CELLS_PER_BLOCK = 4_000_000


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
    ``n_candidates`` counts the single-cell hypotheses evaluated.  ``printed_slip`` is set when the
    table reproduces every published statistic but one, and a one-keystroke slip of that printed
    statistic gives the reproduced value (``statistic``, ``printed``, ``looks_like``, ``kind``): the slip
    is then in the printed (or transcribed) statistic, not in the table.
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
    printed_slip: dict | None = None

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
            "printed_slip": self.printed_slip,
            "message": self.message,
        }

    def to_frame(self) -> pd.DataFrame:
        """One row per published statistic: response, statistic, published, reproduced, agrees, printed,
        printed_decimals."""
        rows = [(self.response, name, self.published[name], self.reproduced[name], bool(self.agrees[name]),
                 *_printed_cells(self.printed.get(name, ""))) for name in self.published]
        return pd.DataFrame(rows, columns=TRANSCRIPTION_FRAME_COLUMNS)


TRANSCRIPTION_FRAME_COLUMNS = ["response", "statistic", "published", "reproduced", "agrees", "printed",
                               "printed_decimals"]


def _printed_cells(text: str) -> tuple[str, float]:
    """The printed text for a table cell and its decimals.

    Every number in the tables carries at most 6 significant digits, so a value printed with
    more (an RMSE of 7579.048) is shown rounded; ``printed_decimals`` keeps the precision the
    agreement was judged at.  Trailing zeros of shorter values are kept (``0.970``)."""
    if not text:
        return "", float("nan")
    decimals = float(parse_printed(text).decimals)
    number = re.search(r"\d[\d.]*", text)
    digits = number.group(0).replace(".", "").lstrip("0") if number else ""
    if len(digits) > CSV_SIGNIFICANT_DIGITS:
        rounded = np.format_float_positional(float(number.group(0)), precision=CSV_SIGNIFICANT_DIGITS,
                                             unique=False, fractional=False, trim="-")
        text = text[:number.start()] + rounded + text[number.end():]
    return text, decimals


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
    # The verdict's outline: reading cells, building hypotheses and ranking repairs are the helpers.
    source = source or f"published statistics for '{response}'"
    factors = list(factors)
    missing = [c for c in [*factors, response] if c not in table.columns]
    if missing:
        raise InputError(f"column(s) {', '.join(repr(c) for c in missing)} not in the table", source=source)
    terms = quadratic_terms(len(factors))
    targets, coef_index = _parse_published(published, decimals, factors, terms, source)
    need_actual = any(units == "actual" for units, _ in coef_index.values())
    x_actual, y_all, z = _read_cells(table, factors, response, log_factors, source)
    fit_rows = np.isfinite(y_all)
    y = y_all[fit_rows]

    table_coding = coding if coding is not None else Coding.from_levels(factors, z, alpha)
    table_design = DesignFit(table_coding.to_coded(z[fit_rows]), terms, table_coding, need_actual)
    base = lack_of_fit_p(table_design.evaluate(y[:, None], coef_index))
    reproduced = {name: float(base[name][0]) for name in targets}
    base_agrees, via_inputs = _agreement(targets, base)
    agrees = {name: bool(base_agrees[name][0]) for name in targets}
    published_values = {name: t.value for name, t in targets.items()}
    printed_text = {name: t.text for name, t in targets.items()}
    n_pub, n_agree = len(targets), sum(agrees.values())

    def result(consistent, suspects, explained, message, n_candidates=0):
        return TranscriptionResult(response, consistent, published_values, reproduced, agrees, suspects,
                                   explained, message, printed_text, n_candidates)

    if n_agree == n_pub:
        note = (f" ({', '.join(sorted(via_inputs))} as computed from the source's own printed, rounded "
                "inputs)" if via_inputs else "")
        return result(True, [], None, f"the table reproduces all {n_pub} published statistics "
                                      f"of '{response}' to the printed decimals{note}")

    texts = _cell_texts(table, printed, [*factors, response], source)
    # (row, column, found_text, found, suggested_text, suggested, kind, _irregularity)
    records: list[tuple] = []
    blocks: list[dict[str, np.ndarray]] = []
    _response_hypotheses(texts[response], response, y_all, fit_rows, table_design, coef_index, records, blocks)
    repaired, repaired_codings = _factor_hypotheses(texts, factors, x_actual, z, fit_rows, design_type, alpha,
                                                    coding, log_factors, records)
    if repaired:
        to_actual = [_coded_to_actual_matrix(c, terms) for c in repaired_codings] if need_actual else None
        blocks.append(evaluate_designs(np.stack(repaired), y, terms, to_actual, coef_index))

    # A slip in one printed statistic is considered only when no slip in the table explains everything.
    slip = _printed_slip(targets, reproduced, agrees)
    slip_result = None
    if slip is not None:
        slip_result = replace(result(False, [], False, _printed_slip_message(response, slip, n_pub, n_agree),
                                     len(records)), printed_slip=slip)
    if not records:
        return slip_result if slip_result is not None else result(
            False, [], False, _unexplained_message(response, targets, reproduced, agrees, 0, 0), 0)
    return _located(response, table, targets, reproduced, agrees, records, blocks, max_suspects, slip_result,
                    result)


def _located(response: str, table: pd.DataFrame, targets: dict, reproduced: dict, agrees: dict, records: list,
             blocks: list, max_suspects: int, slip_result, result) -> TranscriptionResult:
    """The cells whose repair restores the published statistics, best first (every one when some restore them
    all; else up to five partial leads), or ``slip_result`` (a slip in one printed statistic) when no repair
    restores them all; ``result`` builds the :class:`TranscriptionResult`."""
    n_pub, n_agree = len(targets), sum(agrees.values())
    restores, restores_exact, misfit, order = _rank_repairs(records, blocks, targets, table.columns)
    full = order[restores[order] == n_pub]
    explained = bool(full.size)
    if not explained and slip_result is not None:
        return slip_result
    # A partial lead must restore a printed value, not only a bound ("p < 0.0001" holds for any repair
    # that wrecks the fit).
    n_agree_exact = sum(agrees[name] for name in targets if targets[name].relation == "=")
    chosen = full if explained else order[(restores[order] > n_agree) & (restores_exact[order] > n_agree_exact)]
    chosen = chosen[: max_suspects if explained else min(max_suspects, 5)]
    runs = _runs(table)
    suspects = [Suspect(run=runs[records[c][0]], column=records[c][1], found=float(records[c][3]),
                        suggested=float(records[c][5]), kind=records[c][6], restores=int(restores[c]),
                        found_text=records[c][2], suggested_text=records[c][4], misfit=float(misfit[c]))
                for c in chosen]
    if explained:
        message = _explained_message(response, suspects[0], n_pub, n_agree, full.size, len(records))
    else:
        message = _unexplained_message(response, targets, reproduced, agrees, len(suspects),
                                       int(restores.max()))
    return result(False, suspects, explained, message, len(records))


def _read_cells(table: pd.DataFrame, factors: list[str], response: str, log_factors, source: str):
    """Factor and response values as numbers, and the factors in model units (log10 for log factors)."""
    x_actual = _numeric(table, factors, source)
    y_all = _numeric(table, [response], source)[:, 0]
    if not np.isfinite(y_all).any():
        raise InputError(f"no run has a value of '{response}': there is nothing to refit", source=source,
                         column=response)
    if not np.all(np.isfinite(x_actual)):
        row, col = np.argwhere(~np.isfinite(x_actual))[0]
        raise InputError("factor value is missing", source=source, run=_runs(table)[row], column=factors[col])
    z = x_actual.copy()
    for j, name in enumerate(factors):
        if name in log_factors:
            if np.any(z[:, j] <= 0):
                raise InputError("log-scale factor must be positive", source=source, column=name)
            z[:, j] = np.log10(z[:, j])
    return x_actual, y_all, z


def _response_hypotheses(texts: list, response: str, y_all: np.ndarray, fit_rows: np.ndarray,
                         table_design: DesignFit, coef_index: dict, records: list, blocks: list) -> None:
    """Response cells: one column of Y per hypothesis, all evaluated at once (appends to records, blocks)."""
    y = y_all[fit_rows]
    precision = _precision_elsewhere(texts)
    y_columns = []
    for i, row in enumerate(np.flatnonzero(fit_rows)):
        text = texts[row]
        if text is None:
            continue
        for kind, cand_text, value in single_cell_slips(text):
            y_columns.append((i, value))
            records.append((row, response, text, y_all[row], cand_text, value, kind,
                            _irregularity(text, cand_text, precision[row])))
    # a column per hypothesis, about 20 per cell: a few thousand columns at a time, or a large table's
    # hypotheses would be an n x 20n matrix
    per_block = max(1, _CELLS_PER_BLOCK // max(len(y), 1))
    for start in range(0, len(y_columns), per_block):
        part = y_columns[start:start + per_block]
        ymat = np.repeat(y[:, None], len(part), axis=1)
        ymat[[i for i, _ in part], np.arange(len(part))] = [v for _, v in part]
        blocks.append(table_design.evaluate(ymat, coef_index))


def _factor_hypotheses(texts: dict, factors: list[str], x_actual: np.ndarray, z: np.ndarray, fit_rows: np.ndarray,
                       design_type: str, alpha: float, coding: Coding | None, log_factors, records: list):
    """Factor cells: the repairs that land on a valid design level, as coded designs to refit in a batch.

    Appends one record per repair and returns the repaired coded designs and their codings.
    """
    repaired: list[np.ndarray] = []
    repaired_codings: list[Coding] = []
    for j, name in enumerate(factors):
        precision = _precision_elsewhere(texts[name])
        fixed = (float(coding.center[j]), float(coding.unit[j])) if coding is not None else None
        column_precision = int(np.sort(precision)[len(precision) // 2]) if len(precision) else 0
        # one axial distance, or one per factor (a design inferred from a table with rounded levels)
        alpha_j = float(np.broadcast_to(np.asarray(alpha, dtype=float), (len(factors),))[j])
        nominal, unit = _design_levels(z[:, j], design_type, alpha_j, column_precision, fixed)
        is_log = name in log_factors
        for row in range(len(z)):
            text = texts[name][row]
            if text is None:
                continue
            for kind, cand_text, value, model_value, over in _cell_repairs(
                    text, z, row, j, nominal, unit, precision[row], is_log, x_actual[row, j]):
                z_new = z.copy()
                z_new[row, j] = model_value
                code = coding if coding is not None else Coding.from_levels(factors, z_new, alpha)
                repaired.append(code.to_coded(z_new[fit_rows]))
                repaired_codings.append(code)
                records.append((row, name, text, x_actual[row, j], cand_text, value, kind, over))
    return repaired, repaired_codings


def _cell_repairs(text: str, z: np.ndarray, row: int, j: int, nominal: np.ndarray, unit: float, precision: int,
                  is_log: bool, actual: float) -> list[tuple]:
    """The slips of one factor cell that land on a design level: one per level, as
    ``(kind, text, value, model value, irregularity)``."""
    # Printed levels are off by up to half a unit in the column's last place,
    # plus _ALPHA_SLACK for an alpha given to fewer digits than the table.
    half = 0.5 * 10.0 ** (-precision)
    if is_log:
        half /= max(float(actual), 1e-300) * math.log(10)
    exact, loose = _levels_for_cell(z[:, j], row, nominal, half + _ALPHA_SLACK * unit)
    slips = [sl for sl in single_cell_slips(text) if not is_log or sl[2] > 0]
    if not slips or exact.size + loose.size == 0:
        return []
    values = np.array([value for _, _, value in slips])
    model_values = np.log10(values) if is_log else values
    levels = np.concatenate([exact, loose])
    tolerance = np.concatenate([1e-12 * np.maximum(1.0, np.abs(exact)),
                                np.full(loose.size, half + _ALPHA_SLACK * unit)])
    gaps = np.abs(model_values[:, None] - levels[None, :])
    ok = gaps <= tolerance[None, :]
    # A cell found off every design level is itself irregular: its repairs come first in ties.
    off_grid = bool(np.all(np.abs(z[row, j] - levels) > tolerance))
    # One repair per design level: printed like the column, then nearest the level, then kind, then the one
    # that changes the printed value least (10.13, not 10.12, for 10.14 at a level of 10.125), then the lower.
    per_level: dict[int, tuple] = {}
    for c, level in zip(*np.nonzero(ok)):
        kind, cand_text, value = slips[c]
        over = _irregularity(text, cand_text, precision)
        if off_grid and over == 0:
            over = -1
        key = (over, gaps[c, level], _KIND_RANK[kind], abs(value - float(actual)), value)
        if level not in per_level or key < per_level[level][0]:
            per_level[level] = (key, kind, cand_text, value, float(model_values[c]), over)
    return [entry[1:] for entry in per_level.values()]


def _rank_repairs(records: list[tuple], blocks: list[dict], targets: dict, columns) -> tuple:
    """Statistics restored and summed misfit per repair, and the ranking order (see the package docstring)."""
    column_order = {name: i for i, name in enumerate(columns)}
    values = lack_of_fit_p({key: np.concatenate([np.atleast_1d(b[key]) for b in blocks]) for key in blocks[0]})
    restores = np.zeros(len(records), dtype=int)
    restores_exact = np.zeros(len(records), dtype=int)
    misfit = np.zeros(len(records))
    candidate_agrees, _ = _agreement(targets, values)
    for name in targets:
        restores += candidate_agrees[name]
        if targets[name].relation == "=":
            restores_exact += candidate_agrees[name]
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
    return restores, restores_exact, misfit, order


#: Slips of a printed statistic that are looked for: each moves the value far, so a repair that rounds
#: to the reproduced value is not a coincidence (a substituted digit could be).
_STATISTIC_SLIPS = ("sign_lost", "decimal_shift", "transposition", "digit_doubled", "digit_dropped")


def _printed_slip(targets: dict, reproduced: dict, agrees: dict) -> dict | None:
    """The one disagreeing statistic, when every other agrees and a slip of its printed text rounds to the
    reproduced value (0.898 printed for 0.989)."""
    off = [name for name in targets if not agrees[name]]
    if len(targets) < 2 or len(off) != 1 or targets[off[0]].relation != "=" or "%" in targets[off[0]].text:
        return None
    name = off[0]
    printed_decimals = targets[name].decimals
    # a candidate with more decimals than printed would explain any near miss by "a digit dropped" at the end
    fitting = sorted((_KIND_RANK[kind], text) for kind, text, _ in single_cell_slips(targets[name].text)
                     if kind in _STATISTIC_SLIPS
                     and (kind != "digit_dropped" or parse_printed(text).decimals <= printed_decimals)
                     and bool(parse_printed(text).agrees(reproduced[name])))
    if not fitting:
        return None
    rank, text = fitting[0]
    return {"statistic": name, "printed": targets[name].text, "looks_like": text, "kind": KINDS[rank]}


def _printed_slip_message(response: str, slip: dict, n_pub: int, n_agree: int) -> str:
    return (f"the table reproduces {n_agree} of {n_pub} published statistics of '{response}'; the printed "
            f"{slip['statistic']}, {slip['printed']}, looks like {slip['looks_like']} "
            f"with {SLIP_WORDS[slip['kind']]}: the slip is in the printed or transcribed statistic, not in the "
            f"table — check the source's value")


def _explained_message(response: str, best: Suspect, n_pub: int, n_agree: int, n_full: int,
                       n_candidates: int) -> str:
    head = f"the table does not reproduce {n_pub - n_agree} of {n_pub} published statistics of '{response}'"
    cell = (f"run {best.run}, column '{best.column}' reads {best.found_text} where {best.suggested_text} restores "
            f"all {n_pub} ({best.kind.replace('_', ' ')})")
    if n_full == 1 and n_pub == 1:
        # One number is matched by chance among hundreds of candidate repairs often enough that a lone
        # match is a lead, not a location.
        return (f"{head}; one single-cell repair restores it: {cell}; with a single published statistic a "
                f"chance match among the {n_candidates} repairs tried cannot be ruled out, so check that cell "
                f"against the source (a second published statistic would confirm or clear it)")
    if n_full == 1:
        return f"{head}; a single-cell slip explains it: {cell}"
    # Many repairs fitting equally is what a published statistic too weak to locate anything looks like:
    # naming the first as "the" slip would send the user to a cell the evidence does not single out.
    return (f"{head}; a single-cell slip could explain it, but {n_full} different single-cell repairs restore "
            f"all of them, so the published statistics do not locate the slip; the closest to the printed "
            f"values: {cell} (all listed as leads; check them against the source)")


def _unexplained_message(response, targets, reproduced, agrees, n_partial, best_restores) -> str:
    off = [f"{name} {_format(reproduced[name])} vs printed {targets[name].text}"
           for name in targets if not agrees[name]]
    message = (f"'{response}' disagrees with the source ({'; '.join(off)}). No single-cell slip explains the "
               "disagreement: the table or the model differs from the source's in a bigger way "
               "(a different model, a dropped run, more than one typo), or the printed value is itself wrong")
    unreproducible = [name for name in targets if not np.isfinite(reproduced[name])]
    if unreproducible:
        message += (f"; {', '.join(unreproducible)} cannot be computed from this table "
                    "(e.g. no replicated runs for lack of fit)")
    if n_partial:
        message += (f"; the closest single-cell repairs restore only {best_restores} of {len(targets)} "
                    "statistics and are listed as leads")
    return message


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


def check_material(validated, spec: MaterialSpec, printed: pd.DataFrame | None = None) -> list[TranscriptionResult]:
    """The transcription check of a validated material table against its config's ``published`` blocks.

    ``spec`` is the material's :class:`~demid.spec.MaterialSpec`.  Uses the validated table's design
    coding, so the check and the fits share one coding.
    """
    responses = {r: ({"published": spec.published[r]} if r in spec.published else {}) for r in spec.response_names}
    return check_table(validated.table, spec.factor_names, responses, alpha=spec.alpha,
                       design_type=spec.design_type, coding=validated.coding, log_factors=spec.log_factors,
                       printed=printed, source=spec.data)


def transcription_frame(results: list[TranscriptionResult]) -> pd.DataFrame:
    """Rows of tables/transcription_check.csv (without the material column)."""
    columns = TRANSCRIPTION_FRAME_COLUMNS
    frames = [r.to_frame() for r in results]
    return pd.concat(frames, ignore_index=True) if frames else pd.DataFrame(columns=columns)

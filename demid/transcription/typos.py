"""Single-cell slips a typist makes, the validator's likely-typo flag and the stop on a likely typo.

:func:`single_cell_slips` lists every edit of one printed cell (sign lost, decimal shift,
transposition, doubled, dropped or substituted digit); :func:`likely_typos` flags runs whose
extreme studentised residual a slip would explain, even without published statistics;
:func:`refuse_likely_typos` stops on such a cell unless the config confirms it.  Part of the input
layer: it imports nothing above the design and precision modules.
"""

from __future__ import annotations

import math
from decimal import Decimal, InvalidOperation
from typing import TYPE_CHECKING

import numpy as np

from ..errors import InputError
from .printed import _jsonable

if TYPE_CHECKING:
    import pandas as pd

    from ..spec import MaterialSpec


# Priority order (fewer keystrokes first); also the tie-break among equal repairs.
KINDS = ("sign_lost", "decimal_shift", "transposition", "digit_doubled", "digit_dropped", "digit_substitution")


_KIND_RANK = {kind: i for i, kind in enumerate(KINDS)}

#: Each slip in words, as messages say what a value "looks like ... with".
SLIP_WORDS = {"sign_lost": "its sign lost", "decimal_shift": "the decimal point shifted",
              "transposition": "two adjacent digits swapped", "digit_doubled": "a digit doubled",
              "digit_dropped": "a digit dropped", "digit_substitution": "a digit mistyped",
              "digit_added": "a digit added"}


_ALL_DIGITS = "0123456789"


def single_cell_slips(text: str) -> list[tuple[str, str, float]]:
    """All repairs ``(kind, suggested_text, suggested_value)`` of a cell printed as ``text``.

    ``kind`` names the slip that would turn the suggestion into ``text``:
    ``digit_dropped`` inserts a digit, ``digit_doubled`` removes one of two equal
    neighbours, ``sign_lost`` restores a lost minus (or removes a stray one),
    ``decimal_shift`` moves the point by 1 or 2 places.  Repairs that give the
    same number are kept once, under the kind listed first in :data:`KINDS`.
    """
    raw = text.strip().replace("\u2212", "-")  # a typeset minus, which the table reader accepts
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
        if candidate.lstrip("-")[:1] == "0" and candidate.lstrip("-")[1:2].isdigit():
            continue  # "050.3": no table prints a leading zero, so no slip produced the cell from it
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


def cell_decimals(text: str) -> int:
    """Digits after the decimal point of a printed number (``1.5e-3`` counts as 0.0015)."""
    try:
        exponent = Decimal(str(text).strip().replace("\u2212", "-")).as_tuple().exponent
    except InvalidOperation:
        return 0
    return max(-int(exponent), 0) if isinstance(exponent, int) else 0


def _decimal_places(cells) -> int | None:
    """The most decimals any printed cell of a column shows (None without printed cells)."""
    places = [cell_decimals(c) for c in cells if str(c).strip()]
    return max(places) if places else None


def added_digit_repairs(text: str) -> list[tuple[str, str, float]]:
    """Repairs ``("digit_added", text, value)`` of a cell with one stray digit keyed in (359.17 for 39.17).

    Not one of :data:`KINDS`: with every digit removable, so many repairs exist that the transcription
    search would match published statistics by chance.  The typo screen uses them only to say that the repair
    it names is not the only one that fits.
    """
    raw = text.strip().replace("\u2212", "-")
    try:
        found = float(Decimal(raw))
    except (InvalidOperation, ValueError):
        return []
    out = []
    for i, ch in enumerate(raw):
        candidate = raw[:i] + raw[i + 1:]
        bare = candidate.lstrip("-")
        if not ch.isdigit() or not any(c.isdigit() for c in bare) or (bare[:1] == "0" and bare[1:2].isdigit()):
            continue
        try:
            value = float(Decimal(candidate))
        except InvalidOperation:
            continue
        if value != found and math.isfinite(value):
            out.append(("digit_added", candidate, value))
    return out


def two_sided_t_p(t, df: int) -> np.ndarray:
    """P(|T| >= |t|) for Student's t with integer ``df`` >= 1.

    The finite series in cos(theta), theta = atan(|t| / sqrt(df)) (Abramowitz & Stegun
    26.7.3-4), so the typo screen, which runs when the workflow is parsed, needs no scipy.
    The absolute error is a few 1e-16: ample for a threshold at family_alpha / n.
    """
    t = np.abs(np.asarray(t, dtype=float))
    theta = np.arctan(t / math.sqrt(df))
    sin, cos2 = np.sin(theta), np.cos(theta) ** 2
    term = np.ones_like(t)
    series = np.ones_like(t)
    if df % 2 == 0:
        for k in range(1, df // 2):
            term = term * cos2 * (2 * k - 1) / (2 * k)
            series = series + term
        inside = sin * series
    elif df == 1:
        inside = 2 * theta / math.pi
    else:
        for k in range(1, (df - 1) // 2):
            term = term * cos2 * (2 * k) / (2 * k + 1)
            series = series + term
        inside = 2 / math.pi * (theta + sin * np.sqrt(cos2) * series)
    return np.clip(1.0 - inside, 0.0, 1.0)


def studentised_residuals(coded: np.ndarray, y: np.ndarray, terms) -> dict[str, np.ndarray]:
    """Leverage, residual and externally studentised residual of every run of an OLS fit.

    Plain numpy (pseudo-inverse, as statsmodels' OLS), so the screen imports neither scipy nor
    statsmodels; the definitions are statsmodels' ``get_influence()``: the residual over the
    scale without the run, s_(i)^2 = (SSE - e_i^2 / (1 - h_i)) / (n - rank - 1).
    """
    from ..design import model_matrix
    from ..precision import round_off_only

    x = model_matrix(coded, terms)
    pinv = np.linalg.pinv(x)
    residual = y - x @ (pinv @ y)
    leverage = np.einsum("ij,ji->i", x, pinv)
    dof = len(y) - np.linalg.matrix_rank(x) - 1
    with np.errstate(divide="ignore", invalid="ignore"):
        scale_without = (np.sum(residual ** 2) - residual ** 2 / (1 - leverage)) / dof
        student = residual / np.sqrt(scale_without * (1 - leverage))
    if round_off_only(residual, y):
        student = np.full_like(residual, np.nan)  # 0/0: round-off over round-off is noise
    return {"leverage": leverage, "residual": residual, "student_resid": student}


#: From this many residual degrees of freedom on, the screen lets the scatter vary with the response's level
#: (below it a variance trend is too poorly estimated to be worth the extra freedom).
LOCAL_SCALE_MIN_DF = 100


def local_scale(fitted: np.ndarray, residual: np.ndarray, leverage: np.ndarray) -> np.ndarray:
    """Per run, the residual standard deviation at the run's level relative to the table's pooled one (1 where
    the scatter is the same everywhere).

    Simulated responses often scatter in proportion to their level (a relative seed-to-seed noise), and with
    thousands of runs the pooled scale then makes the top of the range look like outliers by the dozen: a
    studentised residual of 4.9 at 10,000 runs is 4.2 of the run's own scatter.  Harvey's multiplicative model
    log sigma_i^2 = a + b * fitted_i, fitted by least squares on log e_i^2 / (1 - h_i) (a planted slip moves
    a log-scale fit very little), rescaled so that the squared residuals over the variance function average 1.
    """
    raw = residual ** 2 / np.clip(1 - leverage, 1e-12, None)
    positive = raw > 0
    if positive.sum() < 3 or np.ptp(fitted[positive]) == 0:
        return np.ones_like(residual)
    design = np.column_stack([np.ones(positive.sum()), fitted[positive]])
    coef, *_ = np.linalg.lstsq(design, np.log(raw[positive]), rcond=None)
    variance = np.exp(coef[0] + coef[1] * fitted)
    variance *= np.mean(raw / variance)
    return np.sqrt(variance / np.mean(raw))


def _screen_residuals(coded: np.ndarray, observed: np.ndarray, terms, df: int) -> dict[str, np.ndarray]:
    """The studentised residuals the screen judges: against the scatter at each run's level from
    :data:`LOCAL_SCALE_MIN_DF` residual degrees of freedom on (the leave-one-out scale the screen derives as
    residual / student then follows the level too)."""
    infl = studentised_residuals(coded, observed, terms)
    if df >= LOCAL_SCALE_MIN_DF:
        infl["student_resid"] = infl["student_resid"] / local_scale(observed - infl["residual"], infl["residual"],
                                                                    infl["leverage"])
    return infl


def likely_typos(validated, spec: MaterialSpec, printed: pd.DataFrame | None = None, *,
                 family_alpha: float = 0.05, kinds=("transposition", "decimal_shift", "sign_lost")) -> list[dict]:
    """Response cells that look mistyped even without published statistics.

    A run is flagged when its externally studentised residual is extreme after a
    Bonferroni correction over the runs (family-wise ``family_alpha``) *and* a digit
    swap, misplaced decimal point or lost sign of the printed cell lands within three
    leave-one-out standard errors of the prediction from the other runs (three exactly included).  Both
    conditions together keep this silent on clean tables.  With :data:`LOCAL_SCALE_MIN_DF` residual degrees
    of freedom or more, residual and prediction error are measured against the scatter at the run's level
    (:func:`local_scale`), so that a scatter growing with the response does not read as slips.
    """
    from ..design import model_units, quadratic_terms

    factors, log_factors = spec.factor_names, spec.log_factors
    terms = quadratic_terms(len(factors))
    table = validated.table
    flags = []
    for response in spec.response_names:
        ok = np.isfinite(table[response].to_numpy(dtype=float))  # failed runs do not enter the fit
        sub = table.loc[ok]
        n, p = len(sub), len(terms)
        df = n - p - 1
        if df < 1:
            continue
        observed = sub[response].to_numpy(dtype=float)
        coded = validated.coding.to_coded(model_units(sub[factors].to_numpy(dtype=float), factors, log_factors))
        infl = _screen_residuals(coded, observed, terms, df)
        runs = sub["run"].to_numpy()  # a validated table always has its run column
        pvals = two_sided_t_p(infl["student_resid"], df) * n
        for i in np.flatnonzero(pvals < family_alpha):
            h, residual, student = infl["leverage"][i], infl["residual"][i], infl["student_resid"][i]
            loo_pred = observed[i] - residual / (1 - h)
            s_loo = abs(residual / student) / np.sqrt(1 - h) if student else 0.0
            se = s_loo * np.sqrt(1 + h / (1 - h))  # prediction error of the run from the others (at its level)
            run = runs[i]
            if printed is not None:
                text = printed.loc[table["run"].to_numpy() == run, response].iloc[0]
            else:
                text = repr(float(observed[i]))
            # A digit dropped from a column printed to two decimals leaves no third one to restore: without
            # that rule, inserted digits (60.941 for 60.41) cover the values around any cell and every
            # outlier would read as a slip.
            places = _decimal_places(printed[response].to_numpy()[ok] if printed is not None else [])

            def possible(kind, candidate):
                return kind != "digit_dropped" or places is None or cell_decimals(candidate) <= places

            # Of the repairs that fit, the commonest slip (KINDS order), then the closest: a centre run's
            # 500.3 is 50.03 with the point shifted even if a digit swap, 50.3, happens to land closer.
            fitting = [(_KIND_RANK[kind], abs(value - loo_pred), kind, value)
                       for kind, candidate, value in single_cell_slips(str(text))
                       if kind in kinds and abs(value - loo_pred) <= 3 * se and possible(kind, candidate)]
            best = min(fitting)[1:] if fitting else None
            if best is not None:
                # Other slips that fit, more than twice the prediction's error from the named one: those that
                # fit better by more than that error, and those of a slip as common (61.31 beside 62.31 for
                # 6.31). The named repair is then a guess among them, and the message says so.  (Nearer rivals
                # would be found for one true decimal shift in six: dropped digits cover the window densely.)
                repairs = single_cell_slips(str(text)) + added_digit_repairs(str(text))
                rivals, seen = [], set()
                for distance, value, kind in sorted(
                        (abs(value - loo_pred), value, kind) for kind, candidate, value in repairs
                        if abs(value - loo_pred) <= 3 * se and abs(value - best[2]) > 2 * se
                        and possible(kind, candidate)
                        and (abs(value - loo_pred) < best[0] - se
                             or _KIND_RANK.get(kind, len(KINDS)) <= _KIND_RANK[best[1]])):
                    if value not in seen:  # 101.5 from 1001.5 by two keystrokes is one repair
                        seen.add(value)
                        rivals.append((distance, value, kind))
                flags.append({"run": _jsonable(run), "column": response, "found": float(observed[i]),
                              "suggested": best[2], "kind": best[1], "student_resid": float(student),
                              "other_repairs": [{"value": value, "kind": kind} for _, value, kind in rivals],
                              "predicted_from_other_runs": float(loo_pred), "prediction_se": float(se),
                              "message": f"{spec.data}, run {_jsonable(run)}, column '{response}': "
                                         f"{text} is far from the fit of the other runs (studentised residual "
                                         f"{student:.1f}, predicted {loo_pred:.4g}); "
                                         f"{best[2]:g} ({best[1].replace('_', ' ')}) would fit — likely typo"})
    return flags


def _shortest(value: float) -> str:
    return np.format_float_positional(float(value), trim="-")


def repair_explains(flag: dict, share: float = 0.2) -> bool:
    """The repair removes most of the run's miss: a large slip, not a digit shuffle of a noisy value."""
    predicted = flag["predicted_from_other_runs"]
    return abs(flag["suggested"] - predicted) <= share * abs(flag["found"] - predicted)


def refuse_likely_typos(validated, spec: MaterialSpec, printed: pd.DataFrame) -> list[dict]:
    """Stop on a response cell that is far off the other runs' fit *and* reads like a digit-level slip.

    ``validated`` is the material's :class:`~demid.data.ValidatedTable`, ``printed`` its cells as printed
    (:func:`demid.data.read_printed`).  A value the user has confirmed under ``confirmed_values`` passes;
    the confirmed flags are returned so they can still be shown.  Raises InputError naming the file, run
    and column.
    """
    from pathlib import Path

    src = str(Path(spec.data))
    key = f"materials.{spec.name}.confirmed_values"
    runs = set(int(r) for r in validated.table["run"])
    for run, column in spec.confirmed_values:
        if column not in spec.response_names:
            raise InputError(f"config key {key}: '{column}' is not a response of this material "
                             f"(responses: {', '.join(spec.response_names)})", source=src)
        if run not in runs:
            raise InputError(f"config key {key}: run {run} is not in the table", source=src)
    confirmed = set(spec.confirmed_values)
    # Stopping a run needs stronger evidence than the report's warning (family-wise 1 %, not 5 %).
    # A dropped digit stops the run too (29.4 for 129.4); the report's screen keeps its three kinds.
    flags = likely_typos(validated, spec, printed, family_alpha=0.01,
                         kinds=("transposition", "decimal_shift", "sign_lost", "digit_dropped"))
    for flag in flags:
        run, column = int(flag["run"]), flag["column"]
        if (run, column) in confirmed or not repair_explains(flag):
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
    others = flag.get("other_repairs", [])
    if not others:
        return ""
    named = [f"{_shortest(c['value'])} ({SLIP_WORDS[c['kind']]})" for c in others[:2]]
    shown = (", ".join(named) + f" and {len(others) - 2} more" if len(others) > 2 else " and ".join(named))
    return (f" after checking it against the source: {shown} {'fits' if len(others) == 1 else 'fit'} the other "
            f"runs as well (predicted {flag['predicted_from_other_runs']:.4g})")

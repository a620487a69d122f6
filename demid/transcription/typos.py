"""Single-cell slips a typist makes, and the validator's likely-typo flag.

:func:`single_cell_slips` lists every edit of one printed cell (sign lost, decimal shift,
transposition, doubled, dropped or substituted digit); :func:`likely_typos` flags runs whose
extreme studentised residual a slip would explain, even without published statistics.
"""

from __future__ import annotations

import math
from decimal import Decimal, InvalidOperation
from typing import TYPE_CHECKING

import numpy as np

from ..spec import as_spec
from .printed import _jsonable

if TYPE_CHECKING:
    import pandas as pd


# Priority order (fewer keystrokes first); also the tie-break among equal repairs.
KINDS = ("sign_lost", "decimal_shift", "transposition", "digit_doubled", "digit_dropped", "digit_substitution")


_KIND_RANK = {kind: i for i, kind in enumerate(KINDS)}


_ALL_DIGITS = "0123456789"


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


def likely_typos(validated, material, printed: pd.DataFrame | None = None, *,
                 family_alpha: float = 0.05, kinds=("transposition", "decimal_shift", "sign_lost")) -> list[dict]:
    """Response cells that look mistyped even without published statistics.

    A run is flagged when its externally studentised residual is extreme after a
    Bonferroni correction over the runs (family-wise ``family_alpha``) *and* a digit
    swap, misplaced decimal point or lost sign of the printed cell lands within three
    leave-one-out standard errors of the prediction from the other runs.  Both
    conditions together keep this silent on clean tables.
    """
    from scipy import stats as _stats

    from ..surrogate import fit_response

    spec = as_spec(material)
    factors, log_factors = spec.factor_names, spec.log_factors
    table = validated.table
    flags = []
    for response in spec.response_names:
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
                              "message": f"{spec.data}, run {_jsonable(run)}, column '{response}': "
                                         f"{text} is far from the fit of the other runs (studentised residual "
                                         f"{row['student_resid']:.1f}, predicted {loo_pred:.4g}); "
                                         f"{best[2]:g} ({best[1].replace('_', ' ')}) would fit — likely typo"})
    return flags

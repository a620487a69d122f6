"""Which surrogate a simulated wave's sets use, per response: the quadratic or universal kriging, by measurement.

The first wave's model, and the model of every study demid did not simulate, is the reference paper's
quadratic.  From the second wave of a simulated study on, each response is also fitted by universal kriging
(:mod:`demid.kriging`) on every run so far over the search range Omega, and kriging judges that wave's sets
when its leave-one-out Q² is higher by a margin (:data:`CHOICE_PRESS_RATIO`; a tie keeps the quadratic).  The quadratic
stays the model of everything that needs its coefficients (the ANOVA, the canonical analysis, the criticism).

The choice is stored in the wave's fit statistics (:data:`CHOICE_COLUMNS`): per response the surrogate used,
both Q² and the kriging hyper-parameters, from which :func:`chosen_surrogates` rebuilds the same surrogates
for the next wave's placement without a new likelihood search.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from .kriging import KIND, QUADRATIC, KrigingSurrogate, quadratic_trend
from .precision import q2_text

#: Kriging is used only when its leave-one-out squared error (PRESS) is at most this share of the quadratic's,
#: i.e. 1 - Q²_kriging <= CHOICE_PRESS_RATIO (1 - Q²_quadratic): a tie keeps the paper's model.  On a truly
#: quadratic response with noise kriging's PRESS came within 0.75-1.17 of the quadratic's (its hyper-parameters
#: are fitted to the same runs, so its leave-one-out error is a little optimistic); on a saturating one at
#: 0.03-0.21 (tests/test_kriging.py's responses, 6 seeds each).  A margin on the unexplained share rather than on
#: Q² itself: a quadratic with Q² 0.99 can still miss by a tolerance band that kriging meets.
CHOICE_PRESS_RATIO = 0.5
#: Where the quadratic misfits, kriging judges the sets on a smaller gain, :data:`MISFIT_PRESS_RATIO`.  Misfit is
#: measured against the runs' own scatter where replicates give one (lack of fit against pure error, p at most
#: :data:`MISFIT_P`), else by a leave-one-out Q² below :data:`QUADRATIC_ADEQUATE_Q2` (a tenth of the variation
#: between runs left unexplained).  Measured on benchmarks/loop_vs_lhs.py: the half margin alone kept the quadratic
#: on a ridge with Q² 0.3-0.5 against kriging's 0.6-0.7 (set errors 3.5 against 1.2-1.4); a Q² below 0.9 alone as
#: the sign of misfit also took kriging on near-quadratic crossing bands whose Q² fell below 0.9 through noise of
#: a band (set error 0.19 -> 0.40): scatter, not misfit, which the lack-of-fit test tells apart.
MISFIT_P = 0.05
QUADRATIC_ADEQUATE_Q2 = 0.9
MISFIT_PRESS_RATIO = 0.8
#: Above this many runs kriging is not fitted (its cost grows as the cube of the runs); the quadratic is kept.
KRIGING_MAX_RUNS = 1000
#: The columns the choice adds to a wave's fit statistics.
CHOICE_COLUMNS = ["surrogate", "q2_quadratic", "q2_kriging", "kriging_hyperparameters"]


@dataclass
class SurrogateChoice:
    """The surrogates a wave's sets use (response -> surrogate) and the statistics frame with the choice."""

    surrogates: dict
    statistics: pd.DataFrame


def response_runs(table: pd.DataFrame, factors, response: str) -> tuple[np.ndarray, np.ndarray]:
    """The runs a response is fitted to: not failed, the response finite (as the quadratic's fit)."""
    keep = np.isfinite(table[response].to_numpy(dtype=float))
    if "status" in table:
        keep &= (table["status"] != "failed").to_numpy()
    return table.loc[keep, list(factors)].to_numpy(dtype=float), table.loc[keep, response].to_numpy(dtype=float)


def kriging_fits(n_runs: int, spec) -> bool:
    """Whether there are runs enough (and not too many) for a kriging surrogate: more than two residual degrees of
    freedom beyond its quadratic trend (n - p >= 3), at most :data:`KRIGING_MAX_RUNS`."""
    trend = quadratic_trend(np.zeros((1, spec.dim))).shape[1]
    return trend + 2 < n_runs <= KRIGING_MAX_RUNS


def fit_kriging(table: pd.DataFrame, spec, response: str, hyperparameters: str | None = None) -> KrigingSurrogate:
    """The kriging surrogate of ``response`` on ``table``'s runs over the search range of ``spec``: fitted, or
    rebuilt from stored ``hyperparameters``."""
    x, y = response_runs(table, spec.factor_names, response)
    lower, upper = spec.domain.search_bounds()
    if hyperparameters:
        return KrigingSurrogate.from_hyperparameters(response, spec.factor_names, x, y, lower, upper,
                                                     hyperparameters, spec.log_factors)
    return KrigingSurrogate.fit(response, spec.factor_names, x, y, lower, upper, spec.log_factors)


def prefers_kriging(q2_quadratic: float, q2_kriging: float, lof_p: float = float("nan")) -> bool:
    """Kriging judges the sets when its Q² is defined and its unexplained share 1 - Q² is at most
    :data:`CHOICE_PRESS_RATIO` of the quadratic's, or at most :data:`MISFIT_PRESS_RATIO` of it where the quadratic
    misfits (:func:`quadratic_misfits`), or the quadratic's Q² is undefined (a run alone fixes it)."""
    if not np.isfinite(q2_kriging):
        return False
    if not np.isfinite(q2_quadratic):
        return True
    return (1.0 - q2_kriging) <= required_ratio(q2_quadratic, lof_p) * (1.0 - q2_quadratic)


def quadratic_misfits(q2_quadratic: float, lof_p: float = float("nan")) -> bool:
    """Whether the quadratic misfits: lack of fit against pure error at p <= :data:`MISFIT_P` where replicates
    give the test, else a leave-one-out Q² below :data:`QUADRATIC_ADEQUATE_Q2`."""
    if np.isfinite(lof_p):
        return lof_p <= MISFIT_P
    return q2_quadratic < QUADRATIC_ADEQUATE_Q2


def required_ratio(q2_quadratic: float, lof_p: float = float("nan")) -> float:
    """The share of the quadratic's leave-one-out error kriging must come within to judge the sets."""
    return MISFIT_PRESS_RATIO if quadratic_misfits(q2_quadratic, lof_p) else CHOICE_PRESS_RATIO


def choose_surrogates(table: pd.DataFrame, spec, quadratic: dict, statistics: pd.DataFrame) -> SurrogateChoice:
    """Per response of ``spec``, the quadratic (``quadratic``: its surrogates, ``statistics``: its fit
    statistics with ``q2``) or kriging, whichever predicts left-out runs better by the margin of :func:`prefers_kriging`."""
    q2_quadratic = dict(zip(statistics["response"], statistics["q2"].astype(float)))
    lof_p = dict(zip(statistics["response"], statistics["lof_p"].astype(float))) if "lof_p" in statistics else {}
    chosen, rows = dict(quadratic), []
    for response in statistics["response"]:
        x, _ = response_runs(table, spec.factor_names, response)
        kriging = fit_kriging(table, spec, response) if kriging_fits(len(x), spec) else None
        q2_k = kriging.q2 if kriging is not None else float("nan")
        use = KIND if kriging is not None and prefers_kriging(q2_quadratic[response], q2_k,
                                                                         lof_p.get(response, float("nan"))) else QUADRATIC
        if use == KIND:
            chosen[response] = kriging
        rows.append({"surrogate": use, "q2_quadratic": q2_quadratic[response], "q2_kriging": q2_k,
                     "kriging_hyperparameters": kriging.hyperparameters_json() if kriging is not None else ""})
    return SurrogateChoice(chosen, pd.concat([statistics.reset_index(drop=True),
                                              pd.DataFrame(rows, columns=CHOICE_COLUMNS)], axis=1))


def chosen_surrogates(table: pd.DataFrame, spec, quadratic: dict, statistics: pd.DataFrame | None) -> dict:
    """The surrogates a wave's sets used, rebuilt from its stored statistics (:func:`choose_surrogates`'s
    columns; without them every response keeps the quadratic)."""
    if statistics is None or "surrogate" not in statistics:
        return dict(quadratic)
    out = dict(quadratic)
    for row in statistics.itertuples():
        if row.surrogate == KIND:
            out[row.response] = fit_kriging(table, spec, row.response, row.kriging_hyperparameters)
    return out


def used_q2(row) -> float:
    """The Q² of the surrogate a response's sets use (a statistics row, with or without the choice)."""
    if getattr(row, "surrogate", QUADRATIC) == KIND:
        return float(row.q2_kriging)
    return float(row.q2)


def choice_text(response_label: str, row) -> str:
    """One response's choice in words, e.g. "θ by kriging (Q² 0.81 against the quadratic's 0.42)"."""
    if getattr(row, "surrogate", QUADRATIC) != KIND:
        if "q2_kriging" in getattr(row, "_fields", ()) and np.isfinite(row.q2_kriging):
            return (f"{response_label} by the quadratic (Q² {q2_text(float(row.q2))}: kriging's {q2_text(row.q2_kriging)} "
                    f"does not cut the leave-one-out error to "
                    f"{required_ratio(float(row.q2), float(getattr(row, 'lof_p', float('nan')))):g} of the quadratic's)")
        return f"{response_label} by the quadratic (Q² {q2_text(float(row.q2))})"
    return f"{response_label} by kriging (Q² {q2_text(row.q2_kriging)} against the quadratic's {q2_text(float(row.q2))})"


def surrogate_record(row) -> dict:
    """One response's choice for the waves summary: the surrogate used and both Q² (None where undefined or
    not fitted)."""
    def number(v):
        return float(v) if v is not None and np.isfinite(v) else None

    return {"used": getattr(row, "surrogate", QUADRATIC), "q2_quadratic": number(float(row.q2)),
            "q2_kriging": number(getattr(row, "q2_kriging", None))}


#: The key a kriging-judged response gets in the criticism's level-1 entry (``criticism/<material>.json``): the
#: criticism is of the quadratic, and its "does not predict" is about the quadratic, not about the sets.
SETS_SURROGATE_KEY = "sets_surrogate"


def mark_criticism(summary: dict, statistics: pd.DataFrame) -> None:
    """Tell the criticism summary's level-1 entries which responses' sets kriging judged, with its Q², so the
    advice and the report do not call those sets untrustworthy for the quadratic's Q² alone."""
    level1 = summary.get("level1") or {}
    for row in statistics.itertuples():
        if getattr(row, "surrogate", QUADRATIC) == KIND and row.response in level1:
            level1[row.response][SETS_SURROGATE_KEY] = {"surrogate": KIND, "q2": float(row.q2_kriging)}


def sets_do_not_predict(level1_entry: dict) -> bool:
    """Whether a response's sets rest on a surrogate that does not predict left-out runs (Q² < 0): the
    criticism's ``does_not_predict`` verdict of the quadratic, unless kriging judged the sets and predicts."""
    if level1_entry.get("verdict") != "does_not_predict":
        return False
    used = level1_entry.get(SETS_SURROGATE_KEY)
    return not (used and used.get("q2") is not None and used["q2"] >= 0)

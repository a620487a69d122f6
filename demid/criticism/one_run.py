"""Does a cause that describes the whole design rest on one run?

Unequal scatter, a missing term, a response transform or drift describes every run.  A defect outside the
catalogue (a batch of shifted runs, an unrecorded factor that moved one or two runs far, a step) often
gets such a name from one wild run: the cause's test is then significant with that run and not without
it.  :func:`worst_deletion` redoes the cause's own test with each run left out in turn.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from ..design import model_matrix
from .catalogue import _Round, _added_variable_stats, _f_logp, _het_lr
from .models import _orth, _residualize

if TYPE_CHECKING:
    from .catalogue import _Hypothesis
    from .models import _Data, _Model

#: Causes that describe the whole design (outliers and slipped runs are one run by nature).
WHOLE_DESIGN = ("missing_term", "response_transform", "heteroscedasticity", "drift")


@dataclass(frozen=True)
class Deletion:
    """The run whose deletion weakens a cause's test most, and the test's nominal p without it."""

    row: int  # index into the data
    p_without: float


def deleted_logp(data: _Data, model: _Model, h: _Hypothesis, y: np.ndarray) -> np.ndarray:
    """Nominal log p (runs, B) of cause h's test on response columns y (the model's kept runs, B) with each
    run left out in turn: the one-parameter tests in their F form, as ranked in catalogue._Round (the
    likelihood ratios of unequal scatter and Box-Cox through (df - 1)(exp(LR / n) - 1) ~ F(1, df - 1))."""
    n = len(y)
    out = np.zeros((n, y.shape[1]))
    column = None
    if h.cause == "missing_term":
        column = model_matrix(model.coded, [h.detail.terms[0]])[:, 0]
    elif h.cause == "drift":
        column = model.run_column(model.keep)
    for pos in range(n):
        keep = np.arange(n) != pos
        q = _orth(model.x[keep])
        df = int(keep.sum()) - q.shape[1]
        if df < 3:
            continue
        if column is not None:
            u = _residualize(q, column[keep, None])[:, 0]
            if np.linalg.norm(u) <= 1e-7 * max(np.linalg.norm(column), 1e-300):
                continue  # the term is not estimable without this run
            stat = _added_variable_stats(_residualize(q, y[keep]), u / np.linalg.norm(u), df - 1)
            out[pos] = _f_logp(stat, df - 1)
            continue
        if h.cause == "response_transform":
            lr = _Round._boxcox_lr(y[keep], q)
        else:
            lr = _het_lr(y[keep], model.x[keep], _covariate(data, model, h, keep, q))
        out[pos] = _f_logp((df - 1) * np.expm1(lr / (n - 1)), df - 1)
    return out


def _covariate(data: _Data, model: _Model, h: _Hypothesis, keep: np.ndarray, q: np.ndarray) -> np.ndarray:
    """The variance covariate on the remaining runs, scaled as in catalogue._Round.covariates."""
    if h.detail != "fitted":
        return data.coded[model.keep, data.factors.index(h.detail)][keep] / data.alpha
    z = model.z[keep]
    fitted = z - _residualize(q, z[:, None])[:, 0]
    return (fitted - (fitted.max() + fitted.min()) / 2) / max(np.ptp(fitted) / 2, 1e-300)


def worst_deletion(data: _Data, model: _Model, h: _Hypothesis) -> Deletion | None:
    """The run without which cause h's test on ``model``'s runs is weakest (None for causes of one run and
    for weighted models, whose tests are not run)."""
    if h.cause not in WHOLE_DESIGN or model.spec.weight_on is not None:
        return None
    logp = deleted_logp(data, model, h, model.z[:, None])[:, 0]
    pos = int(np.argmax(logp))
    return Deletion(int(np.flatnonzero(model.keep)[pos]), float(math.exp(logp[pos])))

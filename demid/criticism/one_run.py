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

from ..design import LEVERAGE_UNPREDICTABLE, model_matrix
from ..surrogate import LOO_REFIT_MAX_RUNS
from .catalogue import Round, added_variable_stats, f_logp, heteroscedasticity_lr
from .models import orthonormal_basis, residualize

if TYPE_CHECKING:
    from .catalogue import Hypothesis
    from .models import Data, Model

#: Causes that describe the whole design (outliers and slipped runs are one run by nature).
WHOLE_DESIGN = ("missing_term", "response_transform", "heteroscedasticity", "drift")


@dataclass(frozen=True)
class Deletion:
    """The run whose deletion weakens a cause's test most, and the test's nominal p without it."""

    row: int  # index into the data
    p_without: float


def deleted_logp(data: Data, model: Model, h: Hypothesis, y: np.ndarray, positions=None) -> np.ndarray:
    """Nominal log p (runs, B) of cause h's test on response columns y (the model's kept runs, B) with each
    run left out in turn: the one-parameter tests in their F form, as ranked in catalogue.Round (the
    likelihood ratios of unequal scatter and Box-Cox through (df - 1)(exp(LR / n) - 1) ~ F(1, df - 1))."""
    n = len(y)
    out = np.zeros((n, y.shape[1]))
    column = None
    if h.cause == "missing_term":
        column = model_matrix(model.coded, [h.detail.terms[0]])[:, 0]
    elif h.cause == "drift":
        column = model.run_column(model.keep)
    for pos in range(n) if positions is None else positions:
        keep = np.arange(n) != pos
        q = orthonormal_basis(model.x[keep])
        df = int(keep.sum()) - q.shape[1]
        if df < 3:
            continue
        if column is not None:
            u = residualize(q, column[keep, None])[:, 0]
            if np.linalg.norm(u) <= 1e-7 * max(np.linalg.norm(column), 1e-300):
                continue  # the term is not estimable without this run
            stat = added_variable_stats(residualize(q, y[keep]), u / np.linalg.norm(u), df - 1)
            out[pos] = f_logp(stat, df - 1)
            continue
        if h.cause == "response_transform":
            lr = Round._boxcox_lr(y[keep], q)
        else:
            lr = heteroscedasticity_lr(y[keep], model.x[keep], _covariate(data, model, h, keep, q))
        out[pos] = f_logp((df - 1) * np.expm1(lr / (n - 1)), df - 1)
    return out


def deleted_logp_by_identity(data: Data, model: Model, h: Hypothesis, y: np.ndarray) -> np.ndarray:
    """:func:`deleted_logp` for a missing term, drift or a response transform from the one fit with every run,
    not a fit per run left out (n fits of n runs: hours at 10,000 runs).  For residuals a, b of the model
    (leverage h_i), the fit without run i has a_(i)'b_(i) = a'b - a_i b_i / (1 - h_i): the residual sums of
    squares and the added variable's projection, at each lambda for Box-Cox.  Runs of leverage near 1
    (whose deletion lowers the rank) are refitted as before."""
    n = len(y)
    q = orthonormal_basis(model.x)
    leverage = np.sum(q * q, axis=1)
    near_one = np.flatnonzero(leverage >= LEVERAGE_UNPREDICTABLE)
    lever = np.where(leverage >= LEVERAGE_UNPREDICTABLE, 1.0, 1.0 - leverage)[:, None]  # near 1: refitted below
    df = n - 1 - q.shape[1]
    out = np.zeros((n, y.shape[1]))
    if h.cause == "response_transform":
        from .catalogue import _LAMBDA_TEST_GRID, boxcox_profile

        def deleted_profile(lam):  # boxcox_profile without each run, (n, B)
            z = np.log(y) if lam == 0 else np.expm1(lam * np.log(y)) / lam
            r = residualize(q, z)
            sse = np.maximum(np.sum(r * r, axis=0)[None, :] - r * r / lever, 1e-300)
            return -0.5 * (n - 1) * np.log(sse / (n - 1)) + (lam - 1.0) * (np.log(y).sum(axis=0) - np.log(y))

        profiles = np.array([deleted_profile(lam) for lam in _LAMBDA_TEST_GRID])
        one = int(np.flatnonzero(_LAMBDA_TEST_GRID == 1.0)[0])
        lr = 2.0 * (profiles.max(axis=0) - profiles[one])
        out = f_logp((df - 1) * np.expm1(lr / (n - 1)), df - 1)
    else:
        column = (model_matrix(model.coded, [h.detail.terms[0]])[:, 0] if h.cause == "missing_term"
                  else model.run_column(model.keep))[:, None]
        e, rc = residualize(q, y), residualize(q, column)
        sse = np.sum(e * e, axis=0)[None, :] - e * e / lever
        u2 = float(rc[:, 0] @ rc[:, 0]) - rc * rc / lever
        proj2 = (rc[:, 0] @ e - rc * e / lever) ** 2 / np.maximum(u2, 1e-300)
        with np.errstate(divide="ignore", invalid="ignore"):
            stat = proj2 * (df - 1) / np.maximum(sse - proj2, 1e-300 * np.maximum(sse, 1e-300))
        # relative to the whole column, as deleted_logp's refits: the two agree on every run
        estimable = np.sqrt(np.maximum(u2, 0.0)) > 1e-7 * np.linalg.norm(column)
        out = np.where(estimable, f_logp(stat, df - 1), 0.0)
    if len(near_one):
        out[near_one] = deleted_logp(data, model, h, y, near_one)[near_one]
    return out if df >= 3 else np.zeros_like(out)


def _covariate(data: Data, model: Model, h: Hypothesis, keep: np.ndarray, q: np.ndarray) -> np.ndarray:
    """The variance covariate on the remaining runs, scaled as in catalogue.Round.covariates."""
    if h.detail != "fitted":
        return data.coded[model.keep, data.factors.index(h.detail)][keep] / data.alpha
    z = model.z[keep]
    fitted = z - residualize(q, z[:, None])[:, 0]
    return (fitted - (fitted.max() + fitted.min()) / 2) / max(np.ptp(fitted) / 2, 1e-300)


def worst_deletion(data: Data, model: Model, h: Hypothesis) -> Deletion | None:
    """The run without which cause h's test on ``model``'s runs is weakest (None for causes of one run and
    for weighted models, whose tests are not run)."""
    if h.cause not in WHOLE_DESIGN or model.spec.weight_on is not None:
        return None
    positions = None
    if h.cause == "heteroscedasticity" and len(model.z) > LOO_REFIT_MAX_RUNS:
        positions = _weakest_by_identity(data, model, h)
    if h.cause != "heteroscedasticity" and len(model.z) > LOO_REFIT_MAX_RUNS:
        logp = deleted_logp_by_identity(data, model, h, model.z[:, None])[:, 0]
    else:
        logp = deleted_logp(data, model, h, model.z[:, None], positions)[:, 0]
    if positions is not None:
        logp = np.where(np.isin(np.arange(len(logp)), positions), logp, -np.inf)
    pos = int(np.argmax(logp))
    return Deletion(int(np.flatnonzero(model.keep)[pos]), float(math.exp(logp[pos])))


#: Above LOO_REFIT_MAX_RUNS runs, the test of unequal scatter is redone without each of this many runs only.
SCREENED_RUNS = 32


def _weakest_by_identity(data: Data, model: Model, h: Hypothesis) -> np.ndarray:
    """The :data:`SCREENED_RUNS` runs whose deletion most weakens the test of unequal scatter, ranked with the
    covariate of all runs held fixed: then each weighted fit without run i follows from the fit with it
    (SSE_(i) = SSE - e_i^2 / (1 - h_i)), one fit per variance slope for all runs instead of one per run and
    slope (n^2 work: hours at 10,000 runs).  :func:`deleted_logp` then redoes the exact test for these runs."""
    from .catalogue import GAMMA_GRID

    n, y, x = len(model.z), model.z, model.x
    covariate = _covariate(data, model, h, np.ones(n, dtype=bool), orthonormal_basis(x))
    prof = np.empty((len(GAMMA_GRID), n))
    for i, g in enumerate(GAMMA_GRID):
        sw = np.exp(-0.5 * g * covariate)
        q = orthonormal_basis(x * sw[:, None])
        r = residualize(q, (y * sw)[:, None])[:, 0]
        leverage = np.sum(q * q, axis=1)
        with np.errstate(divide="ignore", invalid="ignore"):
            sse = np.maximum(float(r @ r) - r * r / (1.0 - leverage), 1e-300)
            prof[i] = -0.5 * (n - 1) * np.log(sse / (n - 1)) + float(np.sum(np.log(sw))) - np.log(sw)
    zero = int(np.argmin(np.abs(GAMMA_GRID)))
    lr = 2.0 * (np.nanmax(prof, axis=0) - prof[zero])
    return np.sort(np.argsort(lr, kind="stable")[:SCREENED_RUNS])

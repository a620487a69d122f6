"""Each catalogue cause's one-parameter extension of a model, and a cause as the findings and the catalogue
table write it.

:func:`extend_for` turns a :class:`~demid.criticism.catalogue.Hypothesis` into the
:class:`~demid.criticism.models.ModelForm` that answers it (an extra term, a transform, an excluded run,
weights, a drift or a step, a moved factor value), with the facts its message quotes.
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import TYPE_CHECKING

import numpy as np
from scipy import optimize, stats

from ..design import model_matrix
from .catalogue import ASYMPTOTIC_RUNS, GAMMA_BOUND, LAMBDA_FINE_GRID, NICE_LAMBDAS, boxcox_profile, weighted_sse
from .models import TRANSFORM_NAMES, Data, Model, ModelForm, json_number, orthonormal_basis, run_label

if TYPE_CHECKING:
    from .catalogue import Hypothesis

#: Causes that describe the run order: a linear drift or a step between two groups of runs.
RUN_ORDER_CAUSES = ("drift", "step")


def extend_for(data: Data, model: Model, h: Hypothesis) -> tuple[ModelForm, dict]:
    """Extension of ``model.spec`` that answers hypothesis h, and facts for the message."""
    spec = model.spec
    info: dict = {}
    if h.cause == "missing_term":
        return replace(spec, extra_terms=spec.extra_terms + (h.detail.terms[0],)), info
    if h.cause == "drift":
        return replace(spec, drift=True), info
    if h.cause == "step":
        return replace(spec, step=int(h.detail)), info
    if h.cause == "factor_level":
        c = h.detail
        row = model.coded[int(np.flatnonzero(np.flatnonzero(model.keep) == c.row)[0])].copy()
        recorded = float(data.to_actual(row)[0, c.factor])
        row[c.factor] = c.coded
        info.update(factor=data.factors[c.factor], recorded_value=recorded,
                    fitting_value=float(data.to_actual(row)[0, c.factor]), slip=f"x1e{c.power:+d}",
                    t_moved=h.info["t_moved"], bayes_factor=h.info["bayes_factor"],
                    t_recorded=h.info["t_recorded"], observed=float(data.y[c.row]))
        return replace(spec, moved=spec.moved + ((c.row, c.factor, c.coded),)), info
    if h.cause == "outlier":
        i = int(h.detail)
        pos = int(np.flatnonzero(np.flatnonzero(model.keep) == i)[0])
        info["observed"] = float(data.y[i])
        info["predicted_without"] = float(data.y[i] - model.loo_errors[pos])
        return replace(spec, dropped=spec.dropped + (i,)), info
    if h.cause == "response_transform":
        q = orthonormal_basis(model.xw)
        prof = boxcox_profile(model.y[:, None], q, LAMBDA_FINE_GRID)[:, 0]
        best = int(np.argmax(prof))
        lam_hat = float(LAMBDA_FINE_GRID[best])
        # Small-sample 95 % interval: the likelihood ratio in F form, F = df (exp(LR/n) - 1) ~ F(1, df)
        # (the chi-square(1) interval is far too narrow at a dozen runs).
        n, df = len(model.y), model.df_resid - 1
        f_ratio = df * np.expm1(2 * (prof[best] - prof) / n)
        inside = LAMBDA_FINE_GRID[f_ratio <= stats.f.ppf(0.95, 1, df)]
        lo, hi = float(inside.min()), float(inside.max())
        # The transform used is the first convenient lambda (log, sqrt, inverse, then others)
        # that the data do not reject at the 1 % level; otherwise lambda-hat to one decimal.
        plausible = LAMBDA_FINE_GRID[f_ratio <= stats.f.ppf(0.99, 1, df)]
        lo99, hi99 = float(plausible.min()), float(plausible.max())
        lam = next((v for v in (*TRANSFORM_NAMES, *NICE_LAMBDAS) if lo99 <= v <= hi99), round(lam_hat, 1))
        # one decimal may land on no transform at all, or on a named one the data reject (0.04 -> the log, with
        # the log outside the 99 % interval): lambda-hat to two decimals then
        if abs(lam - 1.0) < 1e-9 or (lam in TRANSFORM_NAMES and not lo99 <= lam <= hi99):
            lam = round(lam_hat, 2)
        info.update(lambda_hat=lam_hat, lambda_ci=[lo, hi])
        return replace(spec, lam=float(lam)), info
    if h.cause == "heteroscedasticity":
        if h.detail == "fitted":  # excluded runs: their predicted value at the average run, same scaling
            k = len(model.mean_terms)
            fz_all = model_matrix(data.coded, model.mean_terms) @ model.beta[:k]
            if data.blocks is not None:
                fz_all = fz_all + data.blocks @ model.beta[k:k + data.blocks.shape[1]]
            fz = model.fitted_z
            fz_all[model.keep] = fz  # the kept runs' covariate is the one tested (drift, step and moved values too)
            values = (fz_all - (fz.max() + fz.min()) / 2) / (np.ptp(fz) / 2)
        else:
            values = data.coded[:, data.factors.index(h.detail)] / data.alpha
        base = replace(spec, weight_on=h.detail, weight_values=tuple(float(v) for v in values))

        if len(model.y) > ASYMPTOTIC_RUNS:  # the fit's sum of squares, not a model, at each step
            at_zero = Model(data, base)

            def negll(g):
                return -weighted_loglik(at_zero, float(g))
        else:
            def negll(g):
                return -Model(data, replace(base, weight_gamma=float(g))).loglik

        res = optimize.minimize_scalar(negll, bounds=(-GAMMA_BOUND, GAMMA_BOUND), method="bounded",
                                       options={"xatol": 1e-6})
        gamma = float(res.x)
        info["sd_ratio"] = float(np.exp(gamma))  # sd at covariate +1 over sd at -1
        return replace(base, weight_gamma=gamma), info
    raise ValueError(h.cause)


def weighted_loglik(at_zero: Model, gamma: float) -> float:
    """``Model(data, replace(at_zero.spec, weight_gamma=gamma)).loglik`` (the same to round-off) from the
    weighted least-squares sum of squares alone: the search for gamma evaluates it dozens of times, and a
    model (two n x p decompositions) per evaluation was most of the cost of naming unequal scatter on
    thousands of runs."""
    values = np.asarray(at_zero.spec.weight_values, dtype=float)[at_zero.keep]
    w = np.exp(-gamma * values)
    sw = np.sqrt(w)
    ssr = float(weighted_sse(at_zero.x * sw[:, None], (at_zero.z * sw)[:, None])[0])
    return at_zero.loglik_with(ssr, w, gamma)


def step_price(h: Hypothesis) -> float:
    """Log-likelihood a step pays for its change-point, chosen as the best of C positions: log C, the
    Bonferroni price its test pays too (a linear drift is then not read as a step at a dozen runs; in
    tests/criticism/test_criticism.py a 14-SD drift over 13 runs fits a step at run 9 better by 1.9).  0 for other
    causes."""
    return math.log(h.info.get("change_points", 1)) if h.cause == "step" else 0.0


def step_size(model: Model) -> float:
    """The shift of the runs after the step against those before (response units, or the transform's)."""
    return float(model.beta[model.names.index("step")])


def drift_per_run(model: Model) -> float:
    """The fitted drift of a model with a run-order term, per run (response units, or the transform's)."""
    j = model.names.index("run")
    return float(model.beta[j] / model.run_scale)


def detail_json(data: Data, h: Hypothesis):
    """What a cause concerns as the findings write it: the term, the run, the covariate, "boxcox" or ""."""
    if h.cause == "missing_term":
        return h.aliases[0]
    if h.cause == "factor_level":
        return run_label(data.runs[h.detail.row])
    if h.cause == "lack_of_fit":
        return ""
    if h.cause in ("outlier", "step"):
        return run_label(data.runs[int(h.detail)])
    if h.cause == "response_transform":
        return "boxcox"
    return h.detail


def catalogue_entry(data: Data, h: Hypothesis) -> dict:
    """A tested cause as a row of the catalogue table: its detail, aliases, statistic and p-values."""
    detail = detail_json(data, h)
    return {"cause": h.cause, "detail": detail, "aliases": list(h.aliases),
            "statistic": json_number(h.statistic), "p_nominal": json_number(np.exp(h.logp)),
            "p_family": json_number(h.p_family)}

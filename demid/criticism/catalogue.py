"""The catalogue of causes and its family-wise test (one round of level 1).

Every statistic except Box-Cox's is a function of the error vector alone, so the
joint null is simulated and the Westfall-Young step-down min-P procedure gives
family-adjusted p-values; Box-Cox joins by a parametric bootstrap.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np
from scipy import stats

from ..blocks import pure_error_groups
from ..design import cubic_terms, term_name
from ..fit_statistics import pure_error_ss
from ..precision import round_off_floor, round_off_only
from .aliasing import term_classes
from .models import orthonormal_basis, residualize
from .outliers import outlier_logp, outlier_null_max, outlier_stats
from .slips import slip_candidates, slip_fit, slip_ratios
from .step_changes import STEP_CELLS, step_direction_chunks, step_projections

if TYPE_CHECKING:
    from .aliasing import TermClass
    from .models import Data, Model


CAUSES = ("missing_term", "response_transform", "outlier", "drift", "heteroscedasticity", "factor_level", "step")


#: Family members that show misfit without naming a cause.
MISFIT_TESTS = ("lack_of_fit",)

# Further convenient lambdas, tried when the data reject none of the named ones.
NICE_LAMBDAS = (-0.5, 2.0, 1.5, -2.0, 0.25, -0.25)


_LAMBDA_TEST_GRID = np.round(np.arange(-2.0, 2.0001, 0.05), 10)


LAMBDA_FINE_GRID = np.round(np.arange(-3.0, 3.0001, 0.01), 10)


# Log-linear variance var = sigma^2 exp(gamma v), v in [-1, 1]: the sd ratio across the range is exp(gamma).
# |gamma| <= 2.5 (sd ratio 12) in the test and the fit, so that one wild run cannot pose as a trend.
# The bound is a regularisation, not a claim about the physics (a scatter growing 30-fold across the box, as
# near a jamming transition, is plausible): on a CCD the likelihood has no maximum -- weighted towards one end,
# the quadratic goes through that end's few runs, and the likelihood rises towards an infinite ratio on clean
# tables, outliers and missing terms alike (maximum likelihood and REML both run off to |gamma| = 8 there).  So
# the fitted ratio is set by the bound, whatever it is.  In benchmarks/decide_causes.py (seeds 0-19, n_null
# 199) a bound of 4.6 (ratio 100) in the fit named no more unequal scatter (0 of 40 either way) and read more
# outliers as scatter (strict wrong on 3-factor outliers 0.05 -> 0.20; named after the proposed runs 0.556 ->
# 0.439); the same bound in the test's grid lowered detection (0.816 -> 0.781) and raised wrong causes on
# off-catalogue defects (0.31 -> 0.36).  Lower or in between it trades one kind of error for another within a
# few tables (test grid at ratio 7: off-catalogue wrong 0.31 -> 0.26, catalogue strict wrong 0.042 -> 0.046;
# fit at ratio 30, the generator's own: strict wrong 0.042 -> 0.033, catalogue naming 0.579 -> 0.571), so 12
# stays.  Scatter is told from a wild run by replicates where the scatters differ (discrimination).
GAMMA_BOUND = 2.5


# =========================================================================== the catalogue
@dataclass
class Hypothesis:
    """One cause of the catalogue under test: its kind, what it concerns, the statistic and its p-values."""
    cause: str
    detail: object  # Term class / None / covariate name
    aliases: list[str] = field(default_factory=list)
    statistic: float = np.nan
    logp: float = 0.0  # log of the nominal p-value
    info: dict = field(default_factory=dict)
    null_logp: np.ndarray | None = None
    p_family: float = 1.0
    strength: float | None = None  # ranking key when it differs from logp (Box-Cox)

    @property
    def rank_key(self) -> float:
        return self.logp if self.strength is None else self.strength


def f_logp(f, df2):
    """log of the upper-tail probability of F(1, df2) at f (negative f read as 0)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        return stats.f.logsf(np.maximum(f, 0.0), 1, df2)


def added_variable_stats(e: np.ndarray, u: np.ndarray, df2: int, sse: np.ndarray | None = None):
    """F for adding unit direction u (already orthogonal to the model) to residuals e (n, B); ``sse``: the
    columns' sums of squares, when the caller has them (the same e for many directions)."""
    proj = np.einsum("i,ib->b", u, e)
    sse = np.sum(e * e, axis=0) if sse is None else sse
    with np.errstate(divide="ignore", invalid="ignore"):
        return proj ** 2 * df2 / np.maximum(sse - proj ** 2, 1e-300 * np.maximum(sse, 1e-300))


def _added_variable_stats_many(e: np.ndarray, u: np.ndarray, df2: int) -> np.ndarray:
    """F (C, B) for adding each unit column of u (n, C) to residuals e (n, B)."""
    return _f_of_projection(np.einsum("ic,ib->cb", u, e), e, df2)


def _f_of_projection(proj: np.ndarray, e: np.ndarray, df2: int) -> np.ndarray:
    """F (C, B) for adding unit directions whose projections on residuals e (n, B) are proj (C, B)."""
    sse = np.sum(e * e, axis=0)[None, :]
    with np.errstate(divide="ignore", invalid="ignore"):
        return proj ** 2 * df2 / np.maximum(sse - proj ** 2, 1e-300 * np.maximum(sse, 1e-300))


#: Above this many runs a round costs a fixed number of passes over the runs: the step test's projections come
#: from cumulative sums in run order (:func:`step_projections`), lack of fit's pure error from group sums, and
#: the two members whose null is not a cheap function of the error vector (unequal scatter: a weighted refit per
#: variance slope and null draw; Box-Cox: a parametric bootstrap) take their asymptotic p-values, the F form of
#: the likelihood ratio, and join the family as independent uniforms, as Box-Cox's bootstrap p always did.  At
#: this size the F form and the simulated null agree (tests/criticism/test_large_studies.py); on fewer runs the
#: small-sample null is simulated as before.
ASYMPTOTIC_RUNS = 256


GAMMA_GRID = np.linspace(-GAMMA_BOUND, GAMMA_BOUND, 21)


def heteroscedasticity_lr(e: np.ndarray, x: np.ndarray, covariate: np.ndarray) -> np.ndarray:
    """Likelihood ratio of var_i = sigma^2 exp(gamma z_i) against gamma = 0, for residual columns e.

    Profile log-likelihood over a gamma grid (WLS for each gamma, mean refitted);
    e may be residuals or responses, the model's column space x is projected out.
    The statistic is a function of the errors alone, so its null distribution is
    simulated exactly for the design.
    """
    n = len(covariate)
    prof = np.empty((len(GAMMA_GRID), e.shape[1]))
    for i, g in enumerate(GAMMA_GRID):
        sw = np.exp(-0.5 * g * covariate)
        sse = weighted_sse(x * sw[:, None], e * sw[:, None])
        with np.errstate(divide="ignore"):
            prof[i] = -0.5 * n * np.log(sse / n) + float(np.sum(np.log(sw)))
    zero = int(np.argmin(np.abs(GAMMA_GRID)))
    return 2.0 * (prof.max(axis=0) - prof[zero])


def weighted_sse(xw: np.ndarray, ew: np.ndarray) -> np.ndarray:
    """Residual sums of squares (B,) of the columns of ew (n, B) on the column space of xw (n, p).

    Up to ASYMPTOTIC_RUNS runs through an orthonormal basis (rank-revealing SVD); beyond, the least-squares
    coefficients from the p x p normal equations (minimum norm where columns are aliased) and the residuals
    formed from them: one pass over the runs instead of an n x p decomposition per weighting (the same sums
    to round-off, tests/criticism/test_linear_time_equivalents.py)."""
    if len(xw) <= ASYMPTOTIC_RUNS:
        r = residualize(orthonormal_basis(xw), ew)
        return np.sum(r * r, axis=0)
    coef = np.linalg.lstsq(xw.T @ xw, xw.T @ ew, rcond=None)[0]
    r = ew - xw @ coef
    return np.sum(r * r, axis=0)


def boxcox_profile(y: np.ndarray, q: np.ndarray, lams: np.ndarray) -> np.ndarray:
    """Profile log-likelihood (lams, B) of Box-Cox lambda for columns of y (n, B) > 0.

    l(lambda) = -n/2 log(SSE_lambda / n) + (lambda - 1) sum log y, SSE from the OLS fit
    on the model's column space (orthonormal basis q).
    """
    n = y.shape[0]
    logy = np.log(y)
    slog = logy.sum(axis=0)
    out = np.empty((len(lams), y.shape[1]))
    for i, lam in enumerate(lams):
        z = logy if lam == 0 else np.expm1(lam * logy) / lam
        r = residualize(q, z)
        out[i] = -0.5 * n * np.log(np.sum(r * r, axis=0) / n) + (lam - 1.0) * slog
    return out


#: Where replicated runs give pure error, the classical lack-of-fit test gets this share of the family's
#: level and the other members share the rest (weighted step-down min-P: once lack of fit is rejected its
#: share passes on).  With equal weights the omnibus test paid for ten to thirteen specific tests and
#: detected less than the lack-of-fit test alone (0.45 against 0.53 on defects outside the catalogue);
#: with 0.65 the family detects as often (benchmarks/honest_causes.py, numbers in the issue note).
LOF_SHARE = 0.65


def family_weights(causes: list[str]) -> np.ndarray:
    """Weights (mean 1) of the family members in the weighted step-down min-P test."""
    m = len(causes)
    if "lack_of_fit" not in causes or m == 1:
        return np.ones(m)
    return np.array([LOF_SHARE * m if c == "lack_of_fit" else (1 - LOF_SHARE) * m / (m - 1) for c in causes])


def weighted_stepdown(causes: list[str], obs: np.ndarray, null: np.ndarray) -> np.ndarray:
    """Family-adjusted p-values: step-down min-P on p / weight (:func:`family_weights`)."""
    shift = np.log(family_weights(causes))
    return stepdown_minp(obs - shift, null - shift)


def stepdown_minp(obs: np.ndarray, null: np.ndarray) -> np.ndarray:
    """Westfall-Young step-down min-P adjusted p-values from log p-values (m,) and (B, m)."""
    b = null.shape[0]
    order = np.argsort(obs, kind="stable")
    adj = np.empty(len(obs))
    running = 0.0
    for rank, j in enumerate(order):
        min_null = null[:, order[rank:]].min(axis=1)
        p = (1.0 + np.count_nonzero(min_null <= obs[j] + 1e-12)) / (b + 1.0)
        running = max(running, p)
        adj[j] = running
    return adj


def _lr_f_logp(lr, df: int, n: int):
    """Log p of a one-parameter likelihood ratio on the F scale, (df-1)(exp(LR/n)-1) ~ F(1, df-1): close to
    calibrated at a dozen runs, where chi-square(1) is far too liberal."""
    return f_logp((df - 1) * np.expm1(lr / n), df - 1)


def _between_groups_ss(group: np.ndarray, n_groups: int, large: bool):
    """e (n, B) -> the sum of squares of e's replicate-group means (B,), sum_g (sum_{i in g} e_i)^2 / n_g: by
    an indicator matrix (n, groups) on small tables, by group sums on large ones (that matrix is n x n when
    few runs repeat)."""
    counts = np.bincount(group, minlength=n_groups).astype(float)
    if large:
        order = np.argsort(group, kind="stable")
        bounds = np.concatenate([[0], np.cumsum(counts[:-1])]).astype(int)
        return lambda e: np.sum(np.add.reduceat(e[order], bounds, axis=0) ** 2 / counts[:, None], axis=0)
    onehot = np.zeros((len(group), n_groups))
    onehot[np.arange(len(group)), group] = 1.0
    onehot /= np.sqrt(counts)
    return lambda e: np.sum((onehot.T @ e) ** 2, axis=0)


class Round:
    """One round of the catalogue on the current model: observed statistics and joint null."""

    def __init__(self, data: Data, model: Model, n_null: int, rng: np.random.Generator):
        self.data, self.model, self.rng = data, model, rng
        self.hypotheses: list[Hypothesis] = []
        self.classes: list[TermClass] = []
        m = model
        spec = m.spec
        n = len(m.y)
        # an exact fit (to round-off or to the print of the response and the factors): round-off is not evidence
        if m.df_resid < 3 or round_off_only(m.resid_w, m.z, m.factor_round_off_w):
            return
        eps = rng.standard_normal((n, n_null))
        q = orthonormal_basis(m.xw)
        e_null = residualize(q, eps)
        e_obs = m.resid_w[:, None]

        self._missing_terms(data, m, e_obs, e_null)
        if not spec.drift and data.drift_tested:  # only where the run order can be believed (run_order)
            self._drift(m, q, e_obs, e_null)
        if spec.step is None and data.drift_tested:  # the same gate: a change-point in run order
            self._step(m, q, e_obs, e_null)
        self._outlier(m, e_obs, e_null)
        if spec.weight_on is None:
            self._heteroscedasticity(m, e_obs, e_null)

        # --- lack of fit against pure error (replicated runs): a function of the errors alone, so it
        # joins the family exactly; it shows misfit but names no cause.  (Weights depend on a factor or
        # the fitted value only, so replicated runs share them and whitened pure error stays pure error.)
        self._lack_of_fit(m, e_obs, e_null)

        # --- a run that fits another value of one factor (unit or decimal slip in the simulation input)
        if spec.lam is None and spec.weight_on is None:
            self._factor_level(data, m, eps)

        # every run positive, the excluded ones too: a transformed model's likelihood (Model.loglik, which the
        # AICc and the naming compare) counts each excluded run's Box-Cox Jacobian, log y, undefined at y <= 0
        if spec.lam is None and spec.weight_on is None and np.all(data.y > 0):
            self._response_transform(m, q, n_null, rng)

        if self.hypotheses:
            adj = weighted_stepdown([h.cause for h in self.hypotheses], np.array([h.logp for h in self.hypotheses]),
                                    np.column_stack([h.null_logp for h in self.hypotheses]))
            for h, p in zip(self.hypotheses, adj):
                h.p_family = float(p)

    def _missing_terms(self, data: Data, m: Model, e_obs: np.ndarray, e_null: np.ndarray) -> None:
        """A missing cubic term: one hypothesis per alias class of candidates on the current model."""
        df = m.df_resid
        extra = m.x[:, len(m.mean_terms):]  # blocks, drift, step: the model beyond its polynomial
        candidates = [t for t in cubic_terms(len(data.factors)) if t not in m.spec.extra_terms]
        self.classes = term_classes(m.coded, m.mean_terms, candidates, extra, m.w)
        sse_null = np.sum(e_null * e_null, axis=0)  # shared by every class's null
        for c in self.classes:
            names = [term_name(t, data.factors) for t in c.terms]
            if c.direction is None:
                continue
            f_obs = float(added_variable_stats(e_obs, c.direction, df - 1)[0])
            h = Hypothesis("missing_term", c, names, f_obs, float(f_logp(f_obs, df - 1)))
            h.null_logp = f_logp(added_variable_stats(e_null, c.direction, df - 1, sse_null), df - 1)
            self.hypotheses.append(h)

    def _drift(self, m: Model, q: np.ndarray, e_obs: np.ndarray, e_null: np.ndarray) -> None:
        """Drift: the run number as an added variable; not tested when the run column lies in the model's span
        to within 1e-7 of its own norm (what is left is round-off, a direction of noise)."""
        df = m.df_resid
        col = m.run_column(m.keep) * m.sw
        r = residualize(q, col[:, None])[:, 0]
        if np.linalg.norm(r) > 1e-7 * max(np.linalg.norm(col), 1e-300):
            u = r / np.linalg.norm(r)
            f_obs = float(added_variable_stats(e_obs, u, df - 1)[0])
            h = Hypothesis("drift", "run", [], f_obs, float(f_logp(f_obs, df - 1)))
            h.null_logp = f_logp(added_variable_stats(e_null, u, df - 1), df - 1)
            self.hypotheses.append(h)

    def _step(self, m: Model, q: np.ndarray, e_obs: np.ndarray, e_null: np.ndarray) -> None:
        """A shift between two consecutive groups of runs in run order: the largest added-variable F over the
        change-points (at least STEP_MIN_RUNS runs each side); nominal p Bonferroni over the change-points
        (ranking only: the family test uses the simulated joint null of the maximum)."""
        df = m.df_resid
        if len(m.y) > ASYMPTOTIC_RUNS:
            starts, f_obs, f_null = self._step_by_sums(m, q, e_obs, e_null)
        else:
            starts, f_obs, f_null = [], [], None
            for chunk, directions in step_direction_chunks(m, q):
                starts += chunk
                f_obs.append(_added_variable_stats_many(e_obs, directions, df - 1)[:, 0])
                chunk_null = _added_variable_stats_many(e_null, directions, df - 1).max(axis=0)
                f_null = chunk_null if f_null is None else np.maximum(f_null, chunk_null)
            f_obs = np.concatenate(f_obs) if f_obs else f_obs
        if not starts:
            return
        best = int(np.argmax(f_obs))
        n_points = len(starts)
        h = Hypothesis("step", starts[best], [], float(f_obs[best]),
                       float(min(0.0, math.log(n_points) + f_logp(f_obs[best], df - 1))),
                       info={"change_points": n_points})
        h.null_logp = np.minimum(0.0, math.log(n_points) + f_logp(f_null, df - 1))
        self.hypotheses.append(h)

    @staticmethod
    def _step_by_sums(m: Model, q: np.ndarray, e_obs: np.ndarray, e_null: np.ndarray):
        """The step test's change-points, observed F (C,) and each null draw's largest F (B,) from
        :func:`step_projections`, the null draws a block of columns at a time."""
        df2 = m.df_resid - 1
        starts, proj = step_projections(m, q, e_obs)
        f_obs = _f_of_projection(proj, e_obs, df2)[:, 0]
        width = max(1, STEP_CELLS // max(len(m.y), 1))
        f_null = np.concatenate([_f_of_projection(step_projections(m, q, e_null[:, j:j + width])[1],
                                                  e_null[:, j:j + width], df2).max(axis=0, initial=-np.inf)
                                 for j in range(0, e_null.shape[1], width)])
        return starts, f_obs, f_null

    def _outlier(self, m: Model, e_obs: np.ndarray, e_null: np.ndarray) -> None:
        """The run with the largest externally studentised residual."""
        df, n = m.df_resid, len(m.y)
        t_obs = outlier_stats(e_obs, m.hat, df)[:, 0]
        i = int(np.argmax(np.abs(t_obs)))
        h = Hypothesis("outlier", int(np.flatnonzero(m.keep)[i]), [], float(t_obs[i]),
                       float(outlier_logp(abs(t_obs[i]), n, df)))
        h.null_logp = outlier_logp(outlier_null_max(e_null, m.hat, df), n, df)
        self.hypotheses.append(h)

    def _heteroscedasticity(self, m: Model, e_obs: np.ndarray, e_null: np.ndarray) -> None:
        """Unequal scatter against each factor and the fitted values: likelihood ratio of a log-linear
        variance model; its F-scale p-values only set the ranking (the family test uses the simulated joint null)."""
        df, n = m.df_resid, len(m.y)
        for name, v in self.covariates().items():
            lr = float(heteroscedasticity_lr(e_obs, m.x, v)[0])
            h = Hypothesis("heteroscedasticity", name, [], lr, float(_lr_f_logp(lr, df, n)))
            if n > ASYMPTOTIC_RUNS:  # the F form's p is the test's; it joins the family as an independent uniform
                h.null_logp = np.log(self.rng.uniform(size=e_null.shape[1]))
            else:
                h.null_logp = _lr_f_logp(heteroscedasticity_lr(e_null, m.x, v), df, n)
            self.hypotheses.append(h)

    def _response_transform(self, m: Model, q: np.ndarray, n_null: int, rng: np.random.Generator) -> None:
        """Box-Cox: parametric bootstrap from the fitted model, conditional on positive responses;
        joined to the family as an independent uniform (conservative under positive dependence)."""
        df, n = m.df_resid, len(m.y)
        lr_obs = float(self._boxcox_lr(m.y[:, None], q)[0])
        strength = float(_lr_f_logp(lr_obs, df, n))
        if n > ASYMPTOTIC_RUNS:  # the F form of the likelihood ratio is its p-value
            h = Hypothesis("response_transform", None, [], lr_obs, strength, info={"bootstrap_draws": 0})
        else:
            p_boot, n_used = self._boxcox_bootstrap(m, q, lr_obs, n_null, rng)
            h = Hypothesis("response_transform", None, [], lr_obs, math.log(p_boot), info={"bootstrap_draws": n_used})
        # ranked against the other causes by the F form of the likelihood ratio
        h.strength = strength
        h.null_logp = np.log(rng.uniform(size=n_null))
        self.hypotheses.append(h)

    def _lack_of_fit(self, m: Model, e_obs: np.ndarray, e_null: np.ndarray) -> None:
        labels = None if self.data.block_labels is None else self.data.block_labels[m.keep]
        # the ANOVA's replicates (within their block), so that both judge one pure error
        group = pure_error_groups(m.coded, labels)
        n_groups = int(group.max()) + 1
        df_pe = len(group) - n_groups
        df_lof = m.df_resid - df_pe
        if df_pe < 1 or df_lof < 1:
            return
        if pure_error_ss(m.y, group) <= round_off_floor(m.y) ** 2 * df_pe:
            return  # replicates identical to round-off or print: lack of fit is undefined, as in the ANOVA
        between = _between_groups_ss(group, n_groups, large=len(group) > ASYMPTOTIC_RUNS)

        def f_stat(e):
            ss = np.sum(e * e, axis=0)
            ss_pe = ss - between(e)
            ss_lof = ss - ss_pe
            with np.errstate(divide="ignore", invalid="ignore"):
                return (ss_lof / df_lof) / np.maximum(ss_pe / df_pe, 1e-300 * ss + 1e-300)

        f_obs = float(f_stat(e_obs)[0])
        h = Hypothesis("lack_of_fit", None, [], f_obs, float(stats.f.logsf(f_obs, df_lof, df_pe)),
                       info={"df": [df_lof, df_pe]})
        h.null_logp = stats.f.logsf(f_stat(e_null), df_lof, df_pe)
        self.hypotheses.append(h)

    def _factor_level(self, data: Data, m: Model, eps: np.ndarray) -> None:
        """Largest drop of the residual sum of squares when one run is moved to a slipped value of one
        factor (no parameter added); null by a parametric bootstrap from the fitted model that shares
        its normal draws with the rest of the family."""
        cands = slip_candidates(data, m)
        if not cands:
            return
        sigma = math.sqrt(m.ssr / m.df_resid)
        y_all = np.column_stack([m.z, m.fitted_z[:, None] + sigma * eps])
        ratio, best = slip_ratios(m, cands, y_all)
        t_obs = ratio[0]
        null = ratio[1:]
        b = len(null)
        sorted_null = np.sort(null)
        # p-values from the bootstrap distribution itself (Westfall-Young with an empirical margin)
        p_obs = (1.0 + b - np.searchsorted(sorted_null, t_obs - 1e-12, side="left")) / (b + 1.0)
        p_null = (1.0 + b - np.searchsorted(sorted_null, null - 1e-12, side="left")) / (b + 1.0)
        c = cands[int(best[0])]
        c, info = slip_fit(m, [d for d in cands if d.row == c.row], len(data.factors))
        h = Hypothesis("factor_level", c, [], float(t_obs), math.log(p_obs), info=info)
        h.null_logp = np.log(p_null)
        self.hypotheses.append(h)

    def _boxcox_bootstrap(self, m: Model, q: np.ndarray, lr_obs: float, n_null: int,
                          rng: np.random.Generator, max_batches: int = 20) -> tuple[float, int]:
        """P(LR* >= LR | all y* > 0) under y* = fitted + sigma * N(0, 1); (p, draws used).

        When the fitted null model almost never yields all-positive responses the
        positivity of the data is itself the evidence: p = 1 / (draws tried + 1).
        """
        sigma = math.sqrt(m.ssr / m.df_resid)
        used = exceed = tried = 0
        for _ in range(max_batches):
            y_null = m.fitted_z[:, None] + sigma * rng.standard_normal((len(m.y), n_null))
            tried += n_null
            ok = np.all(y_null > 0, axis=0)
            take = np.flatnonzero(ok)[: n_null - used]
            if len(take):
                exceed += int(np.count_nonzero(self._boxcox_lr(y_null[:, take], q) >= lr_obs - 1e-9))
                used += len(take)
            if used >= n_null:
                break
        if used == 0:
            return 1.0 / (tried + 1.0), 0
        return (exceed + 1.0) / (used + 1.0), used

    @staticmethod
    def _boxcox_lr(y: np.ndarray, q: np.ndarray) -> np.ndarray:
        prof = boxcox_profile(y, q, _LAMBDA_TEST_GRID)
        one = int(np.flatnonzero(_LAMBDA_TEST_GRID == 1.0)[0])
        return 2.0 * (prof.max(axis=0) - prof[one])

    def covariates(self) -> dict[str, np.ndarray]:
        """Variance covariates on the kept runs, scaled to [-1, 1]: each factor, then the fitted values."""
        m = self.model
        out = {}
        for j, f in enumerate(self.data.factors):
            v = self.data.coded[m.keep, j] / self.data.alpha
            if np.ptp(v) > 0:
                out[f] = v
        fz = m.fitted_z
        if np.ptp(fz) > 0:
            out["fitted"] = (fz - (fz.max() + fz.min()) / 2) / (np.ptp(fz) / 2)
        return out

    def rejected(self, family_alpha: float) -> list[Hypothesis]:
        """Rejected causes, strongest evidence first (misfit tests that name no cause left out)."""
        rej = [h for h in self.hypotheses if h.p_family <= family_alpha and h.cause in CAUSES]
        return sorted(rej, key=lambda h: (h.rank_key, CAUSES.index(h.cause)))

    def misfit(self, family_alpha: float) -> list[Hypothesis]:
        """Every rejected family member, causes and misfit tests alike."""
        return [h for h in self.hypotheses if h.p_family <= family_alpha]

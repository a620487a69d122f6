"""Model criticism: show what a model gets wrong, name the cause, extend the model, measure the gain.

Level 1 (:func:`criticize`) confronts the quadratic surrogate with the simulation
runs of one response.  A fixed catalogue of causes is tested, each with a
concrete one-parameter extension:

``missing_term``        one extra third-order term (pure cubic ``a^3``, mixed ``a^2:b``,
                        ``a:b:c``); added-variable F-test.  Terms that the design cannot
                        tell apart (their columns coincide once the quadratic is fitted,
                        e.g. ``b^3`` and ``a^2:b`` in a CCD) form one alias set, tested once;
                        :func:`separating_runs` proposes the extra runs that would split it.
``response_transform``  Box-Cox profile likelihood ratio of lambda against lambda = 1;
                        extension: the quadratic on the transformed scale, back-transformed.
``outlier``             largest externally studentised residual, Bonferroni over runs;
                        extension: refit without that run (a mean shift for it).
``drift``               a linear term in run order (``run`` column); added-variable F-test.
``heteroscedasticity``  likelihood ratio of a log-linear variance, var = s^2 exp(g v), with
                        v each factor and the fitted values; extension: maximum-likelihood WLS.

Family-wise error.  The catalogue is one family.  Every statistic except
Box-Cox's is a function of the error vector alone, whose distribution (normal
errors, the current model true) is known exactly for the design, so the joint
null is simulated and the Westfall-Young step-down min-P procedure gives
family-adjusted p-values: exact, aware of the tests' correlation (a factor and
the fitted values overlap as variance covariates), never less powerful than
Holm.  Box-Cox's null depends on the unknown mean, so its p-value comes from a
parametric bootstrap of the fitted model (conditional on positive responses) and
it joins the family as an independent uniform, which is conservative when it
correlates positively with the others.  A clean table yields a finding with
probability at most ``family_alpha``.

Naming.  The rejected cause with the smallest nominal p-value is named, except
that one wild run may read as an outlier or as scatter growing towards its
corner of the design: between those two (and between variance covariates) the
better-fitting extension (higher likelihood) is named.  Its extension is added and
the rest of the catalogue is tested again on the extended model, at most
``max_findings`` rounds; a later finding must also lower the leave-one-out
error, and nothing is tested after a weighted fit (its weights are estimates).

Gain, on the original response scale: leave-one-out RMSE from the exact PRESS
residuals (a transformed fit's leave-one-out prediction is back-transformed;
Box-Cox lambda and variance weights are held at their full-data estimates), and
AICc from the Gaussian likelihood of all n original observations (Jacobian for
transforms, the variance parameter for weights, one mean-shift parameter per
excluded run).  When a run is excluded, leave-one-out errors of the model before
and after are compared on the remaining runs only.

Level 2 (:func:`calibration_check`) confronts the calibrated simulation with the
experiment: the best point in the domain, the errors there and at the reference
point, the bottleneck observable, and bias (discrepancy) extensions with their
cost in parameters and what the measurements can and cannot identify.

Verified against statsmodels (``compare_f_test``, ``outlier_test``, OLS/WLS
log-likelihoods, influence PRESS residuals, ``eval_measures.aicc``) and scipy
(``special.boxcox``, ``optimize``) in ``tests/test_criticism.py``; power and
false-alarm rates against oracle tests in ``benchmarks/criticism_power.py``.
"""

from __future__ import annotations

import json
import math
import warnings
from dataclasses import dataclass, field, replace
from functools import lru_cache
from itertools import product

import numpy as np
import pandas as pd
import statsmodels.api as sm
from scipy import optimize, special, stats
from statsmodels.tools.eval_measures import aicc as _sm_aicc

from .config import targets as material_targets
from .design import Coding, Term, cubic_terms, model_matrix, model_units, quadratic_terms, term_name
from .surrogate import SurrogateFit, fit_response, round_off_only

CAUSES = ("missing_term", "response_transform", "outlier", "drift", "heteroscedasticity")
TRANSFORM_NAMES = {0.0: "log", 0.5: "sqrt", -1.0: "inverse"}
# Further convenient lambdas, tried when the data reject none of the named ones.
_NICE_LAMBDAS = (-0.5, 2.0, 1.5, -2.0, 0.25, -0.25)
_LAMBDA_TEST_GRID = np.round(np.arange(-2.0, 2.0001, 0.05), 10)
_LAMBDA_FINE_GRID = np.round(np.arange(-3.0, 3.0001, 0.01), 10)
# Log-linear variance var = sigma^2 exp(gamma v), v in [-1, 1]: the sd ratio across the range is exp(gamma).
# |gamma| <= 2.5 (sd ratio 12) in the test and the fit, so that one wild run cannot pose as a trend.
_GAMMA_BOUND = 2.5


# =========================================================================== helpers
def infer_axial_distance(actual: np.ndarray) -> float:
    """Axial distance alpha of a CCD from its factor levels (1.0 when not a 5-level CCD).

    A CCD factor takes the levels -alpha, -1, 0, 1, alpha (coded): alpha is the
    half-range divided by the half-distance of the two inner (factorial) levels.
    """
    actual = np.asarray(actual, dtype=float)
    found = []
    for col in actual.T:
        lo, hi = float(np.min(col)), float(np.max(col))
        if hi <= lo:
            continue
        u = np.unique(np.round((col - (lo + hi) / 2) / ((hi - lo) / 2), 6))
        inner = u[(np.abs(u) > 1e-6) & (np.abs(u) < 1 - 1e-6)]
        if len(u) == 5 and len(inner) == 2 and abs(inner[0] + inner[1]) < 1e-4:
            found.append(1.0 / abs(inner[1]))
    return float(np.median(found)) if found else 1.0


def _orth(x: np.ndarray) -> np.ndarray:
    """Orthonormal basis of the column space of x (rank-revealing SVD)."""
    if x.shape[1] == 0:
        return np.zeros((x.shape[0], 0))
    u, s, _ = np.linalg.svd(x, full_matrices=False)
    return u[:, s > s[0] * 1e-10] if s[0] > 0 else u[:, :0]


def _residualize(q: np.ndarray, x: np.ndarray) -> np.ndarray:
    """x minus its projection on the orthonormal columns q.

    einsum rather than BLAS: for these small, wide matrices it is as fast and it
    does not start BLAS threads, which thrash on a loaded machine.
    """
    return x - np.einsum("ij,jb->ib", q, np.einsum("ij,ib->jb", q, x))


def _hat(x: np.ndarray) -> np.ndarray:
    q = _orth(x)
    return np.sum(q * q, axis=1)


def _boxcox(y: np.ndarray, lam: float | None) -> np.ndarray:
    return y if lam is None else special.boxcox(y, lam)


def _inv_boxcox(z: np.ndarray, lam: float | None) -> np.ndarray:
    """Back-transform; clipped so that extrapolated grid points stay finite."""
    z = np.asarray(z, dtype=float)
    if lam is None:
        return z
    if lam == 0:
        return np.exp(np.clip(z, -700, 700))
    base = np.maximum(1.0 + lam * z, 1e-12)
    return np.exp(np.clip(np.log(base) / lam, -700, 700))


def _aicc(llf: float, nobs: int, k: int) -> float:
    """AICc = -2 llf + 2k n/(n-k-1) (statsmodels); NaN when n - k - 1 <= 0."""
    return float(_sm_aicc(llf, nobs, k)) if nobs - k - 1 > 0 else float("nan")


def _num(x) -> float | None:
    x = float(x)
    return x if math.isfinite(x) else None


def _run_value(v):
    v = v.item() if hasattr(v, "item") else v
    return int(v) if isinstance(v, (int, float)) and float(v).is_integer() else v


def _g(x: float, digits: int = 4) -> str:
    return f"{x:.{digits}g}"


# =========================================================================== aliasing
@dataclass(frozen=True)
class AliasSet:
    """Extra terms the design cannot tell apart once the quadratic (or current model) is fitted.

    ``testable`` is False when the terms coincide with the model itself (e.g. ``a^3``
    with ``a`` in a face-centred CCD).  ``extra_runs`` are candidate design points
    (actual units) whose addition makes every member separately estimable.
    """

    representative: str
    members: tuple[str, ...]
    testable: bool
    extra_runs: tuple[dict, ...] = ()

    def to_json(self) -> dict:
        return {"representative": self.representative, "aliases": list(self.members),
                "testable": self.testable, "extra_runs": [dict(p) for p in self.extra_runs]}


@dataclass
class _TermClass:
    terms: list[Term]
    direction: np.ndarray | None  # unit residualised column (None: not estimable)


def _term_classes(coded: np.ndarray, base_terms: list[Term], candidates: list[Term],
                  extra_columns: np.ndarray | None = None, weights: np.ndarray | None = None
                  ) -> list[_TermClass]:
    """Group candidate terms whose columns, residualised on the model, are collinear."""
    sw = np.ones(len(coded)) if weights is None else np.sqrt(weights)
    base = model_matrix(coded, base_terms)
    if extra_columns is not None and extra_columns.size:
        base = np.column_stack([base, extra_columns])
    q = _orth(base * sw[:, None])
    hat = np.sum(q * q, axis=1)
    cols = model_matrix(coded, candidates) * sw[:, None]
    resid = _residualize(q, cols)
    classes: list[_TermClass] = []
    inestimable = []
    for j, t in enumerate(candidates):
        norm = float(np.linalg.norm(resid[:, j]))
        if norm <= 1e-7 * max(float(np.linalg.norm(cols[:, j])), 1e-300):
            inestimable.append(t)
            continue
        u = resid[:, j] / norm
        if np.max(hat + u * u) > 1 - 1e-6:
            # The term would only fit one run exactly (leverage 1): not a curvature the runs can show.
            inestimable.append(t)
            continue
        for c in classes:
            if abs(float(c.direction @ u)) >= 1 - 1e-7:
                c.terms.append(t)
                break
        else:
            classes.append(_TermClass([t], u))
    return classes + [_TermClass([t], None) for t in inestimable]


def _candidate_points(n_factors: int, alpha: float) -> np.ndarray:
    levels = sorted({-alpha, -1.0, -0.5, 0.0, 0.5, 1.0, alpha})
    return np.array(list(product(levels, repeat=n_factors)), dtype=float)


def _separation_criterion(coded, base_terms, members):
    base = model_matrix(coded, base_terms)
    q = _orth(base)
    cols = model_matrix(coded, members)
    resid = _residualize(q, cols)
    ev = np.linalg.eigvalsh(resid.T @ resid)
    keep = ev > max(float(np.sum(cols * cols)), 1e-300) * 1e-12
    return int(keep.sum()), float(np.sum(np.log(ev[keep]))) if keep.any() else -np.inf


def separating_runs(coded: np.ndarray, base_terms: list[Term], members: list[Term],
                    alpha: float) -> np.ndarray:
    """Coded points to add so that every member term becomes separately estimable.

    Greedy D-optimal choice among the candidate levels {-alpha, -1, -0.5, 0, 0.5,
    1, alpha}^k: each step adds the point that raises the rank of the members'
    residualised block, ties broken by its log pseudo-determinant.
    """
    coded = np.round(np.asarray(coded, dtype=float), 12)
    return _separating_runs_cached(coded.tobytes(), coded.shape, tuple(map(tuple, base_terms)),
                                   tuple(map(tuple, members)), float(alpha)).copy()


@lru_cache(maxsize=256)
def _separating_runs_cached(coded_bytes: bytes, shape: tuple, base_terms: tuple, members: tuple,
                            alpha: float) -> np.ndarray:
    coded = np.frombuffer(coded_bytes, dtype=float).reshape(shape)
    base_terms, members = list(base_terms), list(members)
    cands = _candidate_points(coded.shape[1], alpha)
    current = np.asarray(coded, dtype=float)
    chosen = []
    rank, _ = _separation_criterion(current, base_terms, members)
    while rank < len(members) and len(chosen) < len(members):
        best, best_key = None, (rank, -np.inf)
        for c in cands:
            key = _separation_criterion(np.vstack([current, c]), base_terms, members)
            if key > best_key:
                best, best_key = c, key
        if best is None or best_key[0] <= rank:
            break
        chosen.append(best)
        current = np.vstack([current, best])
        rank = best_key[0]
    return np.array(chosen).reshape(-1, coded.shape[1])


# =========================================================================== data and models
@dataclass
class _Data:
    response: str
    factors: list[str]
    coded: np.ndarray
    y: np.ndarray
    runs: np.ndarray
    coding: Coding
    alpha: float
    log_factors: tuple[str, ...]
    base_terms: list[Term]

    @property
    def n(self) -> int:
        return len(self.y)

    def to_actual(self, coded: np.ndarray) -> np.ndarray:
        x = self.coding.to_actual(np.atleast_2d(coded))
        for i, f in enumerate(self.factors):
            if f in self.log_factors:
                x[:, i] = 10.0 ** x[:, i]
        return x

    def point_dict(self, coded_point) -> dict:
        x = self.to_actual(coded_point)[0]
        return {f: float(f"{v:.4g}") for f, v in zip(self.factors, x)}


@dataclass(frozen=True)
class _Spec:
    """A model: quadratic + extra terms [+ run order] on kept runs, optional transform and weights."""

    extra_terms: tuple[Term, ...] = ()
    drift: bool = False
    dropped: tuple[int, ...] = ()
    lam: float | None = None
    weight_on: str | None = None
    weight_gamma: float = 0.0
    weight_values: tuple[float, ...] = ()

    @property
    def n_extra_params(self) -> int:
        return (len(self.extra_terms) + int(self.drift) + len(self.dropped)
                + int(self.lam is not None) + int(self.weight_on is not None))


class _Model:
    """Fit of a :class:`_Spec` with statsmodels; whitened quantities for the tests."""

    def __init__(self, data: _Data, spec: _Spec):
        self.data, self.spec = data, spec
        keep = np.ones(data.n, dtype=bool)
        keep[list(spec.dropped)] = False
        self.keep = keep
        self.y = data.y[keep]
        self.z = _boxcox(self.y, spec.lam)
        coded = data.coded[keep]
        self.mean_terms = list(data.base_terms) + list(spec.extra_terms)
        x = model_matrix(coded, self.mean_terms)
        names = [term_name(t, data.factors) for t in self.mean_terms]
        self.run_center = float(np.mean(data.runs[keep].astype(float)))
        self.run_scale = float(max(np.ptp(data.runs.astype(float)), 1.0))
        if spec.drift:
            x = np.column_stack([x, self.run_column(keep)])
            names.append("run")
        self.x = x
        self.names = names
        if spec.weight_on is not None:
            v = np.asarray(spec.weight_values, dtype=float)[keep]
            self.w = np.exp(-spec.weight_gamma * v)
            self.results = sm.WLS(self.z, x, weights=self.w).fit()
        else:
            self.w = np.ones(len(self.y))
            self.results = sm.OLS(self.z, x).fit()
        self.sw = np.sqrt(self.w)
        self.xw = x * self.sw[:, None]
        self.beta = np.asarray(self.results.params, dtype=float)
        self.fitted_z = x @ self.beta
        self.resid_w = (self.z - self.fitted_z) * self.sw
        self.hat = _hat(self.xw)
        self.rank = int(_orth(self.xw).shape[1])
        self.df_resid = len(self.y) - self.rank
        self.ssr = float(self.resid_w @ self.resid_w)

    def run_column(self, rows) -> np.ndarray:
        return (self.data.runs[rows].astype(float) - self.run_center) / self.run_scale

    @property
    def n_params(self) -> int:
        """Mean parameters + sigma + transform/variance parameters + one per excluded run."""
        return self.rank + 1 + self.spec.n_extra_params - len(self.spec.extra_terms) - int(self.spec.drift)

    @property
    def loglik(self) -> float:
        """Gaussian log-likelihood of all n original observations (mean-shift for excluded runs)."""
        n = self.data.n
        sigma2 = self.ssr / n
        ll = -0.5 * n * (np.log(2 * np.pi * sigma2) + 1.0) + 0.5 * float(np.sum(np.log(self.w)))
        if self.spec.weight_on is not None and self.spec.dropped:
            v = np.asarray(self.spec.weight_values, dtype=float)[~self.keep]
            ll += 0.5 * float(np.sum(-self.spec.weight_gamma * v))
        if self.spec.lam is not None:
            ll += (self.spec.lam - 1.0) * float(np.sum(np.log(self.data.y)))
        return float(ll)

    @property
    def aicc(self) -> float:
        return _aicc(self.loglik, self.data.n, self.n_params)

    @property
    def fitted(self) -> np.ndarray:
        return _inv_boxcox(self.fitted_z, self.spec.lam)

    @property
    def loo_errors(self) -> np.ndarray:
        """Exact leave-one-out prediction errors on the original scale, at the kept runs."""
        with np.errstate(divide="ignore", invalid="ignore"):
            press_z = self.resid_w / (1.0 - self.hat) / self.sw
        return self.y - _inv_boxcox(self.z - press_z, self.spec.lam)

    def loo_rmse_on(self, keep_mask: np.ndarray) -> float:
        """Leave-one-out RMSE over the runs in keep_mask (a subset of this model's runs)."""
        err = np.full(self.data.n, np.nan)
        err[self.keep] = self.loo_errors
        return float(np.sqrt(np.mean(err[keep_mask] ** 2)))

    def summary(self) -> dict:
        y, f = self.y, self.fitted
        sst = float(np.sum((y - y.mean()) ** 2))
        sse = float(np.sum((y - f) ** 2))
        s = self.spec
        return {
            "terms": list(self.names),
            "r2": _num(1 - sse / sst) if sst > 0 else None,
            "rmse": _num(np.sqrt(sse / len(y))),
            "loo_rmse": _num(self.loo_rmse_on(self.keep)),
            "aicc": _num(self.aicc),
            "n_runs": int(len(y)),
            "n_params": int(self.n_params),
            "transform": None if s.lam is None else _transform_name(s.lam),
            "weighting": s.weight_on,
            "excluded_runs": [_run_value(self.data.runs[i]) for i in s.dropped],
        }

    def surrogate(self) -> "ExtendedSurrogate":
        k = len(self.mean_terms)
        drift = float(self.beta[k]) if self.spec.drift else 0.0
        return ExtendedSurrogate(
            response=self.data.response, factors=list(self.data.factors), coding=self.data.coding,
            terms=list(self.mean_terms), coefficients=self.beta[:k].copy(), lam=self.spec.lam,
            log_factors=self.data.log_factors, drift_per_run=drift / self.run_scale,
            reference_run=self.run_center, weighting=self.spec.weight_on,
            excluded_runs=tuple(_run_value(self.data.runs[i]) for i in self.spec.dropped))


def _transform_name(lam: float) -> str:
    for value, name in TRANSFORM_NAMES.items():
        if abs(lam - value) < 1e-9:
            return name
    return f"boxcox:{lam:g}"


@dataclass
class ExtendedSurrogate:
    """Predictor of an extended model on the original response scale.

    Duck-types :meth:`demid.surrogate.Surrogate.predict`.  Polynomial in coded
    units; a run-order term is evaluated at the mean run order of the fitted runs
    (its contribution is zero there); a transformed fit is back-transformed
    (median of the response for a log fit).
    """

    response: str
    factors: list[str]
    coding: Coding
    terms: list[Term]
    coefficients: np.ndarray
    lam: float | None = None
    log_factors: tuple[str, ...] = ()
    drift_per_run: float = 0.0
    reference_run: float = 0.0
    weighting: str | None = None
    excluded_runs: tuple = ()

    @property
    def term_names(self) -> list[str]:
        return [term_name(t, self.factors) for t in self.terms]

    def predict(self, points, chunk: int = 1_000_000) -> np.ndarray:
        coded = self.coding.to_coded(model_units(points, self.factors, self.log_factors))
        out = np.empty(len(coded))
        for start in range(0, len(coded), chunk):
            eta = model_matrix(coded[start:start + chunk], self.terms) @ self.coefficients
            out[start:start + chunk] = _inv_boxcox(eta, self.lam)
        return out


# =========================================================================== the catalogue
@dataclass
class _Hypothesis:
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


def _f_logp(f, df2):
    with np.errstate(divide="ignore", invalid="ignore"):
        return stats.f.logsf(np.maximum(f, 0.0), 1, df2)


def _added_variable_stats(e: np.ndarray, u: np.ndarray, df2: int):
    """F for adding unit direction u (already orthogonal to the model) to residuals e (n, B)."""
    proj = np.einsum("i,ib->b", u, e)
    sse = np.sum(e * e, axis=0)
    with np.errstate(divide="ignore", invalid="ignore"):
        return proj ** 2 * df2 / np.maximum(sse - proj ** 2, 1e-300 * np.maximum(sse, 1e-300))


def _outlier_stats(e: np.ndarray, hat: np.ndarray, df: int):
    """Externally studentised residuals t (n, B) of residuals e (n, B)."""
    ok = hat < 1 - 1e-10
    h = np.where(ok, hat, 0.0)[:, None]
    sse = np.sum(e * e, axis=0)
    with np.errstate(divide="ignore", invalid="ignore"):
        s2 = (sse - e ** 2 / (1 - h)) / (df - 1)
        t = e / np.sqrt(np.maximum(s2, 1e-300) * (1 - h))
    t[~ok] = 0.0
    return t


def _outlier_logp(tmax, n, df):
    return np.minimum(0.0, np.log(2.0 * n) + stats.t.logsf(tmax, df - 1))


_GAMMA_GRID = np.linspace(-_GAMMA_BOUND, _GAMMA_BOUND, 21)


def _het_lr(e: np.ndarray, x: np.ndarray, covariate: np.ndarray) -> np.ndarray:
    """Likelihood ratio of var_i = sigma^2 exp(gamma z_i) against gamma = 0, for residual columns e.

    Profile log-likelihood over a gamma grid (WLS for each gamma, mean refitted);
    e may be residuals or responses, the model's column space x is projected out.
    The statistic is a function of the errors alone, so its null distribution is
    simulated exactly for the design.
    """
    n = len(covariate)
    prof = np.empty((len(_GAMMA_GRID), e.shape[1]))
    for i, g in enumerate(_GAMMA_GRID):
        sw = np.exp(-0.5 * g * covariate)
        q = _orth(x * sw[:, None])
        ew = e * sw[:, None]
        r = _residualize(q, ew)
        with np.errstate(divide="ignore"):
            prof[i] = -0.5 * n * np.log(np.sum(r * r, axis=0) / n) + float(np.sum(np.log(sw)))
    zero = int(np.argmin(np.abs(_GAMMA_GRID)))
    return 2.0 * (prof.max(axis=0) - prof[zero])


def _boxcox_profile(y: np.ndarray, q: np.ndarray, lams: np.ndarray) -> np.ndarray:
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
        r = _residualize(q, z)
        out[i] = -0.5 * n * np.log(np.sum(r * r, axis=0) / n) + (lam - 1.0) * slog
    return out


def _stepdown_minp(obs: np.ndarray, null: np.ndarray) -> np.ndarray:
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


class _Round:
    """One round of the catalogue on the current model: observed statistics and joint null."""

    def __init__(self, data: _Data, model: _Model, n_null: int, rng: np.random.Generator):
        self.data, self.model = data, model
        self.hypotheses: list[_Hypothesis] = []
        self.classes: list[_TermClass] = []
        m = model
        spec = m.spec
        df = m.df_resid
        n = len(m.y)
        if df < 3 or round_off_only(m.resid_w, m.z):  # an exact fit: round-off is not evidence
            return
        eps = rng.standard_normal((n, n_null))
        q = _orth(m.xw)
        e_null = _residualize(q, eps)
        e_obs = m.resid_w[:, None]

        # --- missing terms (alias classes on the current model)
        coded = data.coded[m.keep]
        extra = m.run_column(m.keep)[:, None] if spec.drift else None
        candidates = [t for t in cubic_terms(len(data.factors)) if t not in spec.extra_terms]
        self.classes = _term_classes(coded, m.mean_terms, candidates, extra, m.w)
        for c in self.classes:
            names = [term_name(t, data.factors) for t in c.terms]
            if c.direction is None:
                continue
            f_obs = float(_added_variable_stats(e_obs, c.direction, df - 1)[0])
            h = _Hypothesis("missing_term", c, names, f_obs, float(_f_logp(f_obs, df - 1)))
            h.null_logp = _f_logp(_added_variable_stats(e_null, c.direction, df - 1), df - 1)
            self.hypotheses.append(h)

        # --- drift
        if not spec.drift:
            col = m.run_column(m.keep) * m.sw
            r = _residualize(q, col[:, None])[:, 0]
            if np.linalg.norm(r) > 1e-7 * max(np.linalg.norm(col), 1e-300):
                u = r / np.linalg.norm(r)
                f_obs = float(_added_variable_stats(e_obs, u, df - 1)[0])
                h = _Hypothesis("drift", "run", [], f_obs, float(_f_logp(f_obs, df - 1)))
                h.null_logp = _f_logp(_added_variable_stats(e_null, u, df - 1), df - 1)
                self.hypotheses.append(h)

        # --- outlier
        t_obs = _outlier_stats(e_obs, m.hat, df)[:, 0]
        i = int(np.argmax(np.abs(t_obs)))
        h = _Hypothesis("outlier", int(np.flatnonzero(m.keep)[i]), [], float(t_obs[i]),
                        float(_outlier_logp(abs(t_obs[i]), n, df)))
        h.null_logp = _outlier_logp(np.max(np.abs(_outlier_stats(e_null, m.hat, df)), axis=0), n, df)
        self.hypotheses.append(h)

        # --- heteroscedasticity against each factor and the fitted values (likelihood ratio of a
        # log-linear variance model; p-values on the F scale, (df-1)(exp(LR/n)-1) ~ F(1, df-1),
        # which only sets the ranking: the family test uses the simulated joint null)
        if spec.weight_on is None:
            for name, v in self.covariates().items():
                lr = float(_het_lr(e_obs, m.x, v)[0])
                h = _Hypothesis("heteroscedasticity", name, [], lr, float(_f_logp((df - 1) * np.expm1(lr / n), df - 1)))
                h.null_logp = _f_logp((df - 1) * np.expm1(_het_lr(e_null, m.x, v) / n), df - 1)
                self.hypotheses.append(h)

        # --- Box-Cox: parametric bootstrap from the fitted model, conditional on positive responses;
        # joined to the family as an independent uniform (conservative under positive dependence).
        if spec.lam is None and spec.weight_on is None and np.all(m.y > 0):
            lr_obs = float(self._boxcox_lr(m.y[:, None], q)[0])
            p_boot, n_used = self._boxcox_bootstrap(m, q, lr_obs, n_null, rng)
            h = _Hypothesis("response_transform", None, [], lr_obs, math.log(p_boot),
                            info={"bootstrap_draws": n_used})
            # Ranked against the other causes by the F form of the likelihood ratio, which is close
            # to calibrated at a dozen runs (chi-square(1) is far too liberal there).
            h.strength = float(_f_logp((df - 1) * np.expm1(lr_obs / n), df - 1))
            h.null_logp = np.log(rng.uniform(size=n_null))
            self.hypotheses.append(h)

        if self.hypotheses:
            adj = _stepdown_minp(np.array([h.logp for h in self.hypotheses]),
                                 np.column_stack([h.null_logp for h in self.hypotheses]))
            for h, p in zip(self.hypotheses, adj):
                h.p_family = float(p)

    def _boxcox_bootstrap(self, m: _Model, q: np.ndarray, lr_obs: float, n_null: int,
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
        prof = _boxcox_profile(y, q, _LAMBDA_TEST_GRID)
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

    def rejected(self, family_alpha: float) -> list[_Hypothesis]:
        rej = [h for h in self.hypotheses if h.p_family <= family_alpha]
        return sorted(rej, key=lambda h: (h.rank_key, CAUSES.index(h.cause)))


# =========================================================================== findings
@dataclass
class Finding:
    """One named cause with its extension's gain over the model before it."""

    response: str
    cause: str
    detail: object
    aliases: list[str]
    p_value: float
    p_nominal: float
    statistic: float
    message: str
    loo_rmse_baseline: float
    loo_rmse_extended: float
    delta_aicc: float
    compared_runs: int
    extra_runs: list[dict] = field(default_factory=list)
    info: dict = field(default_factory=dict)

    def to_json(self) -> dict:
        out = {"cause": self.cause, "detail": self.detail, "aliases": list(self.aliases),
               "p_value": _num(self.p_value), "message": self.message,
               "p_nominal": _num(self.p_nominal), "statistic": _num(self.statistic),
               "loo_rmse_before": _num(self.loo_rmse_baseline), "loo_rmse_after": _num(self.loo_rmse_extended),
               "delta_aicc": _num(self.delta_aicc), "compared_runs": self.compared_runs}
        if self.extra_runs:
            out["extra_runs"] = self.extra_runs
        out.update({k: v for k, v in self.info.items()})
        return out


@dataclass
class CriticismResult:
    """Level-1 result for one response; ``to_json()`` is the issue's contract (plus extra keys)."""

    response: str
    factors: list[str]
    baseline: dict
    findings: list[Finding]
    extended: dict
    gain: dict
    alias_sets: list[AliasSet]
    catalogue: list[dict]
    summary: str
    family_alpha: float
    residuals: pd.DataFrame = field(repr=False, default=None)
    _extended_model: _Model = field(repr=False, default=None)
    _baseline_model: _Model = field(repr=False, default=None)

    def to_json(self) -> dict:
        """JSON-ready dict: response, baseline, findings, extended, gain (+ alias sets, catalogue, summary)."""
        return {
            "response": self.response,
            "baseline": self.baseline,
            "findings": [f.to_json() for f in self.findings],
            "extended": self.extended,
            "gain": self.gain,
            "summary": self.summary,
            "family_alpha": self.family_alpha,
            "alias_sets": [a.to_json() for a in self.alias_sets],
            "catalogue": self.catalogue,
            "runs": self._runs_json(),
        }

    def _runs_json(self) -> list[dict]:
        if self.residuals is None:
            return []
        cols = ["run", "observed", "fitted", "residual", "loo_residual", "student_resid", "leverage"]
        return [{c: (_run_value(row[c]) if c == "run" else _num(row[c])) for c in cols}
                for _, row in self.residuals[cols].iterrows()]

    def dumps(self) -> str:
        return json.dumps(self.to_json(), indent=2, allow_nan=False)

    def to_frame(self) -> pd.DataFrame:
        cols = ["response", "cause", "detail", "aliases", "p_value", "loo_rmse_baseline",
                "loo_rmse_extended", "delta_aicc", "message"]
        rows = [{"response": self.response, "cause": f.cause, "detail": str(f.detail),
                 "aliases": ";".join(f.aliases), "p_value": f.p_value,
                 "loo_rmse_baseline": f.loo_rmse_baseline, "loo_rmse_extended": f.loo_rmse_extended,
                 "delta_aicc": f.delta_aicc, "message": f.message} for f in self.findings]
        return pd.DataFrame(rows, columns=cols)

    def extended_surrogate(self) -> ExtendedSurrogate:
        """Predictor of the extended model (the baseline quadratic when nothing was found)."""
        return self._extended_model.surrogate()

    def baseline_surrogate(self) -> ExtendedSurrogate:
        return self._baseline_model.surrogate()


def _prepare(table: pd.DataFrame, factors: list[str], response: str, alpha: float | None,
             log_factors: tuple[str, ...]) -> tuple[_Data, SurrogateFit]:
    z = model_units(table[factors].to_numpy(), factors, log_factors)
    ok = np.isfinite(table[response].to_numpy(dtype=float))
    if alpha is None:
        alpha = infer_axial_distance(z[ok])
    coding = Coding.from_levels(factors, z, alpha)
    fit = fit_response(table, factors, response, alpha=alpha, coding=coding, log_factors=tuple(log_factors))
    sub = table.loc[ok]
    runs = sub["run"].to_numpy() if "run" in sub.columns else np.arange(1, int(ok.sum()) + 1)
    data = _Data(response, list(factors), fit.coded, fit.y, runs, coding, float(alpha),
                 tuple(log_factors), quadratic_terms(len(factors)))
    return data, fit


def _apply(data: _Data, model: _Model, h: _Hypothesis) -> tuple[_Spec, dict]:
    """Extension of ``model.spec`` that answers hypothesis h, and facts for the message."""
    spec = model.spec
    info: dict = {}
    if h.cause == "missing_term":
        return replace(spec, extra_terms=spec.extra_terms + (h.detail.terms[0],)), info
    if h.cause == "drift":
        return replace(spec, drift=True), info
    if h.cause == "outlier":
        i = int(h.detail)
        pos = int(np.flatnonzero(np.flatnonzero(model.keep) == i)[0])
        info["observed"] = float(data.y[i])
        info["predicted_without"] = float(data.y[i] - model.loo_errors[pos])
        return replace(spec, dropped=spec.dropped + (i,)), info
    if h.cause == "response_transform":
        q = _orth(model.xw)
        prof = _boxcox_profile(model.y[:, None], q, _LAMBDA_FINE_GRID)[:, 0]
        best = int(np.argmax(prof))
        lam_hat = float(_LAMBDA_FINE_GRID[best])
        # Small-sample 95 % interval: the likelihood ratio in F form, F = df (exp(LR/n) - 1) ~ F(1, df)
        # (the chi-square(1) interval is far too narrow at a dozen runs).
        n, df = len(model.y), model.df_resid - 1
        f_ratio = df * np.expm1(2 * (prof[best] - prof) / n)
        inside = _LAMBDA_FINE_GRID[f_ratio <= stats.f.ppf(0.95, 1, df)]
        lo, hi = float(inside.min()), float(inside.max())
        # The transform used is the first convenient lambda (log, sqrt, inverse, then others)
        # that the data do not reject at the 1 % level; otherwise lambda-hat to one decimal.
        plausible = _LAMBDA_FINE_GRID[f_ratio <= stats.f.ppf(0.99, 1, df)]
        lo99, hi99 = float(plausible.min()), float(plausible.max())
        lam = next((v for v in (*TRANSFORM_NAMES, *_NICE_LAMBDAS) if lo99 <= v <= hi99), round(lam_hat, 1))
        if abs(lam - 1.0) < 1e-9:
            lam = round(lam_hat, 2)
        info.update(lambda_hat=lam_hat, lambda_ci=[lo, hi])
        return replace(spec, lam=float(lam)), info
    if h.cause == "heteroscedasticity":
        if h.detail == "fitted":  # excluded runs: their predicted value, same scaling
            fz_all = model_matrix(data.coded, model.mean_terms) @ model.beta[:len(model.mean_terms)]
            fz = model.fitted_z
            values = (fz_all - (fz.max() + fz.min()) / 2) / (np.ptp(fz) / 2)
        else:
            values = data.coded[:, data.factors.index(h.detail)] / data.alpha
        base = replace(spec, weight_on=h.detail, weight_values=tuple(float(v) for v in values))

        def negll(g):
            return -_Model(data, replace(base, weight_gamma=float(g))).loglik

        res = optimize.minimize_scalar(negll, bounds=(-_GAMMA_BOUND, _GAMMA_BOUND), method="bounded",
                                       options={"xatol": 1e-6})
        gamma = float(res.x)
        info["sd_ratio"] = float(np.exp(gamma))  # sd at covariate +1 over sd at -1
        return replace(base, weight_gamma=gamma), info
    raise ValueError(h.cause)


_CAUSE_WORDS = {"missing_term": "missing term", "response_transform": "transform", "outlier": "outlier run",
                "drift": "drift with", "heteroscedasticity": "unequal scatter with"}


def _gain_phrase(before: float, after: float) -> str:
    if not (np.isfinite(before) and np.isfinite(after)) or before <= 0:
        return "its effect on the leave-one-out error could not be computed"
    ratio = after / before
    if ratio < 0.995:
        return f"cuts the leave-one-out error by {100 * (1 - ratio):.0f} %"
    if ratio <= 1.005:
        return "leaves the leave-one-out error unchanged"
    return f"does not reduce the leave-one-out error (+{100 * (ratio - 1):.0f} %)"


def _and(names: list[str]) -> str:
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]


def _describe_term(term: Term, factors: list[str]) -> str:
    powers = {f: p for f, p in zip(factors, term) if p}
    if len(powers) == 1:
        return f"curvature along {next(iter(powers))}"
    if len(powers) == 3:
        return f"a three-factor interaction of {_and(list(powers))}"
    sq = next(f for f, p in powers.items() if p == 2)
    lin = next(f for f, p in powers.items() if p == 1)
    return f"a change of the {sq} curvature with {lin}"


def _points_text(points: list[dict]) -> str:
    return " and ".join("(" + ", ".join(f"{k}={v:g}" for k, v in p.items()) + ")" for p in points)


def _message(data: _Data, h: _Hypothesis, info: dict, before: float, after: float,
             n_compared: int, extra_runs: list[dict], model: _Model) -> str:
    r = data.response
    gain = _gain_phrase(before, after)
    if h.cause == "missing_term":
        rep = h.aliases[0]
        others = h.aliases[1:]
        alias = f", aliased with {_and(others)} in this design" if others else ""
        text = (f"{r}: the quadratic misses {_describe_term(h.detail.terms[0], data.factors)} "
                f"(term {rep}{alias}); adding it {gain}.")
        if others and extra_runs:
            what = "the two" if len(h.aliases) == 2 else f"the {len(h.aliases)}"
            text += f" Extra runs at {_points_text(extra_runs)} would tell {what} apart."
        return text
    if h.cause == "response_transform":
        lam = info["lam"]
        scale = {"log": "log", "sqrt": "square-root", "inverse": "reciprocal"}.get(_transform_name(lam))
        on = f"on a {scale} scale" if scale else f"after a Box-Cox transform with lambda = {lam:g}"
        lo, hi = info["lambda_ci"]
        kind = "multiplicatively" if lam <= 0.5 else "non-additively"
        return (f"{r}: the response behaves {kind}: the quadratic fits better {on} "
                f"(Box-Cox lambda = {info['lambda_hat']:.2f}, 95 % interval {lo:.2f} to {hi:.2f}); "
                f"fitting there and transforming back {gain}.")
    if h.cause == "outlier":
        run = _run_value(data.runs[int(h.detail)])
        return (f"{r}: run {run} does not fit the other runs (observed {_g(info['observed'])}, "
                f"the other runs predict {_g(info['predicted_without'])}, externally studentised "
                f"residual {h.statistic:.1f}); a transcription or export error is the usual cause, "
                f"check that run. Refitting without it {gain} on the other {n_compared} runs.")
    if h.cause == "drift":
        slope = info.get("drift_per_run", float("nan"))
        span = slope * float(np.ptp(data.runs.astype(float)))
        return (f"{r}: the residuals trend with run order ({slope:+.3g} per run, {span:+.3g} from first to "
                f"last run): something changed while the runs were made (software version, settings, "
                f"seeds, hardware). Adding a run-order term {gain}; predictions refer to the mean run order.")
    if h.cause == "heteroscedasticity":
        ratio = info["sd_ratio"]
        grows = ratio >= 1
        what = "the predicted value" if h.detail == "fitted" else str(h.detail)
        factor = ratio if grows else 1 / ratio
        return (f"{r}: the scatter of the runs {'grows' if grows else 'shrinks'} with {what} (residual "
                f"spread about {factor:.1f} times larger at the {'high' if grows else 'low'} end than at the "
                f"other); weighting the fit by the estimated variance {gain}. Uncertainty from the "
                f"unweighted fit is too wide where the runs agree and too narrow where they scatter.")
    raise ValueError(h.cause)


def criticize(table: pd.DataFrame, factors: list[str], response: str, *, alpha: float | None = None,
              family_alpha: float = 0.05, log_factors: tuple[str, ...] = (), max_findings: int = 3,
              n_null: int = 1999, seed: int = 0) -> CriticismResult:
    """Level-1 model criticism of the quadratic surrogate of one response.

    ``alpha`` is the CCD axial distance used for coding (None: inferred from the
    levels).  Runs with a missing response are dropped.  ``n_null`` Monte Carlo
    draws of the joint null (seeded with ``seed``: results are reproducible) give
    the family-adjusted p-values.  See the module docstring for the catalogue.
    """
    data, fit = _prepare(table, list(factors), response, alpha, tuple(log_factors))
    rng = np.random.default_rng(seed)
    base_model = _Model(data, _Spec())
    model = base_model
    findings: list[Finding] = []
    catalogue: list[dict] = []
    alias_sets: list[AliasSet] = []
    for rnd_index in range(max_findings):
        rnd = _Round(data, model, n_null, rng)
        if rnd_index == 0:
            alias_sets = _alias_sets(data, rnd)
            catalogue = [_catalogue_entry(data, h) for h in rnd.hypotheses]
        rejected = rnd.rejected(family_alpha)
        if not rejected:
            break
        # The rejected cause with the strongest evidence (smallest nominal p-value) is named, except
        # that one wild run can be read as an outlier or as scatter growing towards its corner of the
        # design: between those two (and between variance covariates, often nearly collinear) the
        # better-fitting one-parameter extension (higher likelihood) decides.  The other rejected
        # causes are fitted too and listed as alternatives.
        fitted_alternatives = []
        for cand in rejected:
            cand_spec, cand_info = _apply(data, model, cand)
            fitted_alternatives.append((cand, cand_spec, cand_info, _Model(data, cand_spec)))
        best = 0
        if rejected[0].cause in ("heteroscedasticity", "outlier"):
            rivals = [i for i, alt in enumerate(fitted_alternatives)
                      if alt[0].cause in ("heteroscedasticity", "outlier")]
            best = max(rivals, key=lambda i: (round(fitted_alternatives[i][3].loglik, 9), -i))
        h, spec, info, new = fitted_alternatives[best]
        alternatives = [{"cause": c.cause, "detail": _detail_json(data, c) if c.cause != "response_transform"
                         else _transform_name(sp.lam), "p_value": _num(c.p_family),
                         "loglik_vs_named": _num(mo.loglik - new.loglik)}
                        for c, sp, _, mo in fitted_alternatives if c is not h]
        if findings and not new.loo_rmse_on(new.keep) < model.loo_rmse_on(new.keep):
            break  # a further extension must also predict left-out runs better
        if h.cause == "response_transform":
            info["lam"] = spec.lam
        if h.cause == "drift":
            info["drift_per_run"] = _drift_per_run(new)
        same = new.keep
        before = model.loo_rmse_on(same)
        after = new.loo_rmse_on(same)
        extra_runs = []
        if h.cause == "missing_term" and len(h.detail.terms) > 1:
            pts = separating_runs(data.coded[model.keep], model.mean_terms, h.detail.terms, data.alpha)
            extra_runs = [data.point_dict(p) for p in pts]
        message = _message(data, h, info, before, after, int(same.sum()), extra_runs, model)
        close = [a for a in alternatives if a["loglik_vs_named"] is not None and a["loglik_vs_named"] > -2.0]
        if close:
            message += (" Almost as likely: " + "; ".join(f"{_CAUSE_WORDS[a['cause']]} {a['detail']}" for a in close)
                        + ".")
        detail = _transform_name(spec.lam) if h.cause == "response_transform" else _detail_json(data, h)
        public_info = {k: v for k, v in info.items() if k in ("lambda_hat", "lambda_ci", "sd_ratio",
                                                              "drift_per_run", "observed", "predicted_without")}
        if alternatives:
            public_info["alternatives"] = alternatives
        findings.append(Finding(
            response=response, cause=h.cause, detail=detail, aliases=list(h.aliases), p_value=h.p_family,
            p_nominal=float(np.exp(h.logp)), statistic=h.statistic, message=message,
            loo_rmse_baseline=before, loo_rmse_extended=after, delta_aicc=new.aicc - model.aicc,
            compared_runs=int(same.sum()), extra_runs=extra_runs, info=public_info))
        model = new
        if model.df_resid - 1 < 3 or model.spec.weight_on is not None:
            break  # too few spare runs, or estimated weights (further tests would not be exact)

    baseline = base_model.summary()
    stats_ = fit.statistics()
    baseline.update(lof_f=_num(stats_.lof_f), lof_p=_num(stats_.lof_p))
    if findings:
        extended = model.summary()
        extended.update(lof_f=None, lof_p=None)
        if not model.spec.dropped and model.spec.lam is None and model.spec.weight_on is None \
                and not model.spec.drift:
            ext_fit = fit_response(table, factors, response, alpha=data.alpha, coding=data.coding,
                                   terms=model.mean_terms, log_factors=data.log_factors)
            st = ext_fit.statistics()
            extended.update(lof_f=_num(st.lof_f), lof_p=_num(st.lof_p))
    else:
        extended = dict(baseline)
    same = model.keep
    loo_base_same = base_model.loo_rmse_on(same)
    loo_ext = model.loo_rmse_on(same)
    gain = {
        "loo_rmse_ratio": _num(loo_ext / loo_base_same) if loo_base_same > 0 else None,
        "delta_aicc": _num(model.aicc - base_model.aicc) if findings else 0.0,
        "loo_rmse_baseline_same_runs": _num(loo_base_same),
        "compared_runs": int(same.sum()),
    }
    if not findings:
        gain["loo_rmse_ratio"] = 1.0
    summary = _summary(data, findings, catalogue, family_alpha, gain)
    return CriticismResult(response=response, factors=list(factors), baseline=baseline, findings=findings,
                           extended=extended, gain=gain, alias_sets=alias_sets, catalogue=catalogue,
                           summary=summary, family_alpha=family_alpha, residuals=_residual_frame(fit),
                           _extended_model=model, _baseline_model=base_model)


def _drift_per_run(model: _Model) -> float:
    j = model.names.index("run")
    return float(model.beta[j] / model.run_scale)


def _detail_json(data: _Data, h: _Hypothesis):
    if h.cause == "missing_term":
        return h.aliases[0]
    if h.cause == "outlier":
        return _run_value(data.runs[int(h.detail)])
    if h.cause == "response_transform":
        return "boxcox"
    return h.detail


def _alias_sets(data: _Data, rnd: _Round) -> list[AliasSet]:
    out = []
    for c in rnd.classes:
        names = tuple(term_name(t, data.factors) for t in c.terms)
        runs = ()
        if len(c.terms) > 1 or c.direction is None:
            pts = separating_runs(data.coded[rnd.model.keep], rnd.model.mean_terms, c.terms, data.alpha)
            runs = tuple(data.point_dict(p) for p in pts)
        out.append(AliasSet(names[0], names, c.direction is not None, runs))
    return out


def _catalogue_entry(data: _Data, h: _Hypothesis) -> dict:
    detail = _detail_json(data, h)
    return {"cause": h.cause, "detail": detail, "aliases": list(h.aliases),
            "statistic": _num(h.statistic), "p_nominal": _num(np.exp(h.logp)), "p_family": _num(h.p_family)}


def _summary(data: _Data, findings: list[Finding], catalogue: list[dict], family_alpha: float,
             gain: dict) -> str:
    n_tests = len(catalogue)
    if not n_tests:
        return (f"{data.response}: nothing could be tested: {data.n} runs leave too few spare runs beyond "
                f"the {len(data.base_terms)} quadratic coefficients.")
    if not findings:
        return (f"{data.response}: nothing found: none of the {n_tests} catalogue tests (missing term, "
                f"transform, outlier, drift, unequal scatter) is significant at a family-wise "
                f"{100 * family_alpha:g} % level. With {data.n} runs only clear defects are detectable.")
    names = ", ".join(f"{f.cause} ({f.detail})" for f in findings)
    ratio = gain.get("loo_rmse_ratio")
    tail = f"; together they change the leave-one-out error by {100 * (ratio - 1):+.0f} %" if ratio else ""
    return (f"{data.response}: {len(findings)} finding(s) at a family-wise {100 * family_alpha:g} % level: "
            f"{names}{tail}.")


def _residual_frame(fit: SurrogateFit) -> pd.DataFrame:
    return fit.influence()


# =========================================================================== level 2
@dataclass
class Level2Result:
    """The calibrated simulation against the experiment for one material.

    Relative errors are (y_hat - y*) / |y*| as in :mod:`demid.admissibility`;
    ``best_*`` refers to the point of the domain minimising the largest |relative
    error| over all observables with targets.  ``without[k]`` is that smallest
    largest error when observable k is left out (equivalently: given a free bias).
    """

    factors: list[str]
    observables: list[str]
    targets: dict[str, float]
    tolerance: float
    best_point: dict[str, float]
    best_values: dict[str, float]
    best_errors: dict[str, float]
    best_max_error: float
    feasible: bool
    reference_point: dict[str, float] | None
    reference_values: dict[str, float] | None
    reference_errors: dict[str, float] | None
    bottleneck: str | None
    without: dict[str, float]
    implied_bias: dict[str, float]
    bias_candidates: list[str]
    biased_observable: str | None
    shared_bias: dict
    extensions: list[dict]
    message: str

    @property
    def reference_max_error(self) -> float | None:
        if self.reference_errors is None:
            return None
        return float(max(abs(v) for v in self.reference_errors.values()))

    def to_frame(self) -> pd.DataFrame:
        rows = []
        for o in self.observables:
            ref = self.reference_errors[o] if self.reference_errors else np.nan
            rows.append({
                "observable": o, "target": self.targets[o],
                "at_best": self.best_values[o], "rel_error_best": self.best_errors[o],
                "at_reference": self.reference_values[o] if self.reference_values else np.nan,
                "rel_error_reference": ref, "tolerance": self.tolerance,
                "within_tolerance": bool(abs(self.best_errors[o]) <= self.tolerance + 1e-12),
                "within_tolerance_reference": (bool(abs(ref) <= self.tolerance + 1e-12)
                                               if self.reference_errors else None),
                "bottleneck": o == self.bottleneck,
                "max_error_without": self.without.get(o, np.nan),
                "implied_bias": self.implied_bias.get(o, np.nan),
                "bias_candidate": o in self.bias_candidates,
            })
        return pd.DataFrame(rows)

    def to_json(self) -> dict:
        def clean(d):
            return None if d is None else {k: _num(v) for k, v in d.items()}
        return {
            "observables": list(self.observables), "targets": clean(self.targets), "tolerance": self.tolerance,
            "best_point": clean(self.best_point), "best_values": clean(self.best_values),
            "best_errors": clean(self.best_errors), "best_max_error": _num(self.best_max_error),
            "feasible": bool(self.feasible),
            "reference_point": clean(self.reference_point), "reference_values": clean(self.reference_values),
            "reference_errors": clean(self.reference_errors), "reference_max_error": self.reference_max_error,
            "bottleneck": self.bottleneck, "max_error_without": clean(self.without),
            "implied_bias": clean(self.implied_bias), "bias_candidates": list(self.bias_candidates),
            "biased_observable": self.biased_observable, "shared_bias": self.shared_bias,
            "extensions": self.extensions, "message": self.message,
        }


class _Level2Problem:
    """Relative errors of all observables as a function of a point in unit-scaled search space."""

    def __init__(self, surrogates, domain, targets, observables):
        self.surrogates, self.domain = surrogates, domain
        self.observables = list(observables)
        self.targets = np.array([targets[o] for o in self.observables], dtype=float)
        self.lo, self.hi = domain.search_bounds()

    def actual(self, s: np.ndarray) -> np.ndarray:
        return self.domain.to_actual(self.lo + np.atleast_2d(s) * (self.hi - self.lo))

    def values(self, s: np.ndarray) -> np.ndarray:
        x = self.actual(s)
        return np.stack([np.asarray(self.surrogates[o].predict(x), dtype=float) for o in self.observables])

    def errors(self, s: np.ndarray) -> np.ndarray:
        return (self.values(s) - self.targets[:, None]) / np.abs(self.targets)[:, None]


def _worst(err: np.ndarray, shared: bool) -> np.ndarray:
    """Largest |error| per column; with a shared bias, the best bias leaves half the spread."""
    if shared:
        return (err.max(axis=0) - err.min(axis=0)) / 2
    return np.abs(err).max(axis=0)


def _minimax(problem: _Level2Problem, grid_s: np.ndarray, grid_err: np.ndarray, rows: list[int],
             shared: bool = False, starts: int = 4) -> tuple[float, np.ndarray, float]:
    """min over the domain of the largest |relative error| of ``rows`` (+ optional shared bias).

    Grid search, then SLSQP on the epigraph form (min t s.t. |e_k(x) - delta| <= t)
    from the best few grid nodes.  Returns (value, unit point, delta).
    """
    worst = _worst(grid_err[rows], shared)
    order = np.argsort(worst, kind="stable")
    picks = [order[0]]
    for i in order[1:]:
        if len(picks) >= starts:
            break
        if np.min(np.max(np.abs(grid_s[picks] - grid_s[i]), axis=1)) > 0.1:
            picks.append(i)
    d = grid_s.shape[1]

    def evaluate(s):
        e = problem.errors(s)[rows, 0]
        delta = (e.max() + e.min()) / 2 if shared else 0.0
        return float(np.max(np.abs(e - delta))), delta

    best_val, best_s = float(worst[order[0]]), grid_s[order[0]].copy()
    best_delta = evaluate(best_s)[1]
    for i in picks:
        v0, delta0 = evaluate(grid_s[i])
        x0 = np.concatenate([grid_s[i], [v0], [delta0] if shared else []])

        def cons(v):
            e = problem.errors(v[:d])[rows, 0] - (v[d + 1] if shared else 0.0)
            return np.concatenate([v[d] - e, v[d] + e])

        bounds = [(0.0, 1.0)] * d + [(0.0, None)] + ([(None, None)] if shared else [])
        with warnings.catch_warnings(), np.errstate(all="ignore"):
            warnings.simplefilter("ignore")
            res = optimize.minimize(lambda v: v[d], x0, method="SLSQP", bounds=bounds,
                                    constraints=[{"type": "ineq", "fun": cons}],
                                    options={"maxiter": 200, "ftol": 1e-12})
        s = np.clip(res.x[:d], 0.0, 1.0)
        val, delta = evaluate(s)
        if val < best_val:
            best_val, best_s, best_delta = val, s, delta
    return best_val, best_s, best_delta


def calibration_check(surrogates: dict, domain, targets: dict[str, float], tolerance: float, n: int,
                      reference_point: dict | None = None) -> Level2Result:
    """Level-2 criticism: can any point of the domain meet every target, and if not, why not?

    ``surrogates`` maps observable -> object with ``predict(points_actual)``;
    observables are those with both a surrogate and a target.  The best point
    minimises the largest |relative error| (grid of ``n`` points per axis, then
    SLSQP polish).  Discrepancy extensions: a free bias on one observable (the
    bottleneck), a shared relative bias on all, a bias on each (saturated).
    """
    observables = [o for o in targets if o in surrogates]
    if not observables:
        raise ValueError("no observable has both a surrogate and a target")
    factors = list(domain.factors)
    d, k = len(factors), len(observables)
    problem = _Level2Problem(surrogates, domain, targets, observables)
    axes = [np.linspace(0.0, 1.0, n)] * d
    grid_s = np.column_stack([m.ravel() for m in np.meshgrid(*axes, indexing="ij")])
    grid_err = problem.errors(grid_s)
    every = list(range(k))

    best_val, best_s, _ = _minimax(problem, grid_s, grid_err, every)
    best_x = problem.actual(best_s)[0]
    best_values = dict(zip(observables, problem.values(best_s)[:, 0].tolist()))
    best_errors = dict(zip(observables, problem.errors(best_s)[:, 0].tolist()))
    feasible = best_val <= tolerance + 1e-12

    ref_values = ref_errors = None
    if reference_point is not None:
        x_ref = np.array([[float(reference_point[f]) for f in factors]])
        vals = np.stack([np.asarray(surrogates[o].predict(x_ref), dtype=float) for o in observables])[:, 0]
        ref_values = dict(zip(observables, vals.tolist()))
        ref_errors = {o: (v - targets[o]) / abs(targets[o]) for o, v in ref_values.items()}

    without, implied = {}, {}
    if k > 1:
        for i, o in enumerate(observables):
            val, s, _ = _minimax(problem, grid_s, grid_err, [j for j in every if j != i])
            without[o] = val
            implied[o] = float(problem.errors(s)[i, 0])
    bottleneck = None
    candidates: list[str] = []
    biased = None
    if not feasible:
        # Smallest error left when the observable is dropped; near-ties (common when the rest is
        # exactly solvable) go to the observable needing the smallest bias.
        bottleneck = (min(without, key=lambda o: (round(without[o] / (1e-3 * tolerance)), abs(implied[o])))
                      if without else observables[0])
        candidates = [o for o in observables if without.get(o, np.inf) <= tolerance + 1e-12]
        biased = candidates[0] if len(candidates) == 1 else None

    shared_val, shared_s, shared_delta = _minimax(problem, grid_s, grid_err, every, shared=True)
    shared = {"delta": _num(shared_delta), "max_error": _num(shared_val),
              "point": {f: _num(v) for f, v in zip(factors, problem.actual(shared_s)[0])},
              "n_params": d + 1}
    extensions = _level2_extensions(d, k, best_val, shared_val, without, bottleneck)
    result = Level2Result(
        factors=factors, observables=observables, targets={o: float(targets[o]) for o in observables},
        tolerance=float(tolerance), best_point=dict(zip(factors, best_x.tolist())), best_values=best_values,
        best_errors=best_errors, best_max_error=float(best_val), feasible=bool(feasible),
        reference_point=None if reference_point is None else {f: float(reference_point[f]) for f in factors},
        reference_values=ref_values, reference_errors=ref_errors, bottleneck=bottleneck, without=without,
        implied_bias=implied, bias_candidates=candidates, biased_observable=biased, shared_bias=shared,
        extensions=extensions, message="")
    result.message = _level2_message(result)
    return result


def _level2_extensions(d: int, k: int, best: float, shared: float, without: dict, bottleneck) -> list[dict]:
    def row(model, n_params, max_error):
        spare = k - n_params
        note = ("testable: {} spare measurement(s)".format(spare) if spare > 0 else
                "saturated: as many unknowns as measurements, it fits whenever a solution lies in the domain, "
                "so the fit itself is no evidence" if spare == 0 else
                "not identifiable: more unknowns than measurements; any point fits and the biases are just "
                "the residuals there")
        return {"model": model, "n_params": n_params, "n_measurements": k, "spare_measurements": spare,
                "max_error": _num(max_error), "note": note}

    rows = [row("simulation as calibrated (no discrepancy)", d, best)]
    if bottleneck is not None and without:
        rows.append(row(f"bias on {bottleneck}", d + 1, without[bottleneck]))
    rows.append(row("shared relative bias on all observables", d + 1, shared))
    rows.append(row("bias on every observable", d + k, 0.0))
    return rows


def _pct(x: float) -> str:
    return f"{100 * x:.2f} %" if abs(x) < 0.1 else f"{100 * x:.1f} %"


def _level2_message(r: Level2Result) -> str:
    pt = ", ".join(f"{f}={_g(v)}" for f, v in r.best_point.items())
    k, d = len(r.observables), len(r.factors)
    obs = _and(r.observables)
    parts = []
    if r.feasible:
        parts.append(f"Every target ({obs}) can be met within {_pct(r.tolerance)}: the best point ({pt}) "
                     f"misses by at most {_pct(r.best_max_error)}.")
    else:
        worst = max(r.best_errors, key=lambda o: abs(r.best_errors[o]))
        parts.append(f"No point of the domain meets every target ({obs}) within {_pct(r.tolerance)}; the "
                     f"closest point ({pt}) still misses by {_pct(r.best_max_error)} ({worst} "
                     f"{'over' if r.best_errors[worst] > 0 else 'under'}-predicted).")
        if r.bottleneck is not None and r.without:
            b = r.bottleneck
            parts.append(f"{b} is the bottleneck: without it the others can be met within "
                         f"{_pct(r.without[b])}, and the simulation would then read {b} "
                         f"{_pct(abs(r.implied_bias[b]))} {'high' if r.implied_bias[b] > 0 else 'low'}.")
            if r.biased_observable is not None:
                parts.append(f"{b} is the only observable whose removal makes the rest consistent, so a "
                             f"discrepancy (bias) in {b} explains the mismatch.")
            elif len(r.bias_candidates) > 1:
                parts.append(f"But removing any of {_and(r.bias_candidates)} makes the rest consistent: with "
                             f"{k} measurements and {d} parameters the data cannot say which one is off "
                             f"({b} is named because it needs the smallest bias); a further independent "
                             f"measurement would.")
            else:
                parts.append("No single observable explains the mismatch on its own.")
    if r.reference_errors is not None:
        ref = ", ".join(f"{o} {100 * e:+.2f} %" for o, e in r.reference_errors.items())
        ok = r.reference_max_error <= r.tolerance + 1e-12
        parts.append(f"At the reference point the errors are {ref}: it {'meets' if ok else 'misses'} the "
                     f"{_pct(r.tolerance)} tolerance.")
    sb = r.shared_bias
    spare = k - d - 1
    meas = f"{k} measurement{'s' if k != 1 else ''} and {d} parameter{'s' if d != 1 else ''}"
    if r.feasible:
        return " ".join(parts)
    if spare < 0:
        parts.append(f"With {meas}, a shared relative bias on the targets is not identifiable (any point "
                     f"fits once it is free).")
    else:
        parts.append(f"A shared relative bias of {100 * sb['delta']:+.2f} % on all targets would leave "
                     f"{_pct(sb['max_error'])} at one extra parameter; "
                     + (f"{spare} spare measurement{'s' if spare != 1 else ''} remain{'' if spare != 1 else 's'} "
                        f"to test it." if spare > 0 else
                        f"with {meas} it uses the last spare measurement, so its fit cannot be taken as "
                        f"evidence of a bias."))
    parts.append(f"A bias on every observable ({d + k} unknowns for {k} measurement{'s' if k != 1 else ''}) "
                 f"fits trivially and is not identifiable.")
    return " ".join(parts)


# =========================================================================== figure
def residual_figure(fits: list[SurrogateFit], results: list[CriticismResult], title: str):
    """Residual diagnostics, one row per response: vs fitted, vs run order, normal QQ.

    Residuals are those of the baseline quadratic; the QQ panel uses externally
    studentised residuals.  Named findings are marked: an outlier run is ringed
    and labelled in every panel, a drift gets its trend line, other causes are
    written in the first panel.  Returns a :class:`matplotlib.figure.Figure`
    (no pyplot state, no dates; save with ``metadata={'Software': None}`` etc.).
    """
    from matplotlib.figure import Figure

    by_response = {r.response: r for r in results}
    rows = max(len(fits), 1)
    fig = Figure(figsize=(12, 3.3 * rows), layout="constrained")
    axes = fig.subplots(rows, 3, squeeze=False)
    for row, fit in zip(axes, fits):
        res = by_response.get(fit.response)
        infl = fit.influence()
        runs = infl["run"].to_numpy()
        resid = infl["residual"].to_numpy()
        fitted = infl["fitted"].to_numpy()
        stud = infl["student_resid"].to_numpy()
        order = np.argsort(stud)
        theo = stats.norm.ppf((np.arange(1, len(stud) + 1) - 0.375) / (len(stud) + 0.25))
        qq_x = np.empty_like(theo)
        qq_x[order] = theo
        panels = [(fitted, resid, "fitted value", "residual"),
                  (runs.astype(float), resid, "run order", "residual"),
                  (qq_x, stud, "normal quantile", "ext. studentised residual")]
        for ax, (x, y, xl, yl) in zip(row, panels):
            ax.scatter(x, y, s=18, color="0.25", zorder=3)
            ax.set_xlabel(xl)
            ax.set_ylabel(yl)
            ax.grid(alpha=0.3)
        row[0].axhline(0, color="0.5", lw=0.8)
        row[1].axhline(0, color="0.5", lw=0.8)
        lim = np.nanmax(np.abs(np.concatenate([qq_x, stud[np.isfinite(stud)]]))) if len(stud) else 1.0
        row[2].plot([-lim, lim], [-lim, lim], color="0.5", lw=0.8)
        row[0].set_title(f"{fit.response}: residual vs fitted", fontsize=10)
        row[1].set_title(f"{fit.response}: residual vs run order", fontsize=10)
        row[2].set_title(f"{fit.response}: normal QQ", fontsize=10)
        notes = []
        for f in (res.findings if res is not None else []):
            if f.cause == "outlier":
                hit = runs == f.detail
                for ax, (x, y, _, _) in zip(row, panels):
                    ax.scatter(x[hit], y[hit], s=110, facecolors="none", edgecolors="tab:red", lw=1.5, zorder=4)
                    for xi, yi in zip(x[hit], y[hit]):
                        ax.annotate(f"run {f.detail}", (xi, yi), textcoords="offset points", xytext=(6, 6),
                                    color="tab:red", fontsize=8)
            elif f.cause == "drift":
                slope, icpt = np.polyfit(runs.astype(float), resid, 1)
                xs = np.array([runs.min(), runs.max()], dtype=float)
                row[1].plot(xs, icpt + slope * xs, color="tab:red", lw=1.2)
            label = {"missing_term": "missing term", "response_transform": "transform",
                     "heteroscedasticity": "unequal scatter vs"}.get(f.cause, f.cause)
            alias = " = " + " = ".join(f.aliases[1:]) if f.cause == "missing_term" and len(f.aliases) > 1 else ""
            notes.append(f"{label} {f.detail}{alias} (p={f.p_value:.3g})")
        text = "; ".join(notes) if notes else "nothing found"
        row[0].text(0.02, 0.97, text, transform=row[0].transAxes, va="top", fontsize=8,
                    color="tab:red" if notes else "0.3",
                    bbox={"facecolor": "white", "alpha": 0.8, "edgecolor": "none"})
    fig.suptitle(title)
    return fig


# =========================================================================== per-material step
@dataclass
class MaterialCriticism:
    """What the pipeline writes for one material: per-response JSON, tables, summary, figure."""

    response_json: dict[str, dict]
    findings: pd.DataFrame
    calibration: pd.DataFrame
    summary: dict
    figure: object


def _level2_tolerance(material_cfg: dict) -> float:
    """The tolerance of the scenario with the most observables (ties: the smallest); 0.02 without scenarios."""
    scenarios = list((material_cfg.get("scenarios") or {}).values())
    if not scenarios:
        return 0.02
    return float(min(scenarios, key=lambda sc: (-len(sc["observables"]), sc["tolerance"]))["tolerance"])


def _admissible(surrogates, domain, observables, targets, tolerance, n):
    from .admissibility import MAX_GRID_DIM, admissible_set, sobol_admissible_set

    if domain.dim > MAX_GRID_DIM:
        return sobol_admissible_set(surrogates, domain, observables, targets, tolerance, n)
    return admissible_set(surrogates, domain, observables, targets, tolerance, n)


def _effect_points(n: int, d: int) -> int:
    """Grid points per axis (Sobol points above 3 factors) for the before/after and level-2 searches."""
    if d <= 2:
        return min(n, 401)
    if d == 3:
        return min(n, 61)
    return min(n, 2 ** 14)


def _identifiability_effect(surrogates: dict, extended, response: str, material_cfg: dict, n: int) -> list[dict]:
    """Feasible fraction and spans of every scenario that uses ``response``, before and after the extension."""
    from .admissibility import Domain

    domain = Domain.from_config(material_cfg["factors"])
    targets = material_targets(material_cfg)
    rows = []
    for name, scen in (material_cfg.get("scenarios") or {}).items():
        if response not in scen["observables"]:
            continue
        before = _admissible(surrogates, domain, scen["observables"], targets, scen["tolerance"], n)
        after = _admissible({**surrogates, response: extended}, domain, scen["observables"], targets,
                            scen["tolerance"], n)
        rows.append({"scenario": name, "fraction_pct_before": 100 * before.fraction,
                     "fraction_pct_after": 100 * after.fraction,
                     "width_before": dict(zip(domain.factors, before.width)),
                     "width_after": dict(zip(domain.factors, after.width))})
    return rows


def reference_point_position(surrogates: dict, material_cfg: dict, n: int) -> list[dict]:
    """Where the source's chosen point lies relative to each scenario's admissible set.

    ``inside`` is evaluated at the point itself; ``nearest`` is the closest admissible grid node
    (distance in units of the search ranges, in percent, so factors of different scale compare).
    """
    from .admissibility import Domain

    ref = material_cfg.get("reference_point")
    if not ref:
        return []
    domain = Domain.from_config(material_cfg["factors"])
    targets = material_targets(material_cfg)
    point = np.array([[ref[f] for f in domain.factors]], dtype=float)
    lo, hi = domain.search_bounds()
    u_ref = (domain.to_search(point)[0] - lo) / (hi - lo)
    rows = []
    for name, scen in (material_cfg.get("scenarios") or {}).items():
        obs = scen["observables"]
        errors = {o: float((surrogates[o].predict(point)[0] - targets[o]) / abs(targets[o])) for o in obs}
        inside = max(abs(e) for e in errors.values()) <= scen["tolerance"]
        aset = _admissible(surrogates, domain, obs, targets, scen["tolerance"], n)
        nearest, distance = None, None
        if aset.mask.any():
            nodes = (aset.points if aset.points is not None else domain.grid(n))[aset.mask]
            u = (domain.to_search(nodes) - lo) / (hi - lo)
            k = int(np.argmin(np.sum((u - u_ref) ** 2, axis=1)))
            nearest = dict(zip(domain.factors, map(float, nodes[k])))
            distance = 0.0 if inside else float(100 * np.sqrt(np.sum((u[k] - u_ref) ** 2)))
        rows.append({"scenario": name, "inside": bool(inside), "errors": errors, "nearest_admissible": nearest,
                     "distance_pct_of_range": distance})
    return rows


def criticize_material(table: pd.DataFrame, surrogates: dict, material_cfg: dict, n: int,
                       title: str) -> MaterialCriticism:
    """Level 1 for every response (with the identifiability effect of any extension) and level 2."""
    from .admissibility import Domain
    from .data import infer_coding
    from .surrogate import fit_response

    factors = list(material_cfg["factors"])
    log_factors = tuple(f for f, c in material_cfg["factors"].items() if c.get("scale") == "log")
    design = material_cfg["design"]
    alpha = float(design.get("alpha", 1.0)) if design["type"] == "ccd" else 1.0
    coding = infer_coding(table, factors, design, material_cfg["data"], log_factors)
    # Identifiability before/after is evaluated on a coarser grid than the main one: it is a
    # comparison of two surrogates, and 3-factor grids would otherwise dominate the run time.
    n_effect = _effect_points(n, len(factors))
    n_level2 = n_effect if len(factors) <= 3 else max(5, int(2e5 ** (1 / len(factors))))
    response_json, frames, results, fits = {}, [], [], []
    for response in material_cfg["responses"]:
        result = criticize(table, factors, response, alpha=alpha, log_factors=log_factors)
        payload = result.to_json()
        if result.findings:
            payload["identifiability"] = _identifiability_effect(surrogates, result.extended_surrogate(), response,
                                                                 material_cfg, n_effect)
        response_json[response] = payload
        frames.append(result.to_frame())
        results.append(result)
        fits.append(fit_response(table, factors, response, coding=coding, log_factors=log_factors))
    findings = pd.concat(frames, ignore_index=True) if frames else pd.DataFrame()

    targets = material_targets(material_cfg)
    domain = Domain.from_config(material_cfg["factors"])
    level2 = None
    if targets:
        level2 = calibration_check({r: surrogates[r] for r in targets}, domain, targets,
                                   _level2_tolerance(material_cfg), n_level2, material_cfg.get("reference_point"))
    calibration = level2.to_frame() if level2 is not None else pd.DataFrame()
    summary = {
        "level1": {r: {"findings": len(p["findings"]), "messages": [f["message"] for f in p["findings"]]}
                   for r, p in response_json.items()},
        "level2": level2.to_json() if level2 is not None else None,
        "reference_point": reference_point_position(surrogates, material_cfg, n_effect),
    }
    return MaterialCriticism(response_json, findings, calibration, summary, residual_figure(fits, results, title))

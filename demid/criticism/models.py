"""The data and models level 1 works with, the public core of :mod:`demid.criticism`.

:class:`Data` is a response's runs in coded units; :class:`ModelForm` is the form of a model (the
quadratic and its one-parameter extensions: terms, transform, excluded runs, weights, drift, a step);
:class:`Model` is its fit, with likelihood, AICc and leave-one-out errors; :class:`ExtendedSurrogate`
predicts with it on the original scale.  The small linear-algebra and text helpers the criticism's
modules share are here too.  A round of the catalogue's tests on one model is
:class:`demid.criticism.catalogue.Round`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from ..design import LEVERAGE_UNPREDICTABLE, model_matrix, model_units, term_name

if TYPE_CHECKING:
    from ..design import Coding, Term


__all__ = [
    "TRANSFORM_NAMES", "Data", "ExtendedSurrogate", "Model", "ModelForm", "aicc_of", "aicc_of_many", "boxcox",
    "gaussian_loglik", "infer_axial_distance", "inv_boxcox", "json_number", "leverages", "orthonormal_basis", "residualize",
    "run_label", "short_number", "transform_name",
]

TRANSFORM_NAMES = {0.0: "log", 0.5: "sqrt", -1.0: "inverse"}


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


def orthonormal_basis(x: np.ndarray) -> np.ndarray:
    """Orthonormal basis of the column space of x (rank-revealing SVD)."""
    if x.shape[1] == 0:
        return np.zeros((x.shape[0], 0))
    u, s, _ = np.linalg.svd(x, full_matrices=False)
    return u[:, s > s[0] * 1e-10] if s[0] > 0 else u[:, :0]


def residualize(q: np.ndarray, x: np.ndarray) -> np.ndarray:
    """x minus its projection on the orthonormal columns q.

    einsum rather than BLAS: for these small, wide matrices it is as fast and it
    does not start BLAS threads, which thrash on a loaded machine.
    """
    return x - np.einsum("ij,jb->ib", q, np.einsum("ij,ib->jb", q, x))


def leverages(x: np.ndarray) -> np.ndarray:
    """The hat matrix's diagonal of x: each run's leverage."""
    q = orthonormal_basis(x)
    return np.sum(q * q, axis=1)


def boxcox(y: np.ndarray, lam: float | None) -> np.ndarray:
    """The Box-Cox transform of y (scipy's; y itself when lam is None)."""
    if lam is None:
        return y
    from scipy import special  # here, as statsmodels below: demid.story reads this module without either

    return special.boxcox(y, lam)


def inv_boxcox(z: np.ndarray, lam: float | None) -> np.ndarray:
    """Back-transform; clipped so that extrapolated grid points stay finite."""
    z = np.asarray(z, dtype=float)
    if lam is None:
        return z
    if lam == 0:
        return np.exp(np.clip(z, -700, 700))
    base = np.maximum(1.0 + lam * z, 1e-12)
    return np.exp(np.clip(np.log(base) / lam, -700, 700))


def gaussian_loglik(ssr: float, n: int) -> float:
    """Gaussian log-likelihood of n observations at the maximum-likelihood variance ssr / n."""
    sigma2 = ssr / n
    return -0.5 * n * (np.log(2 * np.pi * sigma2) + 1.0)


def aicc_of(llf: float, nobs: int, k: int) -> float:
    """AICc = -2 llf + 2k n/(n-k-1) (statsmodels); NaN when n - k - 1 <= 0."""
    from statsmodels.tools.eval_measures import aicc as _sm_aicc

    return float(_sm_aicc(llf, nobs, k)) if nobs - k - 1 > 0 else float("nan")


def aicc_of_many(llf: np.ndarray, nobs: int, k: int) -> np.ndarray:
    """:func:`aicc_of` of each log-likelihood in ``llf`` (the same statsmodels formula, one array)."""
    from statsmodels.tools.eval_measures import aicc as _sm_aicc

    llf = np.asarray(llf, dtype=float)
    return np.asarray(_sm_aicc(llf, nobs, k), dtype=float) if nobs - k - 1 > 0 else np.full(llf.shape, np.nan)


def json_number(x) -> float | None:
    """x as a float for a JSON document, None where it is NaN or infinite."""
    x = float(x)
    return x if math.isfinite(x) else None


def run_label(v):
    """A run's label as written in findings: a whole number as int, anything else as it is."""
    v = v.item() if hasattr(v, "item") else v
    return int(v) if isinstance(v, (int, float)) and float(v).is_integer() else v


def short_number(x: float, digits: int = 4) -> str:
    """x to ``digits`` significant digits, for running text."""
    return f"{x:.{digits}g}"


# =========================================================================== data and models
@dataclass
class Data:
    """One response's runs as level 1 models them: the factors in coded units (log factors as their
    logarithm), the response, the run labels in performed order, the coding, and what the models add
    (block columns, the factors' print round-off, candidate points for proposed runs)."""

    response: str
    factors: list[str]
    coded: np.ndarray
    y: np.ndarray
    runs: np.ndarray
    coding: Coding
    alpha: float
    log_factors: tuple[str, ...]
    base_terms: list[Term]
    drift_tested: bool = True  # False when the run column is not the performed order (criticism.run_order)
    # per run, the response error the factors' printed precision adds (SurrogateFit.factor_round_off)
    factor_round_off: np.ndarray | None = None
    blocks: np.ndarray | None = None  # effect-coded block columns (n, B-1) of runs made in blocks (demid.blocks)
    block_labels: np.ndarray | None = None
    # coded points the runs it proposes are chosen from (None: the design's levels within its reach); a next
    # wave's box grid, so that the runs lie where the next wave keeps them
    run_candidates: np.ndarray | None = None
    # the table is demid's own simulations (a wave of a simulated material): no run of it was typed or exported
    simulated: bool = False

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
        """A point in actual units to 4 digits of each factor's design range (the lower bound 0 reads 0, not
        the -3.7e-07 a rounded alpha leaves); a point of the next wave's box grid (``run_candidates``) to 6
        significant digits, as the next wave writes its own runs on that grid, so that both say the same point."""
        x = self.to_actual(coded_point)[0]
        ends = self.to_actual(np.array([[-self.alpha] * len(self.factors), [self.alpha] * len(self.factors)]))
        out = {}
        for f, v, lo, hi in zip(self.factors, x, ends[0], ends[1]):
            if self.run_candidates is not None:  # a bound at 0 stays 0 through the coding's round trip
                out[f] = float(f"{0.0 if abs(v) < 1e-9 * abs(hi - lo) else v:.6g}") + 0.0
                continue
            # a log factor spans decades: its small values keep their own digits
            step = (10.0 ** (math.floor(math.log10(abs(hi - lo))) - 3)
                    if hi != lo and f not in self.log_factors else 0.0)
            snapped = round(v / step) * step if step else v
            out[f] = float(f"{snapped:.4g}") + 0.0  # + 0.0: no -0
        return out


@dataclass(frozen=True)
class ModelForm:
    """The form of a model, before any fit: the quadratic plus extra terms [+ run order, a step] on the kept
    runs, with an optional transform and weights (a :class:`Model` keeps it as ``spec``)."""

    extra_terms: tuple[Term, ...] = ()
    drift: bool = False
    dropped: tuple[int, ...] = ()
    lam: float | None = None
    weight_on: str | None = None
    weight_gamma: float = 0.0
    weight_values: tuple[float, ...] = ()
    # (run index, factor index, coded value): runs whose response fits another value of one factor
    moved: tuple[tuple[int, int, float], ...] = ()
    step: int | None = None  # index (into the data) of the first run after a shift in run order

    @property
    def n_extra_params(self) -> int:
        return (len(self.extra_terms) + int(self.drift) + len(self.dropped) + int(self.step is not None)
                + int(self.lam is not None) + int(self.weight_on is not None))


class Model:
    """Fit of a :class:`ModelForm` to :class:`Data` with statsmodels (OLS, or WLS with weights): the
    whitened quantities the catalogue's tests use, the likelihood, AICc and exact leave-one-out errors."""

    def __init__(self, data: Data, spec: ModelForm):
        self.data, self.spec = data, spec
        keep = np.ones(data.n, dtype=bool)
        keep[list(spec.dropped)] = False
        self.keep = keep
        self.y = data.y[keep]
        self.z = boxcox(self.y, spec.lam)
        all_coded = data.coded.copy()
        for i, j, value in spec.moved:
            all_coded[i, j] = value
        self.coded = all_coded[keep]
        coded = self.coded
        self.mean_terms = list(data.base_terms) + list(spec.extra_terms)
        x = model_matrix(coded, self.mean_terms)
        names = [term_name(t, data.factors) for t in self.mean_terms]
        self.run_center = float(np.mean(data.runs[keep].astype(float)))
        self.run_scale = float(max(np.ptp(data.runs.astype(float)), 1.0))
        if data.blocks is not None:
            x = np.column_stack([x, data.blocks[keep]])
            names += [f"block{j + 1}" for j in range(data.blocks.shape[1])]
        if spec.drift:
            x = np.column_stack([x, self.run_column(keep)])
            names.append("run")
        if spec.step is not None:
            x = np.column_stack([x, self.step_column(keep)])
            names.append("step")
        self.x = x
        self.names = names
        # statsmodels here, not at module level: the light readers of this package (demid.story reads
        # .reach) need none of it.  linear_model only: statsmodels.api would add its graphics and tsa.
        from statsmodels.regression import linear_model as sm

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
        basis = orthonormal_basis(self.xw)  # one decomposition for the leverages and the rank
        self.hat = np.sum(basis * basis, axis=1)
        self.rank = int(basis.shape[1])
        self.df_resid = len(self.y) - self.rank
        self.ssr = float(self.resid_w @ self.resid_w)

    @property
    def factor_round_off_w(self) -> np.ndarray | None:
        """The factors' print round-off at the kept runs on the scale of ``resid_w`` (transformed, weighted)."""
        sd = self.data.factor_round_off
        if sd is None:
            return None
        sd = sd[self.keep]
        if self.spec.lam is not None:
            sd = sd * np.abs(self.y) ** (self.spec.lam - 1.0)  # dz/dy of the Box-Cox transform
        return sd * self.sw

    def run_column(self, rows) -> np.ndarray:
        return (self.data.runs[rows].astype(float) - self.run_center) / self.run_scale

    def step_column(self, rows, step: int | None = None) -> np.ndarray:
        """1 for runs at or after the step's first run, 0 before, less its mean over the kept runs (so that
        predictions refer to the average run, as with drift)."""
        step = self.spec.step if step is None else step
        after = (self.data.runs.astype(float) >= float(self.data.runs[step])).astype(float)
        return after[rows] - float(np.mean(after[self.keep]))

    def new_run_row(self, coded: np.ndarray, later: int = 1) -> np.ndarray:
        """Model-matrix rows (m, p) of new runs made after every run so far, at coded points: blocks at their
        average, drift at the run number ``later`` runs after the last one, after a step."""
        coded = np.atleast_2d(coded)
        rows = [model_matrix(coded, self.mean_terms)]
        if self.data.blocks is not None:
            rows.append(np.zeros((len(coded), self.data.blocks.shape[1])))
        if self.spec.drift:
            nxt = (float(np.max(self.data.runs.astype(float))) + later - self.run_center) / self.run_scale
            rows.append(np.full((len(coded), 1), nxt))
        if self.spec.step is not None:
            after = (self.data.runs.astype(float) >= float(self.data.runs[self.spec.step])).astype(float)
            rows.append(np.full((len(coded), 1), 1.0 - float(np.mean(after[self.keep]))))
        return np.column_stack(rows)
    @property
    def n_params(self) -> int:
        """Mean parameters + sigma + transform/variance parameters + one per excluded run."""
        return (self.rank + 1 + self.spec.n_extra_params - len(self.spec.extra_terms) - int(self.spec.drift)
                - int(self.spec.step is not None))

    @property
    def loglik(self) -> float:
        """Gaussian log-likelihood of all n original observations (mean-shift for excluded runs)."""
        return self.loglik_with(self.ssr, self.w, self.spec.weight_gamma)

    def loglik_with(self, ssr: float, w: np.ndarray, gamma: float) -> float:
        """:attr:`loglik` of this model's form with weights ``w`` (kept runs) from ``gamma`` and the fit's
        weighted residual sum of squares ``ssr`` (:func:`demid.criticism.extensions.extend_for` searches the
        weights' gamma without a model per step)."""
        ll = gaussian_loglik(ssr, self.data.n) + 0.5 * float(np.sum(np.log(w)))
        if self.spec.weight_on is not None and self.spec.dropped:
            v = np.asarray(self.spec.weight_values, dtype=float)[~self.keep]
            ll += 0.5 * float(np.sum(-gamma * v))
        if self.spec.lam is not None:
            ll += (self.spec.lam - 1.0) * float(np.sum(np.log(self.data.y)))
        return float(ll)

    @property
    def aicc(self) -> float:
        return aicc_of(self.loglik, self.data.n, self.n_params)

    @property
    def fitted(self) -> np.ndarray:
        return inv_boxcox(self.fitted_z, self.spec.lam)

    @property
    def loo_errors(self) -> np.ndarray:
        """Exact leave-one-out prediction errors on the original scale, at the kept runs (NaN at runs
        the others do not predict, see :data:`~demid.design.LEVERAGE_UNPREDICTABLE`)."""
        with np.errstate(divide="ignore", invalid="ignore"):
            press_z = self.resid_w / (1.0 - self.hat) / self.sw
            err = self.y - inv_boxcox(self.z - press_z, self.spec.lam)
        return np.where(self.hat < LEVERAGE_UNPREDICTABLE, err, np.nan)

    @property
    def predictable(self) -> np.ndarray:
        """Runs (of all n) that this model keeps and that the other kept runs predict."""
        out = np.zeros(self.data.n, dtype=bool)
        out[self.keep] = self.hat < LEVERAGE_UNPREDICTABLE
        return out

    def loo_rmse_on(self, keep_mask: np.ndarray) -> float:
        """Leave-one-out RMSE over the runs in keep_mask that this model predicts."""
        err = np.full(self.data.n, np.nan)
        err[self.keep] = self.loo_errors
        chosen = err[keep_mask & self.predictable]
        return float(np.sqrt(np.mean(chosen ** 2))) if chosen.size else float("nan")

    def summary(self) -> dict:
        y, f = self.y, self.fitted
        sst = float(np.sum((y - y.mean()) ** 2))
        sse = float(np.sum((y - f) ** 2))
        s = self.spec
        return {
            "terms": list(self.names),
            # a constant response has no R²: its mean's round-off (0.1 on 13 runs) leaves sst ~1e-33, not 0
            "r2": json_number(1 - sse / sst) if np.ptp(y) > 0 else None,
            "rmse": json_number(np.sqrt(sse / len(y))),
            "loo_rmse": json_number(self.loo_rmse_on(self.keep)),
            "aicc": json_number(self.aicc),
            "n_runs": int(len(y)),
            "n_params": int(self.n_params),
            "transform": None if s.lam is None else transform_name(s.lam),
            "weighting": s.weight_on,
            "excluded_runs": [run_label(self.data.runs[i]) for i in s.dropped],
        }

    def surrogate(self) -> "ExtendedSurrogate":
        k = len(self.mean_terms)
        drift = float(self.beta[self.names.index("run")]) if self.spec.drift else 0.0
        return ExtendedSurrogate(
            response=self.data.response, factors=list(self.data.factors), coding=self.data.coding,
            terms=list(self.mean_terms), coefficients=self.beta[:k].copy(), lam=self.spec.lam,
            log_factors=self.data.log_factors, drift_per_run=drift / self.run_scale,
            reference_run=self.run_center, weighting=self.spec.weight_on,
            excluded_runs=tuple(run_label(self.data.runs[i]) for i in self.spec.dropped))


def transform_name(lam: float) -> str:
    """The name of a Box-Cox lambda: "log", "sqrt", "inverse" or "boxcox:<lambda>"."""
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
            out[start:start + chunk] = inv_boxcox(eta, self.lam)
        return out

"""Universal kriging: a quadratic trend with a Gaussian-process residual, the surrogate that can follow what one
global quadratic cannot (a response that saturates, oscillates, steps or bends into a corner).

The model of one response y at a point u of the unit cube over the search range Omega (log10 for log-scale
factors) is ``y(u) = f(u)'β + Z(u) + ε``: ``f`` the full quadratic in u, ``Z`` a zero-mean Gaussian process
of variance σ² with an anisotropic Matérn 5/2 correlation (one length per factor), ``ε`` independent scatter
of variance σ²·g (the nugget g: the runs are noisy).  The responses are standardised first (mean 0, sd 1) so
that one set of bounds on the lengths and the nugget serves every response.

With K = R + g I (R the correlation matrix of the runs), the generalised least-squares trend
``β̂ = (F'K⁻¹F)⁻¹ F'K⁻¹ y`` and the restricted-likelihood scale ``σ̂² = r'K⁻¹r / (n - p)`` (r = y - Fβ̂), the
prediction of the mean at u is ``f(u)'β̂ + k(u)'K⁻¹r`` and its variance
``σ̂² [1 - k'K⁻¹k + (f - F'K⁻¹k)' (F'K⁻¹F)⁻¹ (f - F'K⁻¹k)]``: the last term is the trend's own uncertainty.
A new run's prediction variance adds the scatter σ̂²·g.  The lengths and the nugget maximise the restricted
likelihood (L-BFGS-B from :data:`STARTS`, fixed, so a fit is deterministic).

The leave-one-out residuals with the hyper-parameters held are Dubrule's (1983) closed form:
``e_i = (K⁻¹r)_i / Q_ii`` with ``Q = K⁻¹ - K⁻¹F(F'K⁻¹F)⁻¹F'K⁻¹`` -- exactly the residual of a refit without
run i (trend re-estimated), so Q² = 1 - Σe² / Σ(y - ȳ)² compares with the quadratic's PRESS-based Q².

:class:`KrigingSurrogate` answers ``predict``, ``se_mean`` and ``se_prediction`` as
:class:`~demid.surrogate.Surrogate` does, so a judged scenario's strict and plausible sets and the next wave
use it unchanged (the set evaluator takes the grid for it: it is not a polynomial).  It has no coefficients:
the canonical analysis, the ANOVA and the criticism keep the quadratic (:data:`KIND` tells them apart).
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field, replace
from functools import cached_property

import numpy as np

#: What :attr:`KrigingSurrogate.kind` says; a quadratic surrogate has no ``kind`` (see :func:`surrogate_kind`).
KIND = "kriging"
QUADRATIC = "quadratic"
#: Bounds of the correlation lengths (unit-cube units) and of the nugget (a share of the process variance).
LENGTH_BOUNDS = (0.05, 5.0)
NUGGET_BOUNDS = (1e-6, 1.0)
#: Starting (length, nugget) pairs of the likelihood search, the same length on every factor.
STARTS = ((0.3, 0.05), (0.15, 0.01), (0.8, 0.2))
#: Added to K's diagonal: keeps the Cholesky factor of near-duplicate runs finite.
JITTER = 1e-10


def surrogate_kind(surrogate) -> str:
    """``kriging`` for a :class:`KrigingSurrogate` (or a field built on one), else ``quadratic``."""
    return getattr(surrogate, "kind", QUADRATIC)


def quadratic_trend(u: np.ndarray) -> np.ndarray:
    """The full quadratic in the unit-cube coordinates u (n x k): 1, u_i, u_i u_j (i < j), u_i²."""
    k = u.shape[1]
    columns = [np.ones(len(u))] + [u[:, i] for i in range(k)]
    columns += [u[:, i] * u[:, j] for i in range(k) for j in range(i + 1, k)]
    columns += [u[:, i] ** 2 for i in range(k)]
    return np.column_stack(columns)


def matern52(a: np.ndarray, b: np.ndarray, lengths: np.ndarray) -> np.ndarray:
    """The anisotropic Matérn 5/2 correlation between the rows of a and b."""
    d = np.sqrt(5.0 * np.sum(((a[:, None, :] - b[None, :, :]) / lengths) ** 2, axis=2))
    return (1.0 + d + d * d / 3.0) * np.exp(-d)


def _cho_solve(factor: np.ndarray, b: np.ndarray) -> np.ndarray:
    from scipy.linalg import cho_solve

    return cho_solve((factor, True), b)


@dataclass(frozen=True)
class GaussianSystem:
    """The linear algebra of one fit at fixed hyper-parameters: runs ``u`` (unit cube), standardised responses
    ``z``, correlation ``lengths`` and ``nugget``."""

    u: np.ndarray
    z: np.ndarray
    lengths: np.ndarray
    nugget: float

    @cached_property
    def trend(self) -> np.ndarray:
        return quadratic_trend(self.u)

    @cached_property
    def factor(self) -> np.ndarray:
        """The lower Cholesky factor of K = R + (g + jitter) I."""
        k = matern52(self.u, self.u, self.lengths) + (self.nugget + JITTER) * np.eye(len(self.u))
        return np.linalg.cholesky(k)

    @cached_property
    def ki_trend(self) -> np.ndarray:
        return _cho_solve(self.factor, self.trend)

    @cached_property
    def trend_information(self) -> np.ndarray:
        """F'K⁻¹F."""
        return self.trend.T @ self.ki_trend

    @cached_property
    def beta(self) -> np.ndarray:
        return np.linalg.solve(self.trend_information, self.ki_trend.T @ self.z)

    @cached_property
    def ki_resid(self) -> np.ndarray:
        """K⁻¹r, r = z - Fβ̂ (= Q z)."""
        return _cho_solve(self.factor, self.z - self.trend @ self.beta)

    @cached_property
    def sigma2(self) -> float:
        """The restricted-likelihood process variance r'K⁻¹r / (n - p) (standardised units)."""
        n, p = self.trend.shape
        return float((self.z - self.trend @ self.beta) @ self.ki_resid) / (n - p)

    def restricted_nll(self) -> float:
        """Minus the restricted log-likelihood with σ² profiled out (constants dropped)."""
        n, p = self.trend.shape
        return 0.5 * ((n - p) * np.log(max(self.sigma2, 1e-300)) + 2.0 * np.sum(np.log(np.diag(self.factor)))
                      + np.linalg.slogdet(self.trend_information)[1])

    def loo_residuals(self) -> np.ndarray:
        """Dubrule's leave-one-out residuals (standardised units): (Q z)_i / Q_ii."""
        ki = _cho_solve(self.factor, np.eye(len(self.u)))
        q = ki - self.ki_trend @ np.linalg.solve(self.trend_information, self.ki_trend.T)
        return self.ki_resid / np.diag(q)

    def mean(self, at: np.ndarray) -> np.ndarray:
        return quadratic_trend(at) @ self.beta + matern52(at, self.u, self.lengths) @ self.ki_resid

    def mean_variance(self, at: np.ndarray) -> np.ndarray:
        """Var of the predicted mean at ``at`` over σ̂², the trend's uncertainty included."""
        k_at = matern52(at, self.u, self.lengths)
        ki_k = _cho_solve(self.factor, k_at.T)  # n x m
        gap = quadratic_trend(at).T - self.ki_trend.T @ k_at.T  # p x m: f - F'K⁻¹k
        trend_part = np.sum(gap * np.linalg.solve(self.trend_information, gap), axis=0)
        return np.maximum(1.0 - np.sum(k_at.T * ki_k, axis=0) + trend_part, 0.0)


def fit_hyperparameters(u: np.ndarray, z: np.ndarray) -> tuple[np.ndarray, float]:
    """The lengths and nugget that maximise the restricted likelihood of standardised responses ``z`` at ``u``."""
    from scipy.optimize import minimize

    k = u.shape[1]

    def nll(theta):
        try:
            return GaussianSystem(u, z, np.exp(theta[:k]), float(np.exp(theta[k]))).restricted_nll()
        except np.linalg.LinAlgError:
            return 1e10

    bounds = [tuple(np.log(LENGTH_BOUNDS))] * k + [tuple(np.log(NUGGET_BOUNDS))]
    results = [minimize(nll, np.log([length] * k + [nugget]), method="L-BFGS-B", bounds=bounds)
               for length, nugget in STARTS]
    best = min(results, key=lambda r: (float(r.fun), tuple(r.x)))  # ties: the same pick every time
    return np.exp(best.x[:k]), float(np.exp(best.x[k]))


@dataclass(frozen=True, eq=False)
class KrigingSurrogate:
    """A universal-kriging surrogate of one response (see the module docstring), built from its runs ``x``
    (actual units), responses ``y``, the search bounds ``lower``/``upper`` (search units: log10 for log-scale
    factors) and its hyper-parameters.  ``offset``/``gain`` rescale its output as
    :func:`~demid.tolerance.rescaled_surrogate` rescales a polynomial (``y* + c (ŷ - y*)``)."""

    response: str
    factors: list[str]
    x: np.ndarray
    y: np.ndarray
    lower: np.ndarray
    upper: np.ndarray
    lengths: np.ndarray
    nugget: float
    log_factors: tuple[str, ...] = field(default_factory=tuple)
    offset: float = 0.0
    gain: float = 1.0
    kind: str = KIND

    @classmethod
    def fit(cls, response: str, factors, x, y, lower, upper, log_factors=()) -> KrigingSurrogate:
        """Fit the hyper-parameters by restricted likelihood and build the surrogate."""
        x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
        bare = cls(response, list(factors), x, y, np.asarray(lower, dtype=float), np.asarray(upper, dtype=float),
                   np.ones(len(factors)), 0.0, tuple(log_factors))
        lengths, nugget = fit_hyperparameters(bare.unit(x), bare.standardised)
        return replace(bare, lengths=lengths, nugget=nugget)

    # ------------------------------------------------------------------ coordinates and the fitted system
    def unit(self, points) -> np.ndarray:
        """Points in actual units as coordinates of the unit cube over the search range."""
        points = np.array(points, dtype=float, ndmin=2)
        for i, f in enumerate(self.factors):
            if f in self.log_factors:
                points[:, i] = np.log10(points[:, i])
        return (points - self.lower) / (self.upper - self.lower)

    @cached_property
    def y_center(self) -> float:
        return float(np.mean(self.y))

    @cached_property
    def y_scale(self) -> float:
        return float(np.std(self.y)) or 1.0

    @cached_property
    def standardised(self) -> np.ndarray:
        return (self.y - self.y_center) / self.y_scale

    @cached_property
    def system(self) -> GaussianSystem:
        return GaussianSystem(self.unit(self.x), self.standardised, np.asarray(self.lengths, dtype=float),
                              float(self.nugget))

    # ------------------------------------------------------------------ the Surrogate interface
    def predict(self, points, chunk: int = 4096) -> np.ndarray:
        u = self.unit(points)
        out = np.concatenate([self.system.mean(u[s:s + chunk]) for s in range(0, len(u), chunk)]) if len(u) else \
            np.empty(0)
        return self.offset + self.gain * (self.y_center + self.y_scale * out)

    def se_mean(self, points, chunk: int = 4096) -> np.ndarray:
        """Standard error of the predicted mean (the trend's uncertainty included)."""
        u = self.unit(points)
        var = (np.concatenate([self.system.mean_variance(u[s:s + chunk]) for s in range(0, len(u), chunk)])
               if len(u) else np.empty(0))
        return self._scale_sd(np.sqrt(self.system.sigma2 * var))

    def se_prediction(self, points) -> np.ndarray:
        """Standard error for a new run: the mean's and the scatter's."""
        return np.sqrt(self.se_mean(points) ** 2 + self.resid_var)

    @property
    def resid_var(self) -> float:
        """The scatter of one run (σ̂²·g), in the response's units (rescaled)."""
        return float((abs(self.gain) * self.y_scale) ** 2 * self.system.sigma2 * self.nugget)

    def _scale_sd(self, sd: np.ndarray) -> np.ndarray:
        return abs(self.gain) * self.y_scale * sd

    def rescaled(self, target: float, scale: float) -> KrigingSurrogate:
        """``target + scale (ŷ - target)`` with standard errors times ``scale`` (an own tolerance)."""
        return replace(self, offset=target + scale * (self.offset - target), gain=scale * self.gain)

    # ------------------------------------------------------------------ leave-one-out
    @cached_property
    def loo_residuals(self) -> np.ndarray:
        """Leave-one-out residuals y_i - ŷ_(-i) (hyper-parameters held), in the response's units."""
        return self.y_scale * self.system.loo_residuals()

    @cached_property
    def q2(self) -> float:
        """1 - PRESS / Σ(y - ȳ)², as the quadratic's Q²."""
        sst = float(np.sum((self.y - self.y.mean()) ** 2))
        return 1.0 - float(np.sum(self.loo_residuals ** 2)) / sst if sst > 0 else float("nan")

    def se_mean_after(self, points, new_runs) -> np.ndarray:
        """The standard error of the mean at ``points`` once runs at ``new_runs`` (actual units) are added, the
        hyper-parameters and σ̂² held (their values are not known before the runs are made)."""
        u_all = np.vstack([self.unit(self.x), self.unit(new_runs)])
        grown = GaussianSystem(u_all, np.zeros(len(u_all)), np.asarray(self.lengths, dtype=float), float(self.nugget))
        return self._scale_sd(np.sqrt(self.system.sigma2 * grown.mean_variance(self.unit(points))))

    # ------------------------------------------------------------------ storage
    def hyperparameters_json(self) -> str:
        """The fitted hyper-parameters as one JSON text (stored with the fit statistics)."""
        return json.dumps({"lengths": [float(v) for v in self.lengths], "nugget": float(self.nugget)},
                          sort_keys=True)

    @classmethod
    def from_hyperparameters(cls, response: str, factors, x, y, lower, upper, text: str,
                             log_factors=()) -> KrigingSurrogate:
        """The surrogate of stored hyper-parameters (:meth:`hyperparameters_json`) on the same runs: the same
        numbers as the fitted one, without the likelihood search."""
        hyper = json.loads(text)
        return cls(response, list(factors), np.asarray(x, dtype=float), np.asarray(y, dtype=float),
                   np.asarray(lower, dtype=float), np.asarray(upper, dtype=float),
                   np.asarray(hyper["lengths"], dtype=float), float(hyper["nugget"]), tuple(log_factors))

"""Beyond deterministic admissibility: uncertainty, tolerance sweeps, information gain, accuracy.

The admissible set of eq. (2) treats the surrogate as exact and the targets as
known.  This module adds what a calibration decision needs on top of it:

* **Robust (plausible) admissibility**, history-matching style: x is plausibly
  admissible when, for every observable k,
  ``|yhat_k(x) - y_k*| <= eps |y_k*| + z sqrt(se_mean_k(x)^2 + sigma_k^2)``,
  with ``se_mean`` the OLS standard error of the fitted mean (statsmodels'
  ``mean_se``) and ``sigma_k`` the measurement standard deviation of the target.
* **Tolerance sweeps** Phi(eps) and spans as functions of eps.
* **Grid posteriors**: a uniform prior on Omega (in search units: log10 for
  log-scale factors) and independent Gaussian likelihoods with variance
  ``sigma_k^2 + se_mean_k(x)^2``; marginal densities, equal-tailed credible
  intervals, posterior means and the information gain KL(posterior || prior)
  in bits, all by trapezoidal quadrature on the grid.
* **Which experiment next**: every non-empty subset of the observables ranked
  by information gain and feasible-fraction contraction, with advice in words.
* **Numerical accuracy**: fractions with an error estimate, spans polished to
  the exact set boundary by SLSQP, and randomised-QMC (scrambled Sobol)
  fractions with a confidence interval for materials with more than 3 factors.

:func:`analyse_material` runs all of it for one configured material with the
grid sizes of :func:`recommended_sizes`.

Measurement sigma: ``sigma`` (absolute) or ``sigma_rel`` (times |y*|) from the
response's config.  Robust sets use 0 when neither is configured (surrogate
uncertainty only).  Posteriors need a likelihood width; when neither is
configured the default is ``sigma_rel = tolerance / 2``, i.e. the scenario
tolerance is read as a two-sigma (about 95 %) band; outputs say which basis
was used (``sigma_basis``).
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass, field
from itertools import combinations, product
from math import factorial

import numpy as np
import pandas as pd
from scipy import interpolate, optimize, stats
from scipy.stats import qmc

from .admissibility import AdmissibleSet, Domain, admissible_set, cell_count, plane_band_fraction, predict_grid  # noqa: F401
from .surrogate import Surrogate

LN2 = float(np.log(2.0))

#: Column contracts of the tables this module feeds (the pipeline prepends ``material``).
ROBUST_COLUMNS = ["scenario", "observables", "tolerance", "z", "factor", "strict_fraction_pct",
                  "robust_fraction_pct", "strict_lower", "strict_upper", "strict_width",
                  "robust_lower", "robust_upper", "robust_width"]
SWEEP_COLUMNS = ["scenario", "observables", "tolerance", "feasible_fraction_pct", "factor",
                 "lower", "upper", "width"]
INFORMATION_GAIN_COLUMNS = ["observables", "n_observables", "information_gain_bits", "factor",
                            "credible_lower", "credible_upper", "posterior_mean"]
RANKING_COLUMNS = ["rank", "observables", "information_gain_bits", "feasible_fraction_pct",
                   "contraction_pct_vs_best_subset"]

#: Label of the empty observable set (the prior, Omega itself) in rankings.
NO_OBSERVABLE = "(none)"


def _join(observables) -> str:
    return "+".join(observables)


# =========================================================================== measurement sigma
def measurement_sigma(response_cfg: dict | None, target: float, default_rel: float | None = None) -> float:
    """Absolute measurement standard deviation of one target.

    ``sigma`` wins over ``sigma_rel`` (times |target|); without either,
    ``default_rel * |target|`` when a default is given, else 0.
    """
    cfg = response_cfg or {}
    if cfg.get("sigma") is not None:
        return float(cfg["sigma"])
    if cfg.get("sigma_rel") is not None:
        return float(cfg["sigma_rel"]) * abs(float(target))
    if default_rel is not None:
        return float(default_rel) * abs(float(target))
    return 0.0


def sigma_basis(response_cfg: dict | None, default_rel: float | None = None) -> str:
    """Where :func:`measurement_sigma` took its value from, in words for tables."""
    cfg = response_cfg or {}
    if cfg.get("sigma") is not None:
        return f"config sigma = {float(cfg['sigma']):g}"
    if cfg.get("sigma_rel") is not None:
        return f"config sigma_rel = {float(cfg['sigma_rel']):g}"
    if default_rel is not None:
        return f"default sigma_rel = {float(default_rel):g} (tolerance/2)"
    return "none (surrogate uncertainty only)"


def measurement_sigmas(responses_cfg: dict, observables, targets: dict[str, float],
                       tolerance: float | None = None) -> tuple[dict[str, float], dict[str, str]]:
    """Sigma and its basis for each observable; ``tolerance`` enables the tolerance/2 default."""
    default_rel = None if tolerance is None else float(tolerance) / 2.0
    sigma = {o: measurement_sigma(responses_cfg.get(o), targets[o], default_rel) for o in observables}
    basis = {o: sigma_basis(responses_cfg.get(o), default_rel) for o in observables}
    return sigma, basis


# =========================================================================== robust admissibility
@dataclass(frozen=True)
class PlausibilityField:
    """A surrogate-like field whose *strict* admissibility equals plausible admissibility.

    ``predict(x) = y* + (yhat(x) - y*) * b / (b + z s(x))`` with ``b = eps |y*|`` and
    ``s = sqrt(se_mean^2 + sigma^2)`` (``se_prediction`` instead of ``se_mean`` when
    ``predictive``).  ``|predict - y*| <= b`` iff ``|yhat - y*| <= b + z s``, and the
    field is smooth, so :func:`demid.admissibility.admissible_set` (cell classification,
    curvature margins, boundary refinement) applies unchanged.
    """

    surrogate: Surrogate
    target: float
    tolerance: float
    z: float
    sigma: float = 0.0
    predictive: bool = False

    def uncertainty(self, points) -> np.ndarray:
        se = self.surrogate.se_prediction(points) if self.predictive else self.surrogate.se_mean(points)
        return np.sqrt(se ** 2 + self.sigma ** 2)

    def predict(self, points) -> np.ndarray:
        yhat = self.surrogate.predict(points)
        band = self.tolerance * abs(self.target)
        if self.z == 0:
            return yhat
        return self.target + (yhat - self.target) * band / (band + self.z * self.uncertainty(points))


def plausibility_fields(surrogates: dict[str, Surrogate], observables, targets: dict[str, float],
                        tolerance: float, z: float, sigma: dict[str, float] | None = None,
                        predictive: bool = False) -> dict[str, PlausibilityField]:
    sigma = sigma or {}
    return {o: PlausibilityField(surrogates[o], float(targets[o]), float(tolerance), float(z),
                                 float(sigma.get(o, 0.0)), predictive) for o in observables}


def _fields(surrogates, observables, targets, tolerance, z, sigma) -> dict:
    """The surrogates themselves (strict sets) or their plausibility fields (z > 0)."""
    if z > 0:
        return plausibility_fields(surrogates, observables, targets, tolerance, z, sigma)
    return {o: surrogates[o] for o in observables}


def robust_admissible_set(surrogates: dict[str, Surrogate], domain: Domain, observables,
                          targets: dict[str, float], tolerance: float, n: int, *, z: float = 2.0,
                          sigma: dict[str, float] | None = None, predictive: bool = False,
                          subdivisions: int | None = None) -> AdmissibleSet:
    """Plausibly admissible set: ``|yhat - y*| <= eps |y*| + z sqrt(se_mean^2 + sigma^2)``.

    Same grid, boundary refinement and spans as the strict set, so robust contains strict
    point by point (tested).  ``sigma``: absolute measurement sd per observable (missing: 0).
    ``best_error`` of the result is ``eps * min_x max_k |yhat - y*| / (eps |y*| + z s)``,
    i.e. the smallest implausibility expressed in tolerance units.
    """
    observables = tuple(observables)
    fields = plausibility_fields(surrogates, observables, targets, tolerance, z, sigma, predictive)
    return admissible_set(fields, domain, observables, targets, tolerance, n, subdivisions=subdivisions)


# =========================================================================== fraction with error
@dataclass(frozen=True)
class FractionEstimate:
    """A feasible fraction with its numerical error (fractions of Omega, not percent).

    ``fraction`` is the cell estimate on the n-grid; ``error`` is its difference to the
    same estimate on the nested (n+1)/2 grid plus the root-sum-square of the cell-level
    differences (conservative: 3-6x the true error on annuli).  When the grid result of
    :func:`admissible_set` is passed as ``reference``, ``grid_fraction`` repeats it and
    ``grid_error = |grid_fraction - fraction| + error`` bounds its error.
    """

    fraction: float
    error: float
    coarse_fraction: float
    n: int
    evaluations: int
    analytic_cells: int
    sampled_cells: int
    grid_fraction: float = np.nan
    grid_error: float = np.nan

    @property
    def relative_error(self) -> float:
        return self.error / self.fraction if self.fraction > 0 else (0.0 if self.error == 0 else np.inf)


def _residual_evaluator(fields, observables, targets):
    def evaluate(x):
        return np.stack([(fields[o].predict(x) - targets[o]) / abs(targets[o]) for o in observables])
    return evaluate


def fraction_with_error(surrogates: dict[str, Surrogate], domain: Domain, observables,
                        targets: dict[str, float], tolerance: float, n: int, *, z: float = 0.0,
                        sigma: dict[str, float] | None = None, subdivisions: int | None = None,
                        grid_predictions: pd.DataFrame | None = None,
                        reference: AdmissibleSet | None = None) -> FractionEstimate:
    """Feasible fraction (strict, or plausible when ``z > 0``) with a numerical error estimate.

    Grid nodes give the residual fields; boundary cells are measured by the plane rule of
    :func:`~demid.admissibility.cell_count` (second order, no new evaluations) or sub-sampled.  The error
    compares with the nested (n+1)/2 grid (every second node: no new node evaluations),
    see :class:`FractionEstimate`.  ``n`` is rounded up to odd; ``grid_predictions``, if
    given, must be :func:`predict_grid` on that n.  Verified on annuli and spherical
    shells of exact volume (``benchmarks/admissibility.py``).
    """
    observables = tuple(observables)
    n = int(n) + (1 - int(n) % 2)
    d = domain.dim
    eps = float(tolerance)
    fields = _fields(surrogates, observables, targets, eps, z, sigma)
    if grid_predictions is None or z > 0:
        grid_predictions = predict_grid(fields, domain, n)
    resid = np.stack([(grid_predictions[o].to_numpy() - targets[o]) / abs(targets[o])
                      for o in observables]).reshape((len(observables),) + (n,) * d)
    evaluate = _residual_evaluator(fields, observables, targets)
    s = subdivisions or (16 if d <= 2 else 4)
    lo_u, hi_u = domain.search_bounds()
    step = (hi_u - lo_u) / (n - 1)
    fine = cell_count(resid, eps, domain, step, evaluate, s)
    coarse_resid = resid[(slice(None),) + (slice(None, None, 2),) * d]
    coarse = cell_count(coarse_resid, eps, domain, 2 * step, evaluate, s)
    # Cell-level discrepancies between the two grids do not cancel by luck: adding their
    # root-sum-square to the global difference keeps the estimate above the true error
    # (3-6x on annuli) where the global difference alone sometimes fell below it.
    blocks = fine.cells.reshape(tuple(x for m in fine.cells.shape for x in (m // 2, 2)))
    delta = coarse.cells - blocks.mean(axis=tuple(range(1, 2 * d, 2)))
    error = abs(fine.fraction - coarse.fraction) + float(np.sqrt(np.sum(delta ** 2))) / delta.size
    grid_fraction = grid_error = np.nan
    if reference is not None:
        grid_fraction = float(reference.fraction)
        grid_error = abs(grid_fraction - fine.fraction) + error
    return FractionEstimate(
        fraction=fine.fraction, error=error, coarse_fraction=coarse.fraction, n=n,
        evaluations=int(resid.size + fine.evaluations + coarse.evaluations),
        analytic_cells=fine.analytic_cells, sampled_cells=fine.sampled_cells,
        grid_fraction=grid_fraction, grid_error=grid_error)


# =========================================================================== span polishing
def _start_points(evaluate, domain: Domain, aset: AdmissibleSet) -> np.ndarray:
    """Grid nodes to start polishing from: admissible nodes, else the least-violating ones."""
    d = domain.dim
    n = int(round(aset.n_nodes ** (1.0 / d)))
    mask = np.asarray(aset.mask, dtype=bool)
    if mask.any():
        axes = domain.axes(n)
        return np.column_stack([axes[i][j] for i, j in enumerate(np.unravel_index(np.flatnonzero(mask), (n,) * d))])
    nodes = domain.grid(min(n, int(1e6 ** (1.0 / d))))
    worst = np.max(np.abs(evaluate(nodes)), axis=0)
    return nodes[np.argsort(worst)[:max(16, 2 * d)]]


def _polish(evaluate, domain: Domain, eps: float, lower: np.ndarray, upper: np.ndarray,
            candidates: np.ndarray, starts: int) -> tuple[np.ndarray, np.ndarray]:
    """Extend span ends by SLSQP from the most extreme candidate points (actual units)."""
    lo_u, hi_u = domain.search_bounds()
    scale = hi_u - lo_u

    def to_actual(v):
        return domain.to_actual(lo_u + np.clip(v, 0.0, 1.0) * scale)

    def constraints(v):
        r = evaluate(to_actual(v))[:, 0]
        return np.concatenate([eps - r, eps + r])

    unit = (domain.to_search(candidates) - lo_u) / scale
    lower_v = (domain.to_search(lower)[0] - lo_u) / scale
    upper_v = (domain.to_search(upper)[0] - lo_u) / scale
    for i in range(domain.dim):
        for sign in (1.0, -1.0):
            if (lower_v[i] <= 1e-12) if sign > 0 else (upper_v[i] >= 1 - 1e-12):
                continue  # the span already reaches the domain bound
            for v0 in unit[np.argsort(sign * unit[:, i])[:starts]]:
                with warnings.catch_warnings():
                    # SLSQP may step marginally outside the bounds; the point is re-checked below.
                    warnings.simplefilter("ignore", RuntimeWarning)
                    res = optimize.minimize(
                        lambda v, i=i, sign=sign: sign * v[i], v0,
                        jac=lambda v, i=i, sign=sign: sign * np.eye(len(v))[i],
                        method="SLSQP", bounds=[(0.0, 1.0)] * domain.dim,
                        constraints=[{"type": "ineq", "fun": constraints}],
                        options={"ftol": 1e-12, "maxiter": 300})
                v = np.clip(res.x, 0.0, 1.0)
                if np.max(np.abs(evaluate(to_actual(v))[:, 0])) > eps * (1 + 1e-9):
                    continue  # not admissible: keep the grid value
                if sign > 0:
                    lower_v[i] = min(lower_v[i], v[i])
                else:
                    upper_v[i] = max(upper_v[i], v[i])
    return domain.to_actual(lo_u + lower_v * scale)[0], domain.to_actual(lo_u + upper_v * scale)[0]


def polish_spans(surrogates: dict[str, Surrogate], domain: Domain, observables, targets: dict[str, float],
                 tolerance: float, admissible_set: AdmissibleSet, *, z: float = 0.0,
                 sigma: dict[str, float] | None = None, starts: int = 3) -> tuple[np.ndarray, np.ndarray]:
    """Span ends moved to the exact set boundary by SLSQP (``min/max x_i`` s.t. ``|r_k(x)| <= eps``).

    Starts from the grid's extreme admissible nodes (the ``starts`` nodes with the most
    extreme x_i; the least-violating nodes when no node is admissible).  A polished end is
    accepted only if the optimiser's point is admissible (to 1e-9 relative) and extends
    the span, so the result is never worse than the grid value.  Pass ``z``/``sigma`` to
    polish a plausible set.  Works in search units (log10 for log factors) scaled to
    [0, 1].  Verified against the exact extent of annuli.
    """
    observables = tuple(observables)
    eps = float(tolerance)
    lower = np.array(admissible_set.lower, dtype=float, copy=True)
    upper = np.array(admissible_set.upper, dtype=float, copy=True)
    if admissible_set.empty or not np.isfinite(lower).all():
        return lower, upper
    fields = _fields(surrogates, observables, targets, eps, z, sigma)
    evaluate = _residual_evaluator(fields, observables, targets)
    return _polish(evaluate, domain, eps, lower, upper, _start_points(evaluate, domain, admissible_set), starts)


# =========================================================================== Sobol fraction
@dataclass(frozen=True)
class SobolFraction:
    """Randomised-QMC feasible fraction: mean over independent scrambles with a t interval.

    ``lower``/``upper`` are the spans: the extreme admissible sample points, polished to
    the exact boundary unless ``polish=False``.
    """

    fraction: float
    std_error: float
    ci_lower: float
    ci_upper: float
    confidence: float
    replicates: int
    points_per_replicate: int
    evaluations: int
    lower: np.ndarray
    upper: np.ndarray


def _extreme_points(points: np.ndarray, per_side: int = 3) -> np.ndarray:
    """The ``per_side`` points with the smallest and the largest value of each coordinate."""
    keep = set()
    for i in range(points.shape[1]):
        order = np.argsort(points[:, i])
        keep.update(order[:per_side].tolist())
        keep.update(order[-per_side:].tolist())
    return points[sorted(keep)]


def sobol_fraction(surrogates: dict[str, Surrogate], domain: Domain, observables, targets: dict[str, float],
                   tolerance: float, n_points: int, seed: int, *, replicates: int = 16,
                   confidence: float = 0.95, z: float = 0.0, sigma: dict[str, float] | None = None,
                   polish: bool = True) -> SobolFraction:
    """Feasible fraction from ``replicates`` independently scrambled Sobol sequences.

    Each replicate holds ``2**m`` points with ``2**m * replicates`` as close to
    ``n_points`` as possible; the replicate means are i.i.d. and unbiased, so a Student-t
    interval on them is a valid confidence interval (checked for coverage on a 4-ball).
    Points are uniform in search units.  With ``polish`` the spans are extended to the
    exact boundary from the extreme admissible points as in :func:`polish_spans`.
    """
    observables = tuple(observables)
    eps = float(tolerance)
    fields = _fields(surrogates, observables, targets, eps, z, sigma)
    evaluate = _residual_evaluator(fields, observables, targets)
    m = max(1, int(round(np.log2(max(n_points / replicates, 2)))))
    rng = np.random.default_rng(seed)
    lo_u, hi_u = domain.search_bounds()
    d = domain.dim
    means = np.empty(replicates)
    extremes = []
    for rep in range(replicates):
        u = lo_u + qmc.Sobol(d, scramble=True, rng=rng).random_base2(m) * (hi_u - lo_u)
        ok = np.all(np.abs(evaluate(domain.to_actual(u))) <= eps, axis=0)
        means[rep] = ok.mean()
        if ok.any():
            extremes.append(_extreme_points(u[ok]))
    fraction = float(means.mean())
    se = float(means.std(ddof=1) / np.sqrt(replicates))
    half = float(stats.t.ppf(0.5 + confidence / 2, replicates - 1)) * se
    if extremes:
        points = domain.to_actual(np.vstack(extremes))
        lower, upper = points.min(axis=0), points.max(axis=0)
        if polish:
            lower, upper = _polish(evaluate, domain, eps, lower, upper, points, starts=3)
    else:
        lower = upper = np.full(d, np.nan)
    return SobolFraction(fraction, se, max(0.0, fraction - half), min(1.0, fraction + half), confidence,
                         replicates, 2 ** m, replicates * 2 ** m * len(observables), lower, upper)


# =========================================================================== posterior
@dataclass
class Posterior:
    """Grid posterior of one observable set under a uniform prior on Omega (search units).

    ``marginals[i]`` is the density of factor i per search unit (per log10 unit for
    log-scale factors) at ``axes[i]`` (search units); ``axes_actual`` gives the same
    nodes in actual units.  Credible intervals are equal-tailed, means are in actual
    units, and the information gain is KL(posterior || prior) in bits with its
    numerical error (difference to the nested (n+1)/2 grid).
    """

    observables: tuple[str, ...]
    factors: tuple[str, ...]
    log: tuple[bool, ...]
    n: int
    axes: list[np.ndarray]
    marginals: list[np.ndarray]
    mean: np.ndarray
    credible_lower: np.ndarray
    credible_upper: np.ndarray
    information_gain_bits: float
    information_gain_error_bits: float
    level: float = 0.95
    sigma: dict[str, float] = field(default_factory=dict)
    sigma_basis: dict[str, str] = field(default_factory=dict)

    @property
    def axes_actual(self) -> list[np.ndarray]:
        return [10.0 ** a if lg else a for a, lg in zip(self.axes, self.log)]

    @property
    def credible_width(self) -> np.ndarray:
        return self.credible_upper - self.credible_lower

    def to_frame(self) -> pd.DataFrame:
        """Rows of ``information_gain.csv`` (contract columns first, then provenance)."""
        basis = "; ".join(f"{o}: {self.sigma_basis.get(o, f'sigma = {self.sigma.get(o, np.nan):g}')}"
                          for o in self.observables)
        return pd.DataFrame({
            "observables": _join(self.observables),
            "n_observables": len(self.observables),
            "information_gain_bits": self.information_gain_bits,
            "factor": list(self.factors),
            "credible_lower": self.credible_lower,
            "credible_upper": self.credible_upper,
            "posterior_mean": self.mean,
            "credible_width": self.credible_width,
            "credible_level": self.level,
            "information_gain_error_bits": self.information_gain_error_bits,
            "grid_points": self.n,
            "sigma_basis": basis,
        })

    def marginal_frame(self) -> pd.DataFrame:
        """Long table: observables, factor, value (actual units), density (per search unit)."""
        return pd.concat([pd.DataFrame({"observables": _join(self.observables), "factor": f,
                                        "value": ax, "density": m})
                          for f, ax, m in zip(self.factors, self.axes_actual, self.marginals)],
                         ignore_index=True)


def _trapezoid_weights(axis: np.ndarray) -> np.ndarray:
    h = np.diff(axis)
    w = np.zeros(len(axis))
    w[:-1] += h / 2
    w[1:] += h / 2
    return w


def _weighted_sum(values: np.ndarray, weights: list[np.ndarray], keep: int | None = None) -> np.ndarray:
    """Trapezoidal integral of an n^d array over all axes except ``keep``."""
    out = values
    for axis in reversed(range(values.ndim)):
        if axis == keep:
            continue
        out = np.tensordot(out, weights[axis], axes=([axis], [0]))
    return out


def _quantiles(axis: np.ndarray, density: np.ndarray, probs) -> np.ndarray:
    """Quantiles of a density known at grid nodes.

    The CDF at the nodes is the trapezoidal rule with its Euler-Maclaurin end correction
    (``-h^2/12 [f']``), interpolated by the cubic Hermite spline whose slopes are the
    density itself; both steps are fourth order in the grid step.
    """
    h = np.diff(axis)
    slope = np.gradient(density, axis)
    cdf = np.concatenate([[0.0], np.cumsum(h * (density[:-1] + density[1:]) / 2)])
    cdf -= h[0] ** 2 / 12 * (slope - slope[0])
    cdf = np.maximum.accumulate(np.maximum(cdf, 0.0))
    spline = interpolate.CubicHermiteSpline(axis, cdf / cdf[-1], density / cdf[-1])
    out = []
    for q in probs:
        roots = spline.solve(q, extrapolate=False)
        roots = roots[np.isfinite(roots)]
        j = int(np.clip(np.searchsorted(cdf / cdf[-1], q), 1, len(axis) - 1))
        out.append(float(roots[np.argmin(np.abs(roots - axis[j]))]) if len(roots)
                   else float(np.interp(q, cdf / cdf[-1], axis)))
    return np.array(out)


def _kl_bits(loglik: np.ndarray, weights: list[np.ndarray], volume: float) -> float:
    ll = loglik - loglik.max()
    like = np.exp(ll)
    z = float(_weighted_sum(like, weights))
    p = like / z
    with np.errstate(divide="ignore", invalid="ignore"):
        term = np.where(p > 0, p * (ll - np.log(z) + np.log(volume)), 0.0)
    return max(0.0, float(_weighted_sum(term, weights))) / LN2


def posterior_from_loglik(loglik: np.ndarray, domain: Domain, observables, *, level: float = 0.95,
                          sigma: dict[str, float] | None = None,
                          sigma_basis: dict[str, str] | None = None) -> Posterior:
    """Normalise a log-likelihood given on the n^d grid of ``domain`` into a :class:`Posterior`."""
    d = domain.dim
    n = loglik.shape[0]
    axes = domain.search_axes(n)
    weights = [_trapezoid_weights(a) for a in axes]
    lo_u, hi_u = domain.search_bounds()
    volume = float(np.prod(hi_u - lo_u))
    ll = loglik - loglik.max()
    like = np.exp(ll)
    z = float(_weighted_sum(like, weights))
    p = like / z
    marginals, means, lows, highs = [], [], [], []
    tail = (1.0 - level) / 2
    for i, lg in enumerate(domain.log):
        m = _weighted_sum(p, weights, keep=i)
        m = m / float(np.dot(weights[i], m))
        marginals.append(m)
        actual = 10.0 ** axes[i] if lg else axes[i]
        means.append(float(np.dot(weights[i], m * actual)))
        q = _quantiles(axes[i], m, [tail, 1.0 - tail])
        q = 10.0 ** q if lg else q
        lows.append(q[0])
        highs.append(q[1])
    ig = _kl_bits(loglik, weights, volume)
    if n % 2 == 1 and n >= 5:
        coarse = loglik[(slice(None, None, 2),) * d]
        ig_coarse = _kl_bits(coarse, [_trapezoid_weights(a[::2]) for a in axes], volume)
        ig_error = abs(ig - ig_coarse)
    else:
        ig_error = np.nan
    return Posterior(tuple(observables), tuple(domain.factors), tuple(domain.log), n, axes, marginals,
                     np.array(means), np.array(lows), np.array(highs), ig, ig_error, level,
                     dict(sigma or {}), dict(sigma_basis or {}))


def gaussian_loglik(surrogate: Surrogate, points: np.ndarray, target: float, sigma: float,
                    predictive: bool = False) -> np.ndarray:
    """log N(y*; yhat(x), sigma^2 + se_mean(x)^2) at every point (``se_prediction`` if predictive)."""
    se = surrogate.se_prediction(points) if predictive else surrogate.se_mean(points)
    var = se ** 2 + float(sigma) ** 2
    if np.any(var <= 0):
        raise ValueError(f"zero likelihood variance for '{surrogate.response}': give a measurement sigma")
    resid = surrogate.predict(points) - target
    return -0.5 * (resid ** 2 / var + np.log(2 * np.pi * var))


def grid_posterior(surrogates: dict[str, Surrogate], domain: Domain, observables, targets: dict[str, float],
                   sigma: dict[str, float], n: int, *, level: float = 0.95, predictive: bool = False,
                   sigma_basis: dict[str, str] | None = None) -> Posterior:
    """Posterior on the n^d grid: uniform prior, independent Gaussian likelihoods per observable.

    Likelihood variance ``sigma_k^2 + se_mean_k(x)^2``.  Verified against the closed-form
    truncated-normal posterior of a linear surrogate (interval, mean, KL divergence).
    Use odd n so that the information gain comes with its numerical error.
    """
    return subset_posteriors(surrogates, domain, observables, targets, sigma, n, level=level,
                             predictive=predictive, sigma_basis=sigma_basis,
                             subsets=[tuple(observables)])[tuple(observables)]


def subset_posteriors(surrogates: dict[str, Surrogate], domain: Domain, observables, targets: dict[str, float],
                      sigma: dict[str, float], n: int, *, level: float = 0.95, predictive: bool = False,
                      sigma_basis: dict[str, str] | None = None, subsets=None, sobol_points: int = 2 ** 16,
                      seed: int = 0) -> dict[tuple[str, ...], Posterior]:
    """Posteriors of every non-empty subset of ``observables`` (or of the given ``subsets``).

    The per-observable log-likelihoods are computed once and summed per subset.  Up to
    3 factors on the n^d grid; more factors by self-normalised importance sampling from
    scrambled Sobol points of the prior (``sobol_points``), marginals as n-bin histograms.
    """
    observables = tuple(observables)
    if subsets is None:
        subsets = [c for size in range(1, len(observables) + 1) for c in combinations(observables, size)]
    subsets = [tuple(s) for s in subsets]
    needed = sorted({o for s in subsets for o in s}, key=list(observables).index)
    sigma_basis = {o: (sigma_basis or {}).get(o, f"sigma = {sigma[o]:g}") for o in needed}
    if domain.dim > 3:
        return _qmc_posteriors(surrogates, domain, needed, targets, sigma, subsets, bins=n, points=sobol_points,
                               seed=seed, level=level, predictive=predictive, sigma_basis=sigma_basis)
    points = domain.grid(n)
    shape = (n,) * domain.dim
    terms = {o: gaussian_loglik(surrogates[o], points, targets[o], sigma[o], predictive).reshape(shape)
             for o in needed}
    out = {}
    for s in subsets:
        ll = np.sum([terms[o] for o in s], axis=0)
        out[s] = posterior_from_loglik(ll, domain, s, level=level, sigma={o: sigma[o] for o in s},
                                       sigma_basis={o: sigma_basis[o] for o in s})
    return out


def _weighted_quantiles(values: np.ndarray, weights: np.ndarray, probs) -> np.ndarray:
    order = np.argsort(values)
    cdf = np.cumsum(weights[order])
    cdf = (cdf - weights[order] / 2) / cdf[-1]
    return np.interp(probs, cdf, values[order])


def _qmc_posteriors(surrogates, domain: Domain, observables, targets, sigma, subsets, *, bins: int, points: int,
                    seed: int, level: float, predictive: bool, sigma_basis: dict) -> dict:
    """Posteriors from prior samples weighted by the likelihood (for more than 3 factors).

    KL(post || prior) = sum_i w_i log(w_i / mean(w)) / sum_i w_i with w the likelihood at
    uniform scrambled-Sobol points; its error is the standard error over 8 independent
    scrambles.  Checked against a closed-form truncated-normal case in 4 factors.
    """
    replicates = 8
    m = max(4, int(round(np.log2(max(points / replicates, 16)))))
    rng = np.random.default_rng(seed)
    lo_u, hi_u = domain.search_bounds()
    u = np.vstack([lo_u + qmc.Sobol(domain.dim, scramble=True, rng=rng).random_base2(m) * (hi_u - lo_u)
                   for _ in range(replicates)])
    x = domain.to_actual(u)
    terms = {o: gaussian_loglik(surrogates[o], x, targets[o], sigma[o], predictive) for o in observables}
    edges = [np.linspace(a, b, bins + 1) for a, b in zip(lo_u, hi_u)]
    tail = (1.0 - level) / 2

    def kl(ll):
        w = np.exp(ll - ll.max())
        return float(np.sum(w * np.log(np.maximum(w, 1e-300) / w.mean())) / w.sum())

    out = {}
    for s in subsets:
        ll = np.sum([terms[o] for o in s], axis=0)
        w = np.exp(ll - ll.max())
        per_rep = [kl(part) for part in np.split(ll, replicates)]
        marginals, means, lows, highs = [], [], [], []
        for i, lg in enumerate(domain.log):
            density, _ = np.histogram(u[:, i], bins=edges[i], weights=w, density=True)
            marginals.append(density)
            means.append(float(np.sum(w * x[:, i]) / w.sum()))
            q = _weighted_quantiles(u[:, i], w, [tail, 1.0 - tail])
            q = 10.0 ** q if lg else q
            lows.append(q[0])
            highs.append(q[1])
        out[s] = Posterior(tuple(s), tuple(domain.factors), tuple(domain.log), bins,
                           [(e[:-1] + e[1:]) / 2 for e in edges], marginals, np.array(means), np.array(lows),
                           np.array(highs), kl(ll) / LN2, float(np.std(per_rep, ddof=1) / np.sqrt(replicates)) / LN2,
                           level, {o: sigma[o] for o in s}, {o: sigma_basis[o] for o in s})
    return out


def information_gain_frame(posteriors: dict) -> pd.DataFrame:
    """``information_gain.csv``: one row per observable set and factor."""
    return pd.concat([p.to_frame() for p in posteriors.values()], ignore_index=True)


# =========================================================================== which experiment next
def rank_observable_sets(surrogates: dict[str, Surrogate], domain: Domain, observables_with_targets,
                         targets: dict[str, float], sigma: dict[str, float], tolerance: float, n: int, *,
                         posteriors: dict | None = None, fraction_n: int | None = None,
                         sobol_points: int = 2 ** 16) -> pd.DataFrame:
    """Rank every non-empty observable subset by information gain (bits), then by fraction.

    Columns: rank, observables, information_gain_bits, feasible_fraction_pct (strict, at
    ``tolerance``), contraction_pct_vs_best_subset = 100 (1 - Phi(S) / min_{T < S} Phi(T))
    over proper subsets T (the empty set is Omega, Phi = 1) and best_subset (that T), then
    gain_vs_best_subset_bits = IG(S) - max_{T < S} IG(T), n_observables, rank_by_fraction,
    information_gain_error_bits.
    """
    observables = tuple(observables_with_targets)
    subsets = [c for size in range(1, len(observables) + 1) for c in combinations(observables, size)]
    if posteriors is None:
        posteriors = subset_posteriors(surrogates, domain, observables, targets, sigma, n, subsets=subsets,
                                       sobol_points=sobol_points)
    fn = fraction_n or n
    grid = predict_grid({o: surrogates[o] for o in observables}, domain, fn) if domain.dim <= 3 else None
    frac = {(): 1.0}
    gain = {(): 0.0}
    for s in subsets:
        frac[s] = summarise_set(surrogates, domain, s, targets, tolerance, fn, polish=False, with_error=False,
                                sobol_points=sobol_points, grid_predictions=grid).fraction
        gain[s] = posteriors[s].information_gain_bits
    rows = []
    for s in subsets:
        proper = [t for size in range(len(s)) for t in combinations(s, size)]
        best = min(proper, key=lambda t: (frac[t], -gain[t]))
        contraction = 100.0 * (1.0 - frac[s] / frac[best]) if frac[best] > 0 else np.nan
        rows.append({
            "observables": _join(s), "information_gain_bits": gain[s],
            "feasible_fraction_pct": 100.0 * frac[s], "contraction_pct_vs_best_subset": contraction,
            "n_observables": len(s), "best_subset": _join(best) or NO_OBSERVABLE,
            "gain_vs_best_subset_bits": gain[s] - max(gain[t] for t in proper),
            "information_gain_error_bits": posteriors[s].information_gain_error_bits,
            "tolerance": float(tolerance),
        })
    frame = pd.DataFrame(rows)
    frame["rank_by_fraction"] = frame["feasible_fraction_pct"].rank(method="min").astype(int)
    frame = frame.sort_values(["information_gain_bits", "feasible_fraction_pct"],
                              ascending=[False, True], kind="stable").reset_index(drop=True)
    frame.insert(0, "rank", np.arange(1, len(frame) + 1))
    return frame


def _pct(value: float) -> str:
    return f"{value:.3g} %"


def next_measurement_advice(ranking: pd.DataFrame, labels: dict[str, str] | None = None) -> str:
    """In words: from each smaller observable set, which single added measurement gains most.

    Uses the ``observables``, ``information_gain_bits`` and ``feasible_fraction_pct``
    columns of :func:`rank_observable_sets`.  One sentence per starting set (the first
    for starting from nothing), naming the runner-up and any disagreement with the
    fraction criterion.
    """
    labels = labels or {}

    def name(obs) -> str:
        return " + ".join(labels.get(o, o) for o in obs)

    sets = {tuple(str(s).split("+")): (float(g), float(f)) for s, g, f in
            zip(ranking["observables"], ranking["information_gain_bits"], ranking["feasible_fraction_pct"])}
    order = [o for o in max(sets, key=len)]
    sets[()] = (0.0, 100.0)
    by_members = {frozenset(k): k for k in sets}
    lines = []
    for size in range(len(order)):
        for start in combinations(order, size):
            base_gain, base_frac = sets[by_members[frozenset(start)]]
            options = []
            for o in order:
                if o in start or frozenset(start) | {o} not in by_members:
                    continue
                g, f = sets[by_members[frozenset(start) | {o}]]
                options.append((g - base_gain, f, o, g))
            if not options:
                continue
            options.sort(key=lambda t: (-t[0], t[1]))
            delta, f_new, best, g_new = options[0]
            if not start:
                text = (f"As a first measurement, {name([best])} is the most informative: "
                        f"{g_new:.2f} bits, admissible fraction {_pct(f_new)} of the domain")
            else:
                text = (f"From {name(start)}, adding {name([best])} gains {delta:.2f} bits "
                        f"({base_gain:.2f} -> {g_new:.2f})")
                if base_frac > 0 and 1 - f_new / base_frac < 5e-4:
                    text += f" but leaves the admissible fraction at {_pct(f_new)}"
                elif base_frac > 0:
                    text += (f" and shrinks the admissible fraction by {100 * (1 - f_new / base_frac):.1f} % "
                             f"({_pct(base_frac)} -> {_pct(f_new)})")
                else:
                    text += " (the admissible set is already empty at this tolerance)"
            if len(options) > 1:
                text += f"; {name([options[1][2]])} would gain {options[1][0]:.2f} bits"
                by_frac = min(options, key=lambda t: t[1])
                if by_frac[2] != best and by_frac[1] < f_new:
                    text += (f"; by fraction alone {name([by_frac[2]])} contracts more "
                             f"({_pct(by_frac[1])} vs {_pct(f_new)})")
            lines.append(text + ".")
    return "\n".join(lines)


# =========================================================================== tables
@dataclass(frozen=True)
class SetSummary:
    """Fraction (of Omega), its numerical error and the spans of one admissible set."""

    fraction: float
    error: float
    lower: np.ndarray
    upper: np.ndarray
    method: str

    @property
    def width(self) -> np.ndarray:
        return self.upper - self.lower


def summarise_set(surrogates: dict[str, Surrogate], domain: Domain, observables, targets: dict[str, float],
                  tolerance: float, n: int, *, z: float = 0.0, sigma: dict[str, float] | None = None,
                  polish: bool = True, with_error: bool = True, sobol_points: int = 2 ** 16, seed: int = 0,
                  grid_predictions: pd.DataFrame | None = None, grid_set: AdmissibleSet | None = None) -> SetSummary:
    """One strict (z = 0) or plausible set by the method that suits the dimension.

    Up to 3 factors: :func:`admissible_set` on the n-grid (``grid_set`` if already
    computed), spans polished, error from :func:`fraction_with_error` (``grid_error``).
    More factors: :func:`sobol_fraction` with ``sobol_points`` points; the error is the
    half-width of its 95 % confidence interval.
    """
    observables = tuple(observables)
    if domain.dim > 3:
        res = sobol_fraction(surrogates, domain, observables, targets, tolerance, sobol_points, seed,
                             z=z, sigma=sigma, polish=polish)
        return SetSummary(res.fraction, (res.ci_upper - res.ci_lower) / 2, res.lower, res.upper,
                          f"scrambled Sobol, {res.replicates} x {res.points_per_replicate} points")
    aset = grid_set
    if aset is None:
        aset = (admissible_set(surrogates, domain, observables, targets, tolerance, n,
                               grid_predictions=grid_predictions) if z == 0 else
                robust_admissible_set(surrogates, domain, observables, targets, tolerance, n, z=z, sigma=sigma))
    lower, upper = aset.lower, aset.upper
    if polish:
        lower, upper = polish_spans(surrogates, domain, observables, targets, tolerance, aset, z=z, sigma=sigma)
    error = np.nan
    if with_error:
        preds = grid_predictions if (z == 0 and n % 2 == 1) else None
        error = fraction_with_error(surrogates, domain, observables, targets, tolerance, n, z=z, sigma=sigma,
                                    grid_predictions=preds, reference=aset).grid_error
    return SetSummary(aset.fraction, error, lower, upper, f"grid {n}^{domain.dim} with boundary refinement")


def robust_identifiability_frame(surrogates: dict[str, Surrogate], domain: Domain, scenarios: dict,
                                 targets: dict[str, float], n: int, *, z: float = 2.0,
                                 sigma: dict[str, float] | None = None, polish: bool = True,
                                 strict_sets: dict[str, AdmissibleSet] | None = None,
                                 sobol_points: int = 2 ** 16, seed: int = 0) -> pd.DataFrame:
    """``robust_identifiability.csv``: strict and plausible sets side by side per scenario and factor.

    ``scenarios``: name -> (observables, tolerance).  ``strict_sets`` (name -> the
    pipeline's strict :class:`AdmissibleSet`) are reused when they were computed on the
    same n-grid.
    Spans are polished to the exact boundary unless ``polish`` is False.  Trailing
    columns give the numerical error of both fractions (percentage points).
    """
    frames = []
    for name, (observables, tolerance) in scenarios.items():
        observables = tuple(observables)
        common = dict(polish=polish, sobol_points=sobol_points, seed=seed)
        given = (strict_sets or {}).get(name)
        if given is not None and given.n_nodes != n ** domain.dim:
            given = None  # computed on another grid: recompute so that both sets share one grid
        strict = summarise_set(surrogates, domain, observables, targets, tolerance, n, grid_set=given, **common)
        robust = summarise_set(surrogates, domain, observables, targets, tolerance, n, z=z, sigma=sigma, **common)
        frames.append(pd.DataFrame({
            "scenario": name, "observables": _join(observables), "tolerance": float(tolerance),
            "z": float(z), "factor": list(domain.factors),
            "strict_fraction_pct": 100.0 * strict.fraction, "robust_fraction_pct": 100.0 * robust.fraction,
            "strict_lower": strict.lower, "strict_upper": strict.upper, "strict_width": strict.width,
            "robust_lower": robust.lower, "robust_upper": robust.upper, "robust_width": robust.width,
            "strict_fraction_error_pct": 100.0 * strict.error, "robust_fraction_error_pct": 100.0 * robust.error,
            "method": strict.method,
        }))
    return pd.concat(frames, ignore_index=True)


def tolerance_sweep(surrogates: dict[str, Surrogate], domain: Domain, scenarios: dict,
                    targets: dict[str, float], tolerances, n: int, *, z: float = 0.0,
                    sigma: dict[str, float] | None = None, with_error: bool = True, polish: bool = False,
                    sobol_points: int = 2 ** 14, seed: int = 0) -> pd.DataFrame:
    """Phi(eps) and spans for every scenario at every tolerance (long form, one row per factor).

    ``scenarios``: name -> (observables, nominal tolerance); the nominal tolerance is added
    to ``tolerances``.  Strict sets by default, plausible sets when ``z > 0``.  With
    ``with_error`` a trailing ``fraction_error_pct`` column bounds the numerical error of
    each fraction.  More than 3 factors: scrambled Sobol points instead of the grid.
    """
    needed = sorted({o for obs, _ in scenarios.values() for o in obs})
    base = (predict_grid({o: surrogates[o] for o in needed}, domain, n)
            if z == 0 and domain.dim <= 3 else None)
    frames = []
    for name, (observables, nominal) in scenarios.items():
        observables = tuple(observables)
        for eps in sorted(set(float(t) for t in tolerances) | {float(nominal)}):
            res = summarise_set(surrogates, domain, observables, targets, eps, n, z=z, sigma=sigma, polish=polish,
                                with_error=with_error, sobol_points=sobol_points, seed=seed, grid_predictions=base)
            frame = pd.DataFrame({
                "scenario": name, "observables": _join(observables), "tolerance": eps,
                "feasible_fraction_pct": 100.0 * res.fraction, "factor": list(domain.factors),
                "lower": res.lower, "upper": res.upper, "width": res.width})
            if with_error:
                frame["fraction_error_pct"] = 100.0 * res.error
            frames.append(frame)
    return pd.concat(frames, ignore_index=True)


# =========================================================================== one material
#: Default tolerances of the sweep (the config's ``sweep_tolerances`` default).
DEFAULT_SWEEP_TOLERANCES = (0.005, 0.01, 0.02, 0.03, 0.05, 0.075, 0.1, 0.15, 0.2)
#: Tolerance used for default sigmas and the ranking when a material has no scenario.
FALLBACK_TOLERANCE = 0.02


def recommended_sizes(dim: int) -> dict[str, int]:
    """Grid points per axis (Sobol points / histogram bins above 3 factors) per analysis.

    Chosen on demo-like materials so that fractions agree with a 1001-point (2 factors)
    or 201-point (3 factors) grid to < 0.1 % relative, spans are exact after polishing,
    and information gains agree with a 5x finer grid to < 0.01 bit, while the three
    demo materials take a few seconds together.
    """
    if dim <= 2:
        return {"robust": 401, "sweep": 201, "posterior": 401}
    if dim == 3:
        return {"robust": 61, "sweep": 41, "posterior": 61}
    return {"robust": 2 ** 16, "sweep": 2 ** 14, "posterior": 51, "posterior_points": 2 ** 16}


@dataclass
class MaterialUncertainty:
    """Everything :func:`analyse_material` computes for one material."""

    robust: pd.DataFrame
    sweep: pd.DataFrame
    information_gain: pd.DataFrame
    ranking: pd.DataFrame
    advice: str
    posteriors: dict
    notes: list[str]
    factor_labels: dict[str, str] = field(default_factory=dict)

    def sweep_figure(self, title: str):
        return tolerance_sweep_figure(self.sweep, title, factor_labels=self.factor_labels)

    def posterior_figure(self, title: str):
        return posterior_figure(self.posteriors, title, factor_labels=self.factor_labels)


def _reference_tolerance(scenarios: dict) -> float:
    """Tolerance of the scenario with the most observables (ties: the smallest tolerance)."""
    if not scenarios:
        return FALLBACK_TOLERANCE
    return min(scenarios.values(), key=lambda sc: (-len(sc[0]), sc[1]))[1]


def analyse_material(surrogates: dict[str, Surrogate], material_cfg: dict, *, z: float = 2.0,
                     tolerances=DEFAULT_SWEEP_TOLERANCES, sizes: dict[str, int] | None = None,
                     strict_sets: dict[str, AdmissibleSet] | None = None, seed: int = 0) -> MaterialUncertainty:
    """Robust sets, tolerance sweep, posteriors, ranking and advice for one configured material.

    ``material_cfg`` is one entry of the config's ``materials`` (factors, responses with
    ``target`` and optional ``sigma``/``sigma_rel``, scenarios).  Robust sets use the
    configured measurement sigma only (0 when absent); posteriors and the ranking use it
    or, when absent, ``sigma_rel`` = reference tolerance / 2, where the reference
    tolerance is that of the scenario with the most observables.  ``notes`` states the
    grid sizes and sigma bases used, for the report.
    """
    domain = Domain.from_config(material_cfg["factors"])
    responses = material_cfg.get("responses") or {}
    targets = {r: float(c["target"]) for r, c in responses.items()
               if c.get("target") is not None and r in surrogates}
    scenarios = {name: (tuple(sc["observables"]), float(sc["tolerance"]))
                 for name, sc in (material_cfg.get("scenarios") or {}).items()}
    sizes = {**recommended_sizes(domain.dim), **(sizes or {})}
    tolerance = _reference_tolerance(scenarios)
    observables = list(targets)
    robust_sigma, robust_basis = measurement_sigmas(responses, observables, targets)
    post_sigma, post_basis = measurement_sigmas(responses, observables, targets, tolerance)
    labels = {r: (responses[r].get("label") or r) for r in observables}
    factor_labels = {f: (c.get("label") or f) for f, c in material_cfg["factors"].items()}

    robust = sweep = None
    if scenarios:
        robust = robust_identifiability_frame(surrogates, domain, scenarios, targets, sizes["robust"], z=z,
                                              sigma=robust_sigma, strict_sets=strict_sets,
                                              sobol_points=sizes["robust"], seed=seed)
        sweep = tolerance_sweep(surrogates, domain, scenarios, targets, tolerances, sizes["sweep"],
                                sobol_points=sizes["sweep"], seed=seed)
    points = sizes.get("posterior_points", 2 ** 16)
    posteriors = subset_posteriors(surrogates, domain, observables, targets, post_sigma, sizes["posterior"],
                                   sigma_basis=post_basis, sobol_points=points, seed=seed) if observables else {}
    ranking = (rank_observable_sets(surrogates, domain, observables, targets, post_sigma, tolerance,
                                    sizes["posterior"], posteriors=posteriors, sobol_points=points)
               if observables else pd.DataFrame(columns=RANKING_COLUMNS))
    grid_word = "scrambled Sobol points" if domain.dim > 3 else "grid points per axis"
    notes = [
        f"Robust sets: z = {z:g}; " + "; ".join(f"{o}: {robust_basis[o]}" for o in observables) + ".",
        f"Posteriors and ranking at tolerance {tolerance:g}: "
        + "; ".join(f"{o}: {post_basis[o]}" for o in observables) + ".",
        f"Robust sets on {sizes['robust']} {grid_word}, sweeps on {sizes['sweep']}, "
        + (f"posteriors on {points} scrambled Sobol points ({sizes['posterior']} histogram bins)."
           if domain.dim > 3 else f"posteriors on {sizes['posterior']} grid points per axis."),
    ]
    if not scenarios:
        notes.append(f"No scenarios configured: ranking and default sigma use tolerance {FALLBACK_TOLERANCE:g}.")
    empty_robust = pd.DataFrame(columns=ROBUST_COLUMNS)
    return MaterialUncertainty(
        robust=robust if robust is not None else empty_robust,
        sweep=sweep if sweep is not None else pd.DataFrame(columns=SWEEP_COLUMNS),
        information_gain=information_gain_frame(posteriors) if posteriors else
        pd.DataFrame(columns=INFORMATION_GAIN_COLUMNS),
        ranking=ranking, advice=next_measurement_advice(ranking, labels) if len(ranking) else "",
        posteriors=posteriors, notes=notes, factor_labels=factor_labels)


# =========================================================================== figures
def tolerance_sweep_figure(frame: pd.DataFrame, title: str, *, factor_labels: dict[str, str] | None = None):
    """Phi(eps) on a log scale (one curve per observable set) and one span panel per factor."""
    from matplotlib.figure import Figure

    factor_labels = factor_labels or {}
    factors = list(dict.fromkeys(frame["factor"]))
    fig = Figure(figsize=(4.2 * (1 + len(factors)), 3.6), layout="constrained")
    axes = fig.subplots(1, 1 + len(factors), squeeze=False)[0]
    for k, (scenario, rows) in enumerate(frame.groupby("scenario", sort=False)):
        color = f"C{k}"
        label = f"{scenario}: {rows['observables'].iloc[0]}"
        first = rows.drop_duplicates("tolerance").sort_values("tolerance")
        tol_pct = 100 * first["tolerance"].to_numpy()
        frac = first["feasible_fraction_pct"].to_numpy()
        positive = frac > 0
        axes[0].plot(tol_pct[positive], frac[positive], "o-", color=color, label=label)
        if "fraction_error_pct" in first:
            err = first["fraction_error_pct"].to_numpy()
            axes[0].errorbar(tol_pct[positive], frac[positive], yerr=err[positive], fmt="none", color=color)
        for ax, factor in zip(axes[1:], factors):
            sub = rows[rows["factor"] == factor].sort_values("tolerance")
            ax.plot(100 * sub["tolerance"], sub["width"], "o-", color=color, label=label)
    if (frame["feasible_fraction_pct"] > 0).any():
        axes[0].set_yscale("log")
        axes[0].legend(fontsize="small")
    else:  # a log axis of all zeros cannot be drawn; say what the empty panel means
        axes[0].text(0.5, 0.5, "no admissible point at any swept tolerance:\nthe targets are out of reach",
                     transform=axes[0].transAxes, ha="center", va="center")
    axes[0].set_xlabel("tolerance ε [%]")
    axes[0].set_ylabel("feasible fraction Φ(ε) [% of Ω]")
    for ax, factor in zip(axes[1:], factors):
        ax.set_xlabel("tolerance ε [%]")
        ax.set_ylabel(f"admissible width of {factor_labels.get(factor, factor)}")
    for ax in axes:
        ax.set_xscale("log")
        ax.grid(True, which="both", alpha=0.3)
    fig.suptitle(title)
    return fig


def posterior_figure(posteriors: dict, title: str, *, factor_labels: dict[str, str] | None = None):
    """Marginal posterior densities per factor, one curve per observable set, 95 % intervals shaded."""
    from matplotlib.figure import Figure

    factor_labels = factor_labels or {}
    posts = list(posteriors.values())
    factors = posts[0].factors
    fig = Figure(figsize=(4.2 * len(factors), 3.4), layout="constrained")
    axes = fig.subplots(1, len(factors), squeeze=False)[0]
    for k, post in enumerate(posts):
        label = f"{_join(post.observables)} ({post.information_gain_bits:.2f} bits)"
        for i, ax in enumerate(axes):
            x = post.axes_actual[i]
            ax.plot(x, post.marginals[i], color=f"C{k}", label=label)
            inside = (x >= post.credible_lower[i]) & (x <= post.credible_upper[i])
            ax.fill_between(x, 0, post.marginals[i], where=inside, color=f"C{k}", alpha=0.15)
            if post.log[i]:
                ax.set_xscale("log")
    for i, ax in enumerate(axes):
        ax.set_xlabel(factor_labels.get(factors[i], factors[i]))
        ax.set_ylabel("posterior density" + (" per log10 unit" if posts[0].log[i] else ""))
    axes[0].legend(fontsize="small")
    fig.suptitle(title)
    return fig

"""Grid posteriors and information gain.

A uniform prior on Omega (in search units: log10 for log-scale factors) and
independent Gaussian likelihoods with variance ``sigma_k^2 + se_mean_k(x)^2``;
marginal densities, equal-tailed credible intervals, posterior means and the
information gain KL(posterior || prior) in bits, all by trapezoidal quadrature on
the grid (on scrambled Sobol points with histogram marginals above 3 factors).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from itertools import combinations
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from ..sampling import uses_grid
from ..spec import join_observables

if TYPE_CHECKING:
    from ..sampling import Domain
    from ..surrogate import Surrogate


LN2 = float(np.log(2.0))


INFORMATION_GAIN_COLUMNS = ["observables", "n_observables", "information_gain_bits", "factor",
                            "credible_lower", "credible_upper", "posterior_mean"]


#: Label of the empty observable set (the prior, Omega itself) in rankings.
NO_OBSERVABLE = "(none)"


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
            "observables": join_observables(self.observables),
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
        return pd.concat([pd.DataFrame({"observables": join_observables(self.observables), "factor": f,
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
    density itself: fourth order in the grid step where the density vanishes at the range's ends, third where
    the range cuts it (tests/uncertainty/test_posterior_interval_order_whole.py).
    """
    h = np.diff(axis)
    slope = np.gradient(density, axis)
    cdf = np.concatenate([[0.0], np.cumsum(h * (density[:-1] + density[1:]) / 2)])
    cdf -= h[0] ** 2 / 12 * (slope - slope[0])
    cdf = np.maximum.accumulate(np.maximum(cdf, 0.0))
    from scipy import interpolate  # on first use: the uncertainty step's start-up stays light

    share = cdf / cdf[-1]
    spline = interpolate.CubicHermiteSpline(axis, share, density / cdf[-1])
    out = []
    for q in probs:
        roots = spline.solve(q, extrapolate=False)
        roots = roots[np.isfinite(roots)]
        # the node where the CDF first reaches q, 1 to n - 1: the CDF runs from 0 to 1 and 0 < q < 1
        j = int(np.searchsorted(share, q))
        out.append(float(roots[np.argmin(np.abs(roots - axis[j]))]) if len(roots)
                   else float(np.interp(q, share, axis)))
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
    if not uses_grid(domain.dim):
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
    from scipy.stats import qmc  # only above 3 factors: scipy.stats is a slow import

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

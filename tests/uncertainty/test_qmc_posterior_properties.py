"""Posteriors above three factors (importance sampling from scrambled Sobol points) over generated search ranges
away from the origin (negative, shifted, scaled, some factors on a log scale) and 1-2 observables of either sign:
each factor's mean, equal-tailed 95 % interval and the information gain against a weighted Monte Carlo sample
written out here (numpy's uniform points, scipy's normal density), the marginals' axes the bins' mid-points of
the search range and each marginal a density over it."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import stats

from demid.design import quadratic_terms
from demid.sampling.domain import Domain
from demid.surrogate import Surrogate
from demid.uncertainty.posterior import subset_posteriors


def _linear(name: str, k: int, intercept: float, slopes) -> Surrogate:
    terms = quadratic_terms(k)
    coef = np.zeros(len(terms))
    coef[0], coef[1:1 + k] = intercept, slopes
    return Surrogate(name, [f"f{i}" for i in range(k)], terms, coef, np.zeros((len(terms), len(terms))), 0.0, 1, ())


def _weighted_quantile(values, weights, q):
    order = np.argsort(values)
    cdf = np.cumsum(weights[order]) / weights.sum()
    return np.interp(q, cdf, values[order])


@given(k=st.integers(4, 5), count=st.integers(1, 2), seed=st.integers(0, 10_000), log_mask=st.integers(0, 31),
       sign=st.sampled_from([1.0, -1.0]))
@settings(max_examples=6, deadline=None, derandomize=True)
def test_a_posterior_above_three_factors_matches_a_weighted_monte_carlo_sample(k, count, seed, log_mask, sign):
    rng = np.random.default_rng(seed)
    log = tuple(bool(log_mask >> i & 1) for i in range(k))
    # search units (log10 for a log factor), linear factors at scales 0.01 to 100
    scale = np.where(log, 1.0, 10.0 ** rng.integers(-2, 3, k))
    lo_s = rng.uniform(-3.0, 3.0, k) * scale
    hi_s = lo_s + rng.uniform(0.5, 2.0, k) * scale
    lower = tuple(np.where(log, 10.0 ** lo_s, lo_s))
    upper = tuple(np.where(log, 10.0 ** hi_s, hi_s))
    factors = tuple(f"f{i}" for i in range(k))
    domain = Domain(factors, lower, upper, log)
    # each observable linear in the actual values of two factors (on a log factor: no polynomial of its search
    # units, which importance sampling does not need); targets reached inside the range
    names = [f"y{j}" for j in range(count)]
    surrogates, targets, sigma = {}, {}, {}
    mc = rng.uniform(size=(200_000, k))
    u = lo_s + mc * (hi_s - lo_s)
    x = np.where(log, 10.0 ** u, u)
    loglik = np.zeros(len(u))
    for j, name in enumerate(names):
        slopes = np.zeros(k)
        pair = rng.choice(k, 2, replace=False)
        slopes[pair] = rng.uniform(0.5, 2.0, 2) / (np.array(upper) - np.array(lower))[pair]
        intercept = sign * 10.0
        sur = _linear(name, k, intercept, sign * slopes)
        middle = lo_s + 0.5 * (hi_s - lo_s)
        inside = np.where(log, 10.0 ** middle, middle)
        targets[name] = float(sur.predict(inside[None, :])[0])
        sigma[name] = 0.15
        surrogates[name] = sur
        loglik += stats.norm.logpdf(targets[name], loc=sur.predict(x), scale=sigma[name])
    subset = tuple(names)
    post = subset_posteriors(surrogates, domain, names, targets, sigma, 40, subsets=[subset], seed=3)[subset]
    w = np.exp(loglik - loglik.max())
    span = hi_s - lo_s
    for i in range(k):
        edges = np.linspace(lo_s[i], hi_s[i], 41)
        assert np.allclose(post.axes[i], (edges[:-1] + edges[1:]) / 2)
        assert abs(np.sum(post.marginals[i] * np.diff(edges)) - 1.0) < 1e-9
        mean = np.sum(w * x[:, i]) / w.sum()
        assert abs(post.mean[i] - mean) <= 0.02 * (upper[i] - lower[i]), (i, post.mean[i], mean)
        q_lo, q_hi = _weighted_quantile(u[:, i], w, [0.025, 0.975])
        found = np.array([post.credible_lower[i], post.credible_upper[i]])
        found = np.log10(found) if log[i] else found
        assert np.all(np.abs(found - [q_lo, q_hi]) <= 0.03 * span[i]), (i, found, q_lo, q_hi)
    gain = np.sum(w * np.log(w / w.mean())) / w.sum() / np.log(2)
    assert abs(post.information_gain_bits - gain) <= 0.05 * gain + 0.05

"""Posteriors above three factors, every output on the very points they are computed from: eight scrambled Sobol
replicates of the prior drawn here with scipy (the documented sample: seed, 2^m points each), the likelihood written
out, and from its weights the information gain in bits, its standard error over the replicates (in bits too), each
factor's weighted mean in actual units, the equal-tailed interval of the weighted midpoint quantiles, the histogram
marginals and their bin centres.  4-5 factors, some on a log scale, 1-2 observables of either sign, levels and sizes."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import Phase, given, settings, strategies as st
from scipy.stats import norm, qmc

from demid.design import quadratic_terms
from demid.sampling.domain import Domain
from demid.surrogate import Surrogate
from demid.uncertainty.posterior import subset_posteriors

REPLICATES = 8


def _linear(name: str, k: int, intercept: float, slopes, log_factors) -> Surrogate:
    terms = quadratic_terms(k)
    coef = np.zeros(len(terms))
    coef[0], coef[1:1 + k] = intercept, slopes
    return Surrogate(name, [f"f{i}" for i in range(k)], terms, coef, np.zeros((len(terms), len(terms))), 0.0, 1,
                     log_factors)


def _midpoint_quantile(values, weights, q):
    """Weighted quantile with each point's weight centred on it (numpy's 'hazen' rule for equal weights)."""
    order = np.argsort(values)
    w = weights[order]
    cdf = (np.cumsum(w) - w / 2) / w.sum()
    return float(np.interp(q, cdf, values[order]))


def _actual(search, log):
    """Actual units of search units: 10^u on a log factor (a linear factor's values are never raised)."""
    return np.where(log, 10.0 ** np.where(log, search, 0.0), search)


def _gain_bits(loglik):
    w = np.exp(loglik - loglik.max())
    p = w / w.sum()
    return float(np.sum(p * np.log(np.maximum(w, 1e-300) / w.mean()))) / np.log(2)


@settings(max_examples=6, deadline=None, derandomize=True, phases=(Phase.explicit, Phase.generate))
@given(k=st.integers(4, 5), count=st.integers(1, 2), seed=st.integers(0, 10_000), log_mask=st.integers(0, 31),
       sign=st.sampled_from([1.0, -1.0]), points=st.sampled_from([2 ** 10, 3000, 2 ** 12]),
       bins=st.sampled_from([7, 12]), level=st.sampled_from([0.95, 0.8]), sobol_seed=st.integers(0, 3))
def test_every_output_above_three_factors_is_computed_from_the_prior_sample(k, count, seed, log_mask, sign, points,
                                                                           bins, level, sobol_seed):
    rng = np.random.default_rng(seed)
    log = tuple(bool(log_mask >> i & 1) for i in range(k))
    scale = np.where(log, 1.0, 10.0 ** rng.integers(-2, 3, k))
    lo_s = rng.uniform(-3.0, 3.0, k) * scale
    hi_s = lo_s + rng.uniform(0.5, 2.0, k) * scale
    factors = tuple(f"f{i}" for i in range(k))
    domain = Domain(factors, tuple(_actual(lo_s, log)), tuple(_actual(hi_s, log)), log)
    log_factors = tuple(f for f, lg in zip(factors, log) if lg)
    names = [f"y{j}" for j in range(count)]
    surrogates, targets, sigma = {}, {}, {}
    for name in names:
        slopes = rng.uniform(0.5, 2.0, k) / (hi_s - lo_s) * rng.choice([-1.0, 1.0], k)
        surrogates[name] = _linear(name, k, sign * 10.0, slopes, log_factors)
        at = lo_s + rng.uniform(0.3, 0.7, k) * (hi_s - lo_s)
        targets[name] = float(sign * 10.0 + slopes @ at)
        sigma[name] = float(rng.uniform(0.05, 0.5))
    posteriors = subset_posteriors(surrogates, domain, names, targets, sigma, bins, level=level,
                                   sobol_points=points, seed=sobol_seed)

    m = max(4, int(round(np.log2(max(points / REPLICATES, 16)))))
    draw = np.random.default_rng(sobol_seed)
    u = np.vstack([lo_s + qmc.Sobol(k, scramble=True, rng=draw).random_base2(m) * (hi_s - lo_s)
                   for _ in range(REPLICATES)])
    x = _actual(u, log)
    loglik = {o: norm.logpdf(targets[o], loc=(sign * 10.0 + u @ surrogates[o].coefficients[1:1 + k]), scale=sigma[o])
              for o in names}
    for s, post in posteriors.items():
        ll = np.sum([loglik[o] for o in s], axis=0)
        w = np.exp(ll - ll.max())
        assert post.n == bins and post.level == level and post.factors == factors
        assert post.information_gain_bits == pytest.approx(_gain_bits(ll), rel=1e-9, abs=1e-12)
        per_replicate = [_gain_bits(part) for part in np.split(ll, REPLICATES)]
        assert post.information_gain_error_bits == pytest.approx(
            np.std(per_replicate, ddof=1) / np.sqrt(REPLICATES), rel=1e-9, abs=1e-12)
        for i in range(k):
            assert post.mean[i] == pytest.approx(np.sum(w * x[:, i]) / w.sum(), rel=1e-9)
            for bound, q in ((post.credible_lower[i], (1 - level) / 2), (post.credible_upper[i], (1 + level) / 2)):
                expected = _midpoint_quantile(u[:, i], w, q)
                assert bound == pytest.approx(10.0 ** expected if log[i] else expected, rel=1e-9)
            edges = np.linspace(lo_s[i], hi_s[i], bins + 1)
            counts = np.array([w[(u[:, i] >= a) & ((u[:, i] < b) if j < bins - 1 else (u[:, i] <= b))].sum()
                               for j, (a, b) in enumerate(zip(edges[:-1], edges[1:]))])
            np.testing.assert_allclose(post.marginals[i], counts / w.sum() / np.diff(edges), rtol=1e-9)
            np.testing.assert_allclose(post.axes[i], (edges[:-1] + edges[1:]) / 2, rtol=1e-12)

"""An observable that no factor moves carries no information, however far its target: it adds the same constant to
the log-likelihood at every point, so the posterior of a set with it is the posterior of the set without it (every
mean, interval end, marginal density, information gain and its error), on the grid (2-3 factors) and on the Sobol
sample (4-5 factors), with targets missed by up to 60 sigma (a log-likelihood of about -1800 everywhere), either sign,
log and linear factors."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings, strategies as st

from demid.uncertainty.posterior import subset_posteriors

from ..generators import random_domain
from .test_qmc_posterior_whole import _linear


@settings(max_examples=6, deadline=None, derandomize=True)
@given(k=st.integers(2, 5), seed=st.integers(0, 10_000), log_mask=st.integers(0, 31),
       sign=st.sampled_from([1.0, -1.0]), miss=st.sampled_from([0.0, 3.0, 40.0, 60.0]))
def test_a_flat_observable_leaves_the_posterior_as_it_is(k, seed, log_mask, sign, miss):
    rng = np.random.default_rng(seed)
    domain, lo_s, hi_s = random_domain(rng, k, log_mask, lower=(-2.0, 2.0))
    log, factors = domain.log, domain.factors
    log_factors = tuple(f for f, lg in zip(factors, log) if lg)
    slopes = rng.uniform(0.5, 2.0, k) / (hi_s - lo_s) * rng.choice([-1.0, 1.0], k)
    at = lo_s + rng.uniform(0.3, 0.7, k) * (hi_s - lo_s)
    surrogates = {"y": _linear("y", k, sign * 10.0, slopes, log_factors),
                  "flat": _linear("flat", k, -sign * 5.0, np.zeros(k), log_factors)}
    sigma = {"y": float(rng.uniform(0.05, 0.5)), "flat": 0.2}
    targets = {"y": float(sign * 10.0 + slopes @ at), "flat": -sign * 5.0 + sign * miss * sigma["flat"]}
    posteriors = subset_posteriors(surrogates, domain, ["y", "flat"], targets, sigma, 9, sobol_points=2 ** 10,
                                   subsets=[("y",), ("y", "flat")])
    alone, with_flat = posteriors[("y",)], posteriors[("y", "flat")]
    for got, expected in ((with_flat.mean, alone.mean), (with_flat.credible_lower, alone.credible_lower),
                          (with_flat.credible_upper, alone.credible_upper)):
        assert np.all(np.isfinite(got))
        np.testing.assert_allclose(got, expected, rtol=1e-9)
    for got, expected in zip(with_flat.marginals, alone.marginals):
        np.testing.assert_allclose(got, expected, rtol=1e-9, atol=1e-12 * np.max(expected))
    np.testing.assert_allclose(with_flat.information_gain_bits, alone.information_gain_bits, rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(with_flat.information_gain_error_bits, alone.information_gain_error_bits,
                               rtol=1e-9, atol=1e-12)
    assert alone.information_gain_bits > 0.0

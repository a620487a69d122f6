"""The posterior's quantiles (credible intervals) against closed forms: densities x^k on ranges of different
signs and scales, whose CDF is ((x - a)/(b - a))^(k+1), including densities with much of their mass at the
range's upper end (where the CDF's last step matters); the likelihood's and the plausible band's width (the mean's
error and σ, the residual scatter only when predictive) against the truncated normal and the closed-form span;
the error a set above three factors reports, the half-width of its fraction's confidence interval."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.uncertainty.posterior import _quantiles


@given(k=st.integers(0, 3), a=st.floats(-50.0, 50.0), span=st.floats(1e-3, 1e3), n=st.integers(21, 201),
       increasing=st.booleans())
@settings(max_examples=60, deadline=None, derandomize=True)
def test_quantiles_of_a_power_density_match_its_closed_form(k, a, span, n, increasing):
    b = a + span
    axis = np.linspace(a, b, n)
    t = (axis - a) / span
    density = (t if increasing else 1.0 - t) ** k * 7.3  # unnormalised: the scale must not matter
    probs = [0.025, 0.16, 0.5, 0.84, 0.975]
    found = _quantiles(axis, density, probs)
    # CDF of t^k is t^(k+1); of (1-t)^k it is 1 - (1-t)^(k+1)
    exact = [q ** (1 / (k + 1)) if increasing else 1 - (1 - q) ** (1 / (k + 1)) for q in probs]
    tolerance = 1e-9 if k <= 1 else 2e-3  # a linear density's CDF is a quadratic: the cubic spline is exact
    assert np.allclose((found - a) / span, exact, atol=tolerance)
    assert np.all(np.diff(found) > 0)


def test_a_ramp_rising_to_the_upper_end_has_its_median_at_one_over_root_two():
    axis = np.linspace(0.0, 1.0, 11)
    assert _quantiles(axis, 2 * axis, [0.5])[0] == pytest.approx(2 ** -0.5, abs=1e-12)


@pytest.mark.parametrize("sigma", [0.02, 0.3])
def test_a_sharp_likelihood_above_three_factors_gives_the_truncated_normals_mean_and_interval(sigma):
    """Four factors (importance sampling from Sobol points): y = 2 + 3a with a measurement σ so small that the
    log-likelihood spans thousands of nats over the range; the posterior of a is still the normal N(0.8, σ/3)."""
    from tests.uncertainty.test_uncertainty import linear

    from demid.sampling.domain import Domain
    from demid.uncertainty.posterior import subset_posteriors

    factors = ("a", "b", "c", "d")
    domain = Domain(factors, (0.0, 0.0, 0.0, 0.0), (10.0, 1.0, 1.0, 1.0))
    post = subset_posteriors({"y": linear(2.0, [3.0, 0.0, 0.0, 0.0], 0.0, factors)}, domain, ["y"], {"y": 4.4},
                             {"y": sigma}, 51, seed=2)[("y",)]
    sd = sigma / 3.0
    assert post.mean[0] == pytest.approx(0.8, abs=max(0.2 * sd, 1e-3))
    assert np.all(np.isfinite([post.credible_lower[0], post.credible_upper[0], post.information_gain_bits]))
    assert post.credible_lower[0] < 0.8 < post.credible_upper[0]
    assert np.allclose(post.mean[1:], 0.5, atol=0.02)


@pytest.mark.parametrize("predictive", [False, True])
def test_the_likelihood_width_is_the_mean_error_by_default_and_adds_the_scatter_when_predictive(predictive):
    """y = 2 + 3a, se_mean² = 0.25 everywhere and a residual variance of 4: the a-posterior is the truncated normal
    of sd √(σ² + 0.25)/3 by default, √(σ² + 0.25 + 4)/3 for a predictive likelihood."""
    from scipy import stats

    from demid.design import quadratic_terms
    from demid.sampling.domain import Domain
    from demid.surrogate import Surrogate
    from demid.uncertainty.posterior import grid_posterior

    terms = quadratic_terms(2)
    cov = np.zeros((len(terms), len(terms)))
    cov[0, 0] = 0.25
    coef = np.zeros(len(terms))
    coef[:3] = [2.0, 3.0, 0.0]
    surrogate = Surrogate("y", ["a", "b"], terms, coef, cov, 4.0, 7)
    domain = Domain(("a", "b"), (0.0, 0.0), (10.0, 1.0))
    sigma, mu = 1.5, 2.5
    options = {"predictive": True} if predictive else {}
    post = grid_posterior({"y": surrogate}, domain, ["y"], {"y": 2.0 + 3.0 * mu}, {"y": sigma}, 201, **options)
    sd = np.sqrt(sigma ** 2 + 0.25 + (4.0 if predictive else 0.0)) / 3.0
    exact = stats.truncnorm((0.0 - mu) / sd, (10.0 - mu) / sd, loc=mu, scale=sd)
    assert np.allclose([post.credible_lower[0], post.credible_upper[0]], exact.ppf([0.025, 0.975]), rtol=1e-3)


@pytest.mark.parametrize("sigma", [0.5, 2.0])
def test_a_plausible_set_is_judged_by_the_means_error_and_sigma_not_the_residual_scatter(sigma):
    """y = 2 + 3a, se_mean² = 0.25, a residual variance of 4: the plausible set |ŷ − y*| <= z √(se² + σ²) is the
    interval mu ± z √(0.25 + σ²)/3 in a (the scatter of single runs is not the mean's error)."""
    from demid.design import quadratic_terms
    from demid.sampling.domain import Domain
    from demid.surrogate import Surrogate
    from demid.uncertainty.plausible import plausible_admissible_set

    terms = quadratic_terms(2)
    cov = np.zeros((len(terms), len(terms)))
    cov[0, 0] = 0.25
    coef = np.zeros(len(terms))
    coef[:3] = [2.0, 3.0, 0.0]
    surrogate = Surrogate("y", ["a", "b"], terms, coef, cov, 4.0, 7)
    domain = Domain(("a", "b"), (0.0, 0.0), (10.0, 1.0))
    mu = 4.0
    found = plausible_admissible_set({"y": surrogate}, domain, ["y"], {"y": 2.0 + 3.0 * mu}, 0.05, 201, z=2.0,
                                  sigma={"y": sigma})
    half = 2.0 * np.sqrt(0.25 + sigma ** 2) / 3.0
    assert found.lower[0] == pytest.approx(mu - half, abs=0.06) and found.upper[0] == pytest.approx(mu + half, abs=0.06)


def test_a_set_above_three_factors_reports_the_half_width_of_its_fractions_confidence_interval():
    from tests.uncertainty.test_uncertainty import linear

    from demid.sampling.domain import Domain
    from demid.sampling.sobol import sobol_fraction
    from demid.uncertainty.plausible import summarise_set

    factors = ("a", "b", "c", "d")
    domain = Domain(factors, (0.0,) * 4, (1.0,) * 4)
    surrogates = {"y": linear(1.0, [1.0, 1.0, 0.0, 0.0], 0.0, factors)}
    found = summarise_set(surrogates, domain, ["y"], {"y": 2.0}, 0.1, 11, sobol_points=2 ** 12, seed=3, z=0.5,
                          sigma={"y": 0.05}, polish=False)
    direct = sobol_fraction(surrogates, domain, ["y"], {"y": 2.0}, 0.1, 2 ** 12, 3, z=0.5, sigma={"y": 0.05},
                            polish=False)
    assert found.fraction == direct.fraction and direct.ci_upper > direct.ci_lower
    assert found.error == pytest.approx((direct.ci_upper - direct.ci_lower) / 2, rel=1e-12)


@pytest.mark.parametrize("n", [1, 2, 5, 40])
def test_weighted_quantiles_of_equal_weights_are_the_midpoint_quantiles(n):
    """Equal weights put the k-th smallest of n values at probability (k - 1/2)/n (Hazen's plotting position,
    numpy's method="hazen"), for any common weight, ties and unsorted input included."""
    from demid.uncertainty.posterior import _weighted_quantiles

    rng = np.random.default_rng(n)
    values = np.round(rng.normal(size=n), 1)
    probs = [0.0, 0.025, 0.1, 0.5, 0.9, 0.975, 1.0]
    for weight in (1.0, 3e-7):
        got = _weighted_quantiles(values, np.full(n, weight), probs)
        np.testing.assert_allclose(got, np.quantile(values, probs, method="hazen"), rtol=0, atol=1e-12)

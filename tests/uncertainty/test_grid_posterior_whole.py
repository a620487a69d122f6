"""Grid posteriors (1-3 factors) against the definition written out here with numpy and scipy: the likelihood of
quadratic surrogates with a full covariance (the mean's or, predictive, the new observation's variance added to
sigma²), normalised by the trapezoidal rule over the search box; each marginal, the posterior mean in actual units,
the equal-tailed interval (an independent quantile of a monotone cubic interpolant of the marginal, to a fraction of
a grid step), the information gain in bits and its error against the every-other-node grid; every column of
``information_gain.csv`` and of the marginal table.  Generated over 1-3 factors on ranges away from the origin (some
on a log scale), 1-3 observables of either sign, odd and even grids, credible levels and sigma bases."""

from __future__ import annotations

from itertools import combinations

import numpy as np
import pytest
from hypothesis import Phase, given, settings, strategies as st
from scipy import integrate, interpolate, optimize

from demid.design import quadratic_terms
from demid.sampling.domain import Domain
from demid.spec import join_observables
from demid.surrogate import Surrogate
from demid.uncertainty.posterior import (INFORMATION_GAIN_COLUMNS, grid_posterior, information_gain_frame,
                                         subset_posteriors)


def _trapezoid_all(values: np.ndarray, axes: list[np.ndarray], keep: int | None = None) -> np.ndarray:
    """Trapezoidal integral over every axis but ``keep`` (scipy's rule, one axis at a time)."""
    out = values
    for i in reversed(range(values.ndim)):
        if i != keep:
            out = integrate.trapezoid(out, axes[i], axis=i)
    return out


def _quantile(axis: np.ndarray, density: np.ndarray, q: float) -> float:
    """The q-quantile of a density known at nodes: a shape-preserving cubic (PCHIP) through the density, integrated
    exactly and normalised, its root found by Brent's method (the two agree to about a hundredth of a step)."""
    cdf = interpolate.PchipInterpolator(axis, density).antiderivative()
    total = float(cdf(axis[-1]) - cdf(axis[0]))
    return optimize.brentq(lambda x: float(cdf(x) - cdf(axis[0])) / total - q, axis[0], axis[-1], xtol=1e-14)


def _study(rng, k: int, count: int, sign: float, log_mask: int):
    log = tuple(bool(log_mask >> i & 1) for i in range(k))
    scale = np.where(log, 1.0, 10.0 ** rng.integers(-2, 3, k))
    lo_s = rng.uniform(-3.0, 3.0, k) * scale
    hi_s = lo_s + rng.uniform(0.5, 2.0, k) * scale
    factors = tuple(f"f{i}" for i in range(k))
    domain = Domain(factors, tuple(np.where(log, 10.0 ** lo_s, lo_s)), tuple(np.where(log, 10.0 ** hi_s, hi_s)), log)
    terms = quadratic_terms(k)
    names = [f"y{j}" for j in range(count)]
    surrogates, targets, sigma = {}, {}, {}
    for name in names:
        # a quadratic in the coded search units, written in search units; a full positive covariance
        centre, half = (lo_s + hi_s) / 2, (hi_s - lo_s) / 2
        coded_coef = {t: rng.uniform(-1.0, 1.0) for t in terms}
        coded_coef[terms[0]] = sign * rng.uniform(5.0, 10.0)
        z = rng.uniform(-1, 1, (len(terms) + 3, k))
        u = centre + z * half
        m_coded = np.array([[np.prod(row ** np.array(t)) for t in terms] for row in z])
        y = m_coded @ np.array([coded_coef[t] for t in terms])
        m_search = np.array([[np.prod(row ** np.array(t)) for t in terms] for row in u])
        coef = np.linalg.lstsq(m_search, y, rcond=None)[0]
        a = rng.normal(size=(len(terms), len(terms)))
        covariance = (a @ a.T) * rng.uniform(1e-4, 1e-2) / np.max(np.abs(m_search)) ** 2
        log_factors = tuple(f for f, lg in zip(factors, log) if lg)
        surrogates[name] = Surrogate(name, list(factors), terms, coef, covariance, rng.uniform(0.01, 0.3), 5,
                                     log_factors)
        at = centre + rng.uniform(-0.5, 0.5, k) * half
        targets[name] = float(np.array([np.prod(at ** np.array(t)) for t in terms]) @ coef)
        sigma[name] = float(rng.uniform(0.3, 2.0))
    return domain, surrogates, targets, sigma, terms, names


def _search_loglik(surrogate: Surrogate, terms, u_points: np.ndarray, target, sigma, predictive):
    m = np.prod(u_points[:, None, :] ** np.array(terms, dtype=float)[None], axis=2)  # one column per term
    var = np.einsum("ij,jk,ik->i", m, surrogate.covariance, m) + sigma ** 2
    if predictive:
        var = var + surrogate.resid_var
    return -0.5 * ((m @ surrogate.coefficients - target) ** 2 / var + np.log(2 * np.pi * var))


@settings(max_examples=10, deadline=None, derandomize=True, phases=(Phase.explicit, Phase.generate))
@given(k=st.integers(1, 3), count=st.integers(1, 3), seed=st.integers(0, 10_000), log_mask=st.integers(0, 7),
       sign=st.sampled_from([1.0, -1.0]), n=st.sampled_from([9, 10, 15, 21]),
       level=st.sampled_from([0.95, 0.9, 0.8]), predictive=st.booleans(), with_basis=st.booleans())
def test_every_output_of_a_grid_posterior_is_its_definition(k, count, seed, log_mask, sign, n, level, predictive,
                                                            with_basis):
    if k == 3:
        n = min(n, 15)
    rng = np.random.default_rng(seed)
    domain, surrogates, targets, sigma, terms, names = _study(rng, k, count, sign, log_mask & (2 ** k - 1))
    basis = {names[0]: "measured scatter of 3 replicates"} if with_basis else None
    posteriors = subset_posteriors(surrogates, domain, names, targets, sigma, n, level=level, predictive=predictive,
                                   sigma_basis=basis)
    subsets = [s for size in range(1, count + 1) for s in combinations(names, size)]
    assert list(posteriors) == subsets

    lo_s, hi_s = domain.search_bounds()
    axes = [np.linspace(a, b, n) for a, b in zip(lo_s, hi_s)]
    mesh = np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, k)
    volume = float(np.prod(hi_s - lo_s))
    loglik = {o: _search_loglik(surrogates[o], terms, mesh, targets[o], sigma[o], predictive).reshape((n,) * k)
              for o in names}

    def gain_bits(ll, grid_axes):
        p = np.exp(ll - ll.max())
        p /= _trapezoid_all(p, grid_axes)
        return max(0.0, float(_trapezoid_all(p * np.log(p * volume), grid_axes))) / np.log(2)

    frames = []
    for s in subsets:
        post = posteriors[s]
        ll = np.sum([loglik[o] for o in s], axis=0)
        p = np.exp(ll - ll.max())
        p /= _trapezoid_all(p, axes)
        assert post.observables == s and post.factors == domain.factors and post.n == n and post.level == level
        assert post.sigma == {o: sigma[o] for o in s}
        for i in range(k):
            np.testing.assert_allclose(post.axes[i], axes[i], rtol=1e-12, atol=1e-12)
            marginal = _trapezoid_all(p, axes, keep=i)
            marginal = marginal / integrate.trapezoid(marginal, axes[i])
            np.testing.assert_allclose(post.marginals[i], marginal, rtol=1e-7, atol=1e-9 * marginal.max())
            actual = 10.0 ** axes[i] if domain.log[i] else axes[i]
            np.testing.assert_allclose(post.axes_actual[i], actual, rtol=1e-12)
            assert post.mean[i] == pytest.approx(integrate.trapezoid(marginal * actual, axes[i]), rel=1e-8,
                                                 abs=1e-10 * np.abs(actual).max())
            step = axes[i][1] - axes[i][0]
            for bound, q in ((post.credible_lower[i], (1 - level) / 2), (post.credible_upper[i], (1 + level) / 2)):
                expected = _quantile(axes[i], marginal, q)
                got = np.log10(bound) if domain.log[i] else bound
                assert got == pytest.approx(expected, abs=0.04 * step)
            assert post.credible_width[i] == pytest.approx(post.credible_upper[i] - post.credible_lower[i])
            assert post.credible_lower[i] < post.credible_upper[i]
        expected_gain = gain_bits(ll, axes)
        assert post.information_gain_bits == pytest.approx(expected_gain, rel=1e-7, abs=1e-10)
        if n % 2:
            coarse = gain_bits(ll[(slice(None, None, 2),) * k], [a[::2] for a in axes])
            assert post.information_gain_error_bits == pytest.approx(abs(expected_gain - coarse), rel=1e-6,
                                                                     abs=1e-10)
        else:
            assert np.isnan(post.information_gain_error_bits)

        frame = post.to_frame()
        assert list(frame.columns[:len(INFORMATION_GAIN_COLUMNS)]) == INFORMATION_GAIN_COLUMNS
        assert list(frame["factor"]) == list(domain.factors) and len(frame) == k
        assert set(frame["observables"]) == {join_observables(s)} and set(frame["n_observables"]) == {len(s)}
        np.testing.assert_array_equal(frame["credible_lower"], post.credible_lower)
        np.testing.assert_array_equal(frame["credible_upper"], post.credible_upper)
        np.testing.assert_array_equal(frame["posterior_mean"], post.mean)
        np.testing.assert_allclose(frame["credible_width"], post.credible_upper - post.credible_lower)
        assert set(frame["credible_level"]) == {level} and set(frame["grid_points"]) == {n}
        assert set(frame["information_gain_bits"]) == {post.information_gain_bits}
        expected_basis = "; ".join(
            f"{o}: {basis[o]}" if basis and o in basis else f"{o}: sigma = {sigma[o]:g}" for o in s)
        assert set(frame["sigma_basis"]) == {expected_basis}

        marginals = post.marginal_frame()
        assert len(marginals) == n * k and set(marginals["observables"]) == {join_observables(s)}
        for i, factor in enumerate(domain.factors):
            rows = marginals[marginals["factor"] == factor]
            np.testing.assert_allclose(rows["value"], post.axes_actual[i], rtol=1e-12)
            np.testing.assert_array_equal(rows["density"], post.marginals[i])
        frames.append(frame)

    table = information_gain_frame(posteriors)
    assert len(table) == k * len(subsets)
    assert list(table["observables"]) == [join_observables(s) for s in subsets for _ in range(k)]
    whole = grid_posterior(surrogates, domain, names, targets, sigma, n, level=level, predictive=predictive,
                           sigma_basis=basis)
    assert whole.information_gain_bits == posteriors[tuple(names)].information_gain_bits
    np.testing.assert_array_equal(whole.mean, posteriors[tuple(names)].mean)

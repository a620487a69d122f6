"""The observable ranking given no posteriors computes them itself: each subset's information gain is the
Kullback-Leibler divergence of its posterior from the uniform prior on the search range, in bits, with independent
Gaussian likelihoods of variance σ² + se_mean(x)² (the surrogates' standard error of the mean, not of a new
observation, though their residual variance is as large as σ²), computed here by fine quadrature on a range of
volume 6, for one and two observables of either sign."""

from __future__ import annotations

import numpy as np
import pytest

from demid.sampling.domain import Domain
from demid.surrogate import Surrogate
from demid.uncertainty.ranking import rank_observable_sets

DOMAIN = Domain(("a", "b"), (2.0, -1.0), (5.0, 1.0))
TERMS = [(0, 0), (1, 0), (0, 1)]
SIGMA = 0.4


def _plane(name, coefficients, cov_scale, seed):
    """y = c0 + c1 a + c2 b with a full coefficient covariance and a residual variance of σ²."""
    root = np.random.default_rng(seed).normal(size=(3, 3)) * cov_scale
    return Surrogate(name, ["a", "b"], TERMS, np.asarray(coefficients, dtype=float), root @ root.T, SIGMA ** 2, 8)


def _fine_gains_bits(surrogates, targets, subsets, n=301):
    """KL(posterior || uniform prior) of each subset by Simpson's rule on an n x n grid."""
    a, b = np.linspace(2.0, 5.0, n), np.linspace(-1.0, 1.0, n)
    aa, bb = np.meshgrid(a, b, indexing="ij")
    f = np.stack([np.ones_like(aa), aa, bb], axis=-1)
    loglik = {}
    for o, sur in surrogates.items():
        var = SIGMA ** 2 + np.einsum("...i,ij,...j->...", f, sur.covariance, f)
        loglik[o] = -0.5 * (f @ sur.coefficients - targets[o]) ** 2 / var - 0.5 * np.log(2 * np.pi * var)
    w = np.ones(n)
    w[1:-1:2], w[2:-1:2] = 4, 2
    wa, wb = w * (a[1] - a[0]) / 3, w * (b[1] - b[0]) / 3
    out = {}
    for subset in subsets:
        ll = sum(loglik[o] for o in subset)
        like = np.exp(ll - ll.max())
        p = like / (wa @ like @ wb)
        out[subset] = float(wa @ (p * np.log(p * 3.0 * 2.0)) @ wb) / np.log(2)  # the range's volume is 6
    return out


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_ranking_gains_are_the_posteriors_kl_divergence_with_the_means_standard_error(sign):
    surrogates = {"y": _plane("y", [sign * 10, sign * 1.5, -0.8], 0.15, 1),
                  "w": _plane("w", [sign * 3, -0.2, sign * 2.0], 0.1, 2)}
    targets = {"y": sign * 10 + sign * 1.5 * 3.4 - 0.8 * 0.2, "w": sign * 3 - 0.2 * 3.4 + sign * 2.0 * 0.2}
    frame = rank_observable_sets(surrogates, DOMAIN, ["y", "w"], targets, {"y": SIGMA, "w": SIGMA}, 0.5, 101)
    got = dict(zip(frame["observables"], frame["information_gain_bits"]))
    assert set(got) == {"y", "w", "y+w"}
    for subset, expected in _fine_gains_bits(surrogates, targets, [("y",), ("w",), ("y", "w")]).items():
        assert expected > 0.1
        assert got["+".join(subset)] == pytest.approx(expected, rel=2e-3), subset

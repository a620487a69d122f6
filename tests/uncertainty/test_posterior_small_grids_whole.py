"""A grid posterior's information gain and its error on the smallest grids the rule distinguishes: the error is
the gain's change against every other node, estimated from 5 nodes per axis on (odd grids), NaN on 3 nodes (every
other node would leave 2) and on even grids; both against the trapezoidal rule written out with scipy, 1-2 factors
on ranges away from the origin.  And a likelihood of zero width (a surrogate without error and no measurement
sigma) is refused by name, not divided by."""

from __future__ import annotations

import numpy as np
import pytest
from scipy import integrate

from demid.design import quadratic_terms
from demid.sampling.domain import Domain
from demid.surrogate import Surrogate
from demid.uncertainty.posterior import gaussian_loglik, posterior_from_loglik


def _gain_bits(loglik: np.ndarray, axes: list[np.ndarray], volume: float) -> float:
    like = np.exp(loglik - loglik.max())
    integral = like
    for i in reversed(range(like.ndim)):
        integral = integrate.trapezoid(integral, axes[i], axis=i)
    p = like / float(integral)
    term = p * np.log(p * volume)
    for i in reversed(range(like.ndim)):
        term = integrate.trapezoid(term, axes[i], axis=i)
    return float(term) / np.log(2.0)


@pytest.mark.parametrize("k", [1, 2])
@pytest.mark.parametrize("n", [3, 4, 5, 6, 7])
def test_the_gain_error_is_estimated_from_five_odd_nodes_per_axis_on(k, n):
    lower, upper = (2.0, -7.5)[:k], (3.5, -4.0)[:k]
    domain = Domain(tuple(f"f{i}" for i in range(k)), lower, upper, (False,) * k)
    axes = domain.search_axes(n)
    grids = np.meshgrid(*axes, indexing="ij")
    centre = [2.4, -6.9][:k]
    loglik = -0.5 * sum(((g - c) / 0.4) ** 2 for g, c in zip(grids, centre)) - 3.0
    post = posterior_from_loglik(loglik, domain, ("y",))
    volume = float(np.prod(np.subtract(upper, lower)))
    gain = _gain_bits(loglik, axes, volume)
    assert post.information_gain_bits == pytest.approx(gain, rel=1e-9, abs=1e-12)
    if n % 2 == 1 and n >= 5:
        coarse = _gain_bits(loglik[(slice(None, None, 2),) * k], [a[::2] for a in axes], volume)
        assert post.information_gain_error_bits == pytest.approx(abs(gain - coarse), rel=1e-9, abs=1e-12)
        assert post.information_gain_error_bits > 0
    else:
        assert np.isnan(post.information_gain_error_bits)


def test_a_likelihood_of_zero_width_is_refused_by_the_response_name():
    terms = quadratic_terms(1)
    exact = Surrogate("angle", ["a"], terms, np.array([1.0, 2.0, -0.5]), np.zeros((3, 3)), 0.0, 5, ())
    points = np.array([[0.0], [0.5], [1.0]])
    with pytest.raises(ValueError, match="zero likelihood variance for 'angle': give a measurement sigma"):
        gaussian_loglik(exact, points, 1.5, 0.0)
    # a measurement sigma gives the likelihood its width: the normal log-density written out
    ll = gaussian_loglik(exact, points, 1.5, 0.2)
    pred = 1.0 + 2.0 * points[:, 0] - 0.5 * points[:, 0] ** 2
    assert np.allclose(ll, -0.5 * ((pred - 1.5) ** 2 / 0.04 + np.log(2 * np.pi * 0.04)), rtol=1e-12)

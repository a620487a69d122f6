"""The grid a two-factor material's posteriors are computed on resolves a measurement that pins a factor to a few
thousandths of its range: the information gain agrees with the closed form of a Gaussian posterior (a linear
response, no surrogate error) to 0.01 bit, its 95 % interval with 2 x 1.96 sigma, whichever factor it pins."""

from __future__ import annotations

import numpy as np
import pytest

from demid.sampling import Domain
from demid.uncertainty.material import recommended_sizes
from demid.uncertainty.posterior import grid_posterior


class _Line:
    """y = slope * x_axis in actual units, with no standard error of its mean."""

    response = "y"

    def __init__(self, axis, slope):
        self.axis, self.slope = axis, slope

    def predict(self, points):
        return self.slope * np.atleast_2d(points)[:, self.axis]

    def se_mean(self, points):
        return np.zeros(len(np.atleast_2d(points)))


@pytest.mark.parametrize("axis, sd_share", [(0, 0.003), (1, 0.004)])
def test_a_two_factor_posterior_a_few_thousandths_of_the_range_wide_is_resolved(axis, sd_share):
    lower, upper = np.array([0.2, 1.0]), np.array([1.2, 5.0])
    domain = Domain(("a", "b"), tuple(lower), tuple(upper))
    width = upper[axis] - lower[axis]
    slope, centre = 3.0, lower[axis] + 0.37 * width  # the posterior well inside the range, off the grid's nodes
    sd = sd_share * width  # the posterior's standard deviation along the pinned factor
    post = grid_posterior({"y": _Line(axis, slope)}, domain, ["y"], {"y": slope * centre}, {"y": slope * sd},
                          recommended_sizes(2)["posterior"])
    # KL(N(centre, sd^2) x uniform || uniform over the box) = log2(width) - log2(sqrt(2 pi e) sd)
    gain = np.log2(width) - 0.5 * np.log2(2 * np.pi * np.e * sd ** 2)
    assert post.information_gain_bits == pytest.approx(gain, abs=0.01)
    assert post.credible_upper[axis] - post.credible_lower[axis] == pytest.approx(2 * 1.959964 * sd, rel=0.02)
    assert post.mean[axis] == pytest.approx(centre, abs=0.01 * sd)
    other = 1 - axis
    assert (post.credible_lower[other], post.credible_upper[other]) == pytest.approx(
        (lower[other] + 0.025 * (upper[other] - lower[other]), upper[other] - 0.025 * (upper[other] - lower[other])),
        rel=1e-6)

"""The credible interval's convergence in the grid step, against scipy's truncated normal: a Gaussian likelihood
on two factors (ranges off zero) has truncated-normal marginals, so each end of the 95 % interval is known
exactly.  The CDF's trapezoid rule with its end correction -h²/12 [f'] and the Hermite spline through it are
fourth order where the density vanishes at the range's ends, third where the range cuts it: halving the step
divides the error by about 16, or 8.  Without the correction (or with another factor in it) the rule is second
order, and the error falls by about 4 only."""

from __future__ import annotations

import numpy as np
import pytest
from scipy import stats

from demid.sampling import Domain
from demid.uncertainty.posterior import posterior_from_loglik

DOMAIN = Domain(("a", "b"), (2.0, -1.0), (5.0, 3.0))


def _interval_error(n: int, centre, sd) -> float:
    """The largest error of the four interval ends, in fractions of each factor's range."""
    grid = DOMAIN.grid(n)
    loglik = (-0.5 * (((grid - centre) / sd) ** 2).sum(axis=1)).reshape(n, n)
    post = posterior_from_loglik(loglik, DOMAIN, ("y",))
    lo, hi = np.array(DOMAIN.lower), np.array(DOMAIN.upper)
    worst = 0.0
    for i in range(2):
        exact = stats.truncnorm((lo[i] - centre[i]) / sd[i], (hi[i] - centre[i]) / sd[i], loc=centre[i],
                                scale=sd[i]).ppf([0.025, 0.975])
        found = np.array([post.credible_lower[i], post.credible_upper[i]])
        worst = max(worst, float(np.abs(found - exact).max() / (hi[i] - lo[i])))
    return worst


@pytest.mark.parametrize("centre, sd, order", [
    ((3.5, 1.0), (0.3, 0.4), 10.0),     # the density vanishes at both ends of both ranges: fourth order
    ((3.86, 0.24), (0.21, 0.28), 10.0),
    ((2.9, 0.2), (0.45, 0.6), 6.0),     # the ranges cut the density: third order
])
def test_halving_the_grid_step_divides_the_intervals_error_by_its_order(centre, sd, order):
    centre, sd = np.array(centre), np.array(sd)
    coarse, fine = _interval_error(81, centre, sd), _interval_error(161, centre, sd)
    assert fine < 2e-6
    assert coarse / fine > order, (coarse, fine)

"""The credible interval of a posterior whose density the range cuts with different slopes at its two ends (an
exponential tilt, a linear log-likelihood), against the closed-form quantiles of the truncated exponential."""

from __future__ import annotations

import numpy as np
import pytest

from demid.sampling.domain import Domain
from demid.uncertainty.posterior import posterior_from_loglik

SQUARE = Domain(("a", "b"), (0.0, 0.0), (1.0, 1.0))


def _exact_quantile(rate: float, q: float) -> float:
    """x with (1 - exp(-rate x)) / (1 - exp(-rate)) = q."""
    return float(-np.log1p(-q * -np.expm1(-rate)) / rate)


@pytest.mark.parametrize("rate", [3.0, -2.0, 5.0])
@pytest.mark.parametrize("n", [41, 61])
def test_the_interval_of_a_tilted_density_is_its_exact_quantiles(rate, n):
    a, b = np.meshgrid(*SQUARE.search_axes(n), indexing="ij")
    post = posterior_from_loglik(-rate * a + 0.0 * b, SQUARE, ["y"], level=0.9)
    assert post.credible_lower[0] == pytest.approx(_exact_quantile(rate, 0.05), abs=2e-5)
    assert post.credible_upper[0] == pytest.approx(_exact_quantile(rate, 0.95), abs=2e-5)
    # the flat factor: its interval is the middle 90 % of the range
    assert post.credible_lower[1] == pytest.approx(0.05, abs=1e-9) and post.credible_upper[1] == pytest.approx(0.95, abs=1e-9)

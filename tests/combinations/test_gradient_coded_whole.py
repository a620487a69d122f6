"""The gradient the ridge advice scores observables by, for responses that are no polynomial (a kriging surrogate
is one): against the derivative written out, per coded unit of each factor, linear and log factors (search units
log10), coded units of any size, points anywhere in the box."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings, strategies as st

from demid.combinations.material import gradient_coded
from demid.design import Coding

from ..generators import random_domain


class Smooth:
    """y = sum_i amp_i sin(freq_i s_i) + exp(s_0 s_1 / 4), with s the point in search units."""

    def __init__(self, amp, freq, log):
        self.amp, self.freq, self.log = np.asarray(amp), np.asarray(freq), np.asarray(log)

    def search(self, x):
        x = np.atleast_2d(np.asarray(x, dtype=float))
        return np.where(self.log, np.log10(np.where(self.log, x, 1.0)), x)

    def predict(self, x):
        s = self.search(x)
        return np.sum(self.amp * np.sin(self.freq * s), axis=1) + np.exp(s[:, 0] * s[:, 1] / 4)

    def gradient_search(self, s):
        g = self.amp * self.freq * np.cos(self.freq * s)
        e = np.exp(s[:, 0] * s[:, 1] / 4)
        g[:, 0] += e * s[:, 1] / 4
        g[:, 1] += e * s[:, 0] / 4
        return g


@given(k=st.integers(2, 4), seed=st.integers(0, 10_000), log_mask=st.integers(0, 15),
       unit_scale=st.sampled_from([0.3, 1.0, 4.0]))
@settings(max_examples=10, deadline=None, derandomize=True)
def test_the_coded_gradient_is_the_derivative_per_coded_unit(k, seed, log_mask, unit_scale):
    rng = np.random.default_rng(seed)
    domain, lo_s, hi_s = random_domain(rng, k, log_mask)
    log = domain.log
    coding = Coding(domain.factors, tuple((lo_s + hi_s) / 2), tuple(unit_scale * (hi_s - lo_s) / 2))
    response = Smooth(rng.uniform(-2.0, 2.0, k), rng.uniform(0.5, 3.0, k), log)
    points = lo_s + rng.uniform(0.0, 1.0, (6, k)) * (hi_s - lo_s)
    got = gradient_coded(response, domain, coding, points)
    expected = response.gradient_search(points) * np.asarray(coding.unit)
    np.testing.assert_allclose(got, expected, rtol=1e-5, atol=1e-7 * np.max(np.abs(expected)))

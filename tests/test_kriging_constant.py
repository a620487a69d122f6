"""A response every run returns alike (a simulation pinned at a cap, a printed constant): the kriging surrogate
predicts that value everywhere with no error beyond round-off, instead of 0/0 from standardising by a zero scatter."""

from __future__ import annotations

import numpy as np
import pytest

from demid.kriging import KrigingSurrogate


@pytest.mark.parametrize("value", [3.7, -0.02, 0.0])
def test_a_constant_response_is_predicted_as_that_constant(value):
    rng = np.random.default_rng(3)
    u = rng.random((11, 2))
    sur = KrigingSurrogate("y", ["a", "b"], u, np.full(11, value), np.zeros(2), np.ones(2),
                           np.array([0.35, 0.6]), 0.02)
    at = np.array([[0.1, 0.9], [0.5, 0.5], *u[:2]])
    np.testing.assert_allclose(sur.predict(at), value, rtol=0, atol=1e-12)
    # no scatter to scale: the errors are round-off, far below the value's own last digit
    assert np.all(sur.se_mean(at) < 1e-12) and 0.0 <= sur.resid_var < 1e-24

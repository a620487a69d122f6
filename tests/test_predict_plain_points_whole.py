"""Predictions at points given as plain Python lists (one point, several points, whole numbers): every surrogate's
value is its polynomial written out term by term in model units (log10 for a log-scale factor), the same as for a
float array of the same points, for surrogates sharing terms and one on other terms, with and without log factors."""

from __future__ import annotations

import numpy as np
import pytest

from demid.design import quadratic_terms
from demid.surrogate import Surrogate, predict_all


def _written_out(coef, terms, points, logs) -> np.ndarray:
    s = np.array(points, dtype=float).reshape(-1, 2)
    s = np.where(logs, np.log10(np.where(logs, s, 1.0)), s)
    return np.array([sum(c * np.prod([v ** e for v, e in zip(row, t)]) for c, t in zip(coef, terms)) for row in s])


@pytest.mark.parametrize("log_factors", [(), ("b",)])
def test_plain_lists_of_points_predict_the_written_out_polynomial(log_factors):
    quad, linear = quadratic_terms(2), [t for t in quadratic_terms(2) if sum(t) <= 1]
    coefs = {"y1": ([1.0, 2.0, -3.0, 0.5, 0.25, -1.5], quad), "y2": ([-4.0, 0.1, 0.2, 0.3, 0.4, 0.5], quad),
             "y3": ([7.0, -1.0, 2.0], linear)}
    surrogates = {n: Surrogate(n, ["a", "b"], t, np.array(c), np.eye(len(t)) * 0.01, 0.1, 13, log_factors)
                  for n, (c, t) in coefs.items()}
    logs = np.array([f in log_factors for f in ("a", "b")])
    for points in ([2, 3], [[2, 3], [1, 10], [-1, 100]], [[0.5, 2.5]]):
        out = predict_all(surrogates, points)
        for name, (c, t) in coefs.items():
            expected = _written_out(c, t, points, logs)
            np.testing.assert_allclose(out[name], expected, rtol=1e-12, atol=1e-12)
            np.testing.assert_allclose(surrogates[name].predict(points), expected, rtol=1e-12, atol=1e-12)

"""The typo screen's studentised residuals of a response the quadratic fits exactly (a response computed from a
formula, not simulated): the residuals are round-off, so their ratio to the round-off scale is noise, and every
studentised residual is NaN (no run can be extreme); leverages and residuals are still the fit's, as written out
with numpy.  One to four factors, responses of either sign and of small and large magnitude."""

from __future__ import annotations

import numpy as np
import pytest

from demid.design import model_matrix, quadratic_terms
from demid.transcription.typos import studentised_residuals


@pytest.mark.parametrize("seed, k, scale", [(1, 1, 1.0), (2, 2, -1e3), (3, 3, 1e-4), (4, 4, 50.0)])
def test_an_exactly_fitted_response_has_no_studentised_residual(seed, k, scale):
    rng = np.random.default_rng(seed)
    terms = quadratic_terms(k)
    n = len(terms) + 3 + k
    coded = rng.uniform(-1.5, 1.5, size=(n, k))
    x = model_matrix(coded, terms)
    y = scale * (x @ rng.normal(size=len(terms)) + 5.0)
    got = studentised_residuals(coded, y, terms)
    h = np.diag(x @ np.linalg.solve(x.T @ x, x.T))
    np.testing.assert_allclose(got["leverage"], h, rtol=1e-8)
    assert np.all(np.abs(got["residual"]) <= 1e-9 * np.max(np.abs(y)))
    assert np.isnan(got["student_resid"]).all() and got["student_resid"].shape == (n,)

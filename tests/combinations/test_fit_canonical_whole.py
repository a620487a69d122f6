"""The canonical analysis of a fitted surface (demid.canonical.fit_canonical) in the factors' own units, over
generated CCD tables of 2-3 factors some of which are on a log scale, with an exact quadratic response: the
stationary point in coded units is -B^-1 b / 2 of the coefficients the response was built with, in actual units the
coding's image of it (10 to that power for a log-scaled factor), the predicted value the surface's there, and the
region the runs' coded box (a stationary point beyond the axial runs is outside it)."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from hypothesis import Phase, given, settings
from hypothesis import strategies as st

from demid.canonical import fit_canonical
from demid.design import ccd_points
from demid.surrogate import fit_response


@given(k=st.integers(2, 3), log_mask=st.integers(0, 7), seed=st.integers(0, 10_000), far=st.booleans())
@settings(max_examples=5, deadline=None, derandomize=True, phases=[Phase.explicit, Phase.generate])
def test_the_stationary_point_in_coded_and_actual_units(k, log_mask, seed, far):
    rng = np.random.default_rng(seed)
    alpha = 1.5
    coded = ccd_points(k, alpha, 3)
    names = [f"f{i}" for i in range(k)]
    logs = tuple(n for i, n in enumerate(names) if log_mask >> i & 1)
    centre, half = rng.uniform(-2, 2, k), rng.uniform(0.1, 0.5, k)
    model_units = centre + coded * half
    actual = np.where([n in logs for n in names], 10.0 ** model_units, model_units * 7.0)
    # a definite quadratic (a maximum) with its stationary point at x_s (coded), inside or beyond the axial runs
    x_s = rng.uniform(-0.8, 0.8, k) * (3.0 if far else 1.0)
    a = rng.normal(size=(k, k))
    big_b = -(a @ a.T + k * np.eye(k))
    b = -2.0 * big_b @ x_s
    b0 = float(rng.uniform(-5, 5))
    y = b0 + coded @ b + np.einsum("ni,ij,nj->n", coded, big_b, coded)
    table = pd.DataFrame({n: actual[:, i] for i, n in enumerate(names)})
    table.insert(0, "run", np.arange(1, len(table) + 1))
    table["y"] = y
    fit = fit_response(table, names, "y", alpha=alpha, log_factors=logs)
    # the fit's own coding maps the table's runs onto the generated coded points
    np.testing.assert_allclose(fit.coding.to_coded(np.where([n in logs for n in names], model_units, actual)),
                               coded, atol=1e-9)
    result = fit_canonical(fit)
    np.testing.assert_allclose(result.stationary_coded, x_s, atol=1e-7)
    model = np.asarray(fit.coding.to_actual(x_s[None, :]))[0]
    want_actual = np.where([n in logs for n in names], 10.0 ** model, model)
    np.testing.assert_allclose(result.stationary_actual, want_actual, rtol=1e-7)
    assert result.value == pytest.approx(b0 + x_s @ b + x_s @ big_b @ x_s, rel=1e-8, abs=1e-8)
    assert result.kind == "maximum"
    assert result.inside == bool(np.all(np.abs(x_s) <= alpha + 1e-9))
    np.testing.assert_allclose(np.sort(result.eigenvalues)[::-1], np.sort(np.linalg.eigvalsh(big_b))[::-1], rtol=1e-7)

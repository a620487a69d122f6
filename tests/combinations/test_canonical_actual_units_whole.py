"""The canonical analysis of a fitted surface in the factors' own units is the search-to-actual conversion of the
domain (demid.sampling.domain.search_to_actual) applied to the coding's image of each coded point, for a linear
and a log factor, also where a stationary point far outside the runs overflows 10 ** on its log factor: inf, and
no warning."""

from __future__ import annotations

import warnings

import numpy as np
import pandas as pd
import pytest

from demid.canonical import fit_canonical
from demid.design import ccd_points
from demid.sampling.domain import search_to_actual
from demid.surrogate import fit_response


@pytest.mark.parametrize("x_s, overflows", [((0.3, -0.4), False), ((-0.2, 900.0), True)])
def test_stationary_and_ridge_points_in_actual_units_are_the_domains_conversion(x_s, overflows):
    coded = ccd_points(2, 1.5, 3)
    model_units = np.array([1.0, 0.5]) + coded * np.array([0.5, 0.5])
    actual = np.column_stack([model_units[:, 0], 10.0 ** model_units[:, 1]])  # f1 on a log scale
    x_s = np.asarray(x_s)
    big_b = np.array([[-2.0, 0.3], [0.3, -1.0]])
    b = -2.0 * big_b @ x_s
    y = 1.0 + coded @ b + np.einsum("ni,ij,nj->n", coded, big_b, coded)
    table = pd.DataFrame({"run": np.arange(1, len(coded) + 1), "f0": actual[:, 0], "f1": actual[:, 1], "y": y})
    fit = fit_response(table, ["f0", "f1"], "y", alpha=1.5, log_factors=("f1",))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        result = fit_canonical(fit)
    with np.errstate(over="ignore"):
        expected = search_to_actual(fit.coding.to_actual(result.stationary_coded[None, :]), [False, True])[0]
    assert np.isinf(expected[1]) == overflows
    np.testing.assert_allclose(result.stationary_actual, expected, rtol=1e-12)
    # the coding's image by hand: f0 = 1 + 0.5 x0, log10 f1 = 0.5 + 0.5 x1
    np.testing.assert_allclose(result.stationary_actual[0], 1.0 + 0.5 * result.stationary_coded[0], rtol=1e-12)
    if not overflows:
        np.testing.assert_allclose(result.stationary_actual[1], 10.0 ** (0.5 + 0.5 * result.stationary_coded[1]),
                                   rtol=1e-12)
    np.testing.assert_allclose(result.stationary_coded, x_s, rtol=1e-6, atol=1e-6)

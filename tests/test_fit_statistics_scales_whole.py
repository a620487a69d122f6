"""A quadratic fit's statistics (demid.surrogate.SurrogateFit.statistics) against least squares written out here
with numpy, for responses of every size (their total sum of squares from 1e-8 to 1e8, so below and above 1): R²,
adjusted R², RMSE, residual sd, PRESS (leave-one-out residuals e / (1 - h) from the hat matrix) and Q² = 1 - PRESS
/ SST; a constant response has no R² or Q² (NaN)."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from demid.design import ccd_points
from demid.surrogate import fit_response


@pytest.mark.parametrize("scale", [1e-4, 0.3, 1.0, 1e4])
@pytest.mark.parametrize("seed", [0, 1])
def test_fit_statistics_are_least_squares_at_every_scale(scale, seed):
    rng = np.random.default_rng(seed)
    coded = ccd_points(2, 1.0, 3)
    x = 5.0 + 2.0 * coded
    a, b = coded[:, 0], coded[:, 1]
    design = np.column_stack([np.ones(len(a)), a, b, a * a, b * b, a * b])
    y = scale * (design @ rng.normal(size=6) + 0.3 * rng.normal(size=len(a)))
    table = pd.DataFrame({"run": np.arange(1, len(a) + 1), "a": x[:, 0], "b": x[:, 1], "y": y})
    stats = fit_response(table, ["a", "b"], "y").statistics()

    coef, *_ = np.linalg.lstsq(design, y, rcond=None)
    resid = y - design @ coef
    hat = np.diag(design @ np.linalg.solve(design.T @ design, design.T))
    n, p = design.shape
    sse, sst = float(resid @ resid), float(np.sum((y - y.mean()) ** 2))
    press = float(np.sum((resid / (1 - hat)) ** 2))
    assert (stats.n_runs, stats.n_params) == (n, p)
    assert stats.r2 == pytest.approx(1 - sse / sst, rel=1e-9)
    assert stats.adj_r2 == pytest.approx(1 - (sse / (n - p)) / (sst / (n - 1)), rel=1e-9)
    assert stats.rmse == pytest.approx(np.sqrt(sse / n), rel=1e-9)
    assert stats.resid_std == pytest.approx(np.sqrt(sse / (n - p)), rel=1e-9)
    assert stats.press == pytest.approx(press, rel=1e-9)
    assert stats.q2 == pytest.approx(1 - press / sst, rel=1e-9)
    assert (sst < 1) == (scale < 1)  # both sides of a total sum of squares of 1


def test_a_constant_response_has_no_r2_or_q2():
    coded = ccd_points(2, 1.0, 3)
    table = pd.DataFrame({"run": np.arange(1, len(coded) + 1), "a": coded[:, 0], "b": coded[:, 1],
                          "y": np.full(len(coded), 2.5)})
    stats = fit_response(table, ["a", "b"], "y").statistics()
    assert np.isnan(stats.r2) and np.isnan(stats.q2) and np.isnan(stats.adj_r2)
    assert stats.rmse == pytest.approx(0.0, abs=1e-12)

"""Known answers for numbers the report prints (not only for the decisions made from them).

Each reference is computed here from its definition with statsmodels/scipy, independently of the
code under test.
"""

from __future__ import annotations

import numpy as np
import pytest
import statsmodels.api as sm
from scipy import optimize, special, stats

from demid.criticism import criticize

from .generators import FACTORS, ccd_table
from .test_criticism import quadratic_ols

GRID_STEP = 0.01  # the lambda grid the interval is read on


@pytest.mark.parametrize("seed, size", [(13, 3.0), (4, 2.5), (21, 3.0)])
def test_box_cox_lambda_and_its_interval(seed, size):
    """λ̂ maximises the profile likelihood; the 95 % interval is where the likelihood ratio in F form,
    df·(exp(LR/n) − 1), stays below F(0.95; 1, df), df = n − p − 1 (p: the quadratic's terms)."""
    table, _ = ccd_table(seed, 2, "log", size)
    finding = next(f for f in criticize(table, FACTORS[2], "y").findings if f.cause == "response_transform")
    y = table["y"].to_numpy(float)
    x = quadratic_ols(table, FACTORS[2]).model.exog
    n, df = len(y), len(y) - x.shape[1] - 1

    def profile(lam):
        return -0.5 * n * np.log(sm.OLS(special.boxcox(y, lam), x).fit().ssr / n) + (lam - 1) * np.log(y).sum()

    best = optimize.minimize_scalar(lambda v: -profile(v), bounds=(-3, 3), method="bounded",
                                    options={"xatol": 1e-6})
    lam_hat, top = best.x, -best.fun
    crit = stats.f.ppf(0.95, 1, df)

    def excess(lam):
        return df * np.expm1(2 * (top - profile(lam)) / n) - crit

    lo = optimize.brentq(excess, -3, lam_hat)
    hi = optimize.brentq(excess, lam_hat, 3)
    assert finding.info["lambda_hat"] == pytest.approx(lam_hat, abs=GRID_STEP)
    reported_lo, reported_hi = finding.info["lambda_ci"]
    # the grid's inside points: the reported ends lie within one step inside the exact ends
    assert lo - 1e-9 <= reported_lo <= lo + GRID_STEP + 1e-9
    assert hi - GRID_STEP - 1e-9 <= reported_hi <= hi + 1e-9

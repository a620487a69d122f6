"""Adjusted R² from printed sums of squares (demid.transcription.printed._adjusted_r2) against statsmodels'
rsquared_adj of the same fit, down to one residual degree of freedom (a saturated-but-one design, common in
small published tables); none for no residual degree of freedom."""
from __future__ import annotations

import numpy as np
import pytest
import statsmodels.api as sm

from demid.transcription.printed import _adjusted_r2


@pytest.mark.parametrize("n, p", [(4, 3), (6, 5), (9, 6), (13, 6)])
def test_adjusted_r2_matches_statsmodels_down_to_one_residual_df(n, p):
    rng = np.random.default_rng(n * 10 + p)
    x = np.column_stack([np.ones(n), rng.normal(size=(n, p - 1))])
    y = x @ rng.normal(size=p) + rng.normal(size=n)
    fit = sm.OLS(y, x).fit()
    assert fit.df_resid == n - p
    ss_total = float(np.sum((y - y.mean()) ** 2))
    got = _adjusted_r2(np.array([fit.ssr]), np.array([ss_total]),
                       {"_df_model_resid": np.array([float(n - p)]), "_n": np.array([float(n)])})
    assert got[0] == pytest.approx(fit.rsquared_adj, rel=1e-10)


def test_no_adjusted_r2_without_residual_degrees_of_freedom():
    got = _adjusted_r2(np.array([0.0]), np.array([2.0]), {"_df_model_resid": np.array([0.0]), "_n": np.array([5.0])})
    assert np.isnan(got[0])

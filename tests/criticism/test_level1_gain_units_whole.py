"""The leave-one-out gain a level-1 finding reports does not depend on the response's units: an outlier planted
in a 2-factor CCD, the response in its own units and in thousandths of them (a leave-one-out error well below 1),
the ratio of the errors after and before recomputed with statsmodels (the outlier as a dummy column, each other
run's leave-one-out error e / (1 - h), h the hat matrix's diagonal)."""

from __future__ import annotations

import numpy as np
import pytest
import statsmodels.api as sm

from demid.criticism import criticize
from demid.design import model_matrix, quadratic_terms
from tests.generators import FACTORS, ccd_table


def _loo(y, x, rows):
    fit = sm.OLS(y, x).fit()
    hat = np.einsum("ij,ji->i", x, np.linalg.pinv(x))
    return fit.resid[rows] / (1 - hat[rows])


@pytest.mark.parametrize("scale", [1.0, 1e-3])
def test_the_leave_one_out_gain_of_a_named_outlier_in_any_units(scale):
    table, _ = ccd_table(3, 2, "outlier", size=9.0)
    table["y"] = table["y"] * scale
    result = criticize(table, FACTORS[2], "y", n_null=99)
    assert [f.cause for f in result.findings] == ["outlier"]
    row = int(np.flatnonzero(table["run"].to_numpy() == result.findings[0].detail)[0])
    lo, hi = table[FACTORS[2]].min().to_numpy(), table[FACTORS[2]].max().to_numpy()
    coded = (table[FACTORS[2]].to_numpy() - (lo + hi) / 2) / ((hi - lo) / 2) * np.sqrt(2)
    x = model_matrix(coded, quadratic_terms(2))
    y = table["y"].to_numpy()
    others = np.arange(len(y)) != row
    before = _loo(y, x, others)
    after = _loo(y, np.column_stack([x, (~others).astype(float)]), others)
    ratio = np.sqrt(np.mean(after ** 2)) / np.sqrt(np.mean(before ** 2))
    assert result.gain["compared_runs"] == len(y) - 1
    assert result.gain["loo_rmse_baseline_same_runs"] == pytest.approx(np.sqrt(np.mean(before ** 2)), rel=1e-9)
    assert result.gain["loo_rmse_ratio"] == pytest.approx(ratio, rel=1e-9)
    assert result.summary.endswith(f"together they change the leave-one-out error by {100 * (ratio - 1):+.0f} %.")

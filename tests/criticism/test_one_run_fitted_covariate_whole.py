"""Unequal scatter along the fitted values with each run left out (criticism.one_run.deleted_logp): the covariate
without run i is the fitted value of the quadratic refitted to the other runs (statsmodels' OLS here), scaled to
[-1, 1] over them, not the response itself; each entry is the F form of the likelihood ratio on that covariate,
(df - 1) expm1(LR / (n - 1)) ~ F(1, df - 1).  Responses growing in scatter with their level, 2-3 factors."""

from __future__ import annotations

import itertools

import numpy as np
import pandas as pd
import pytest
import statsmodels.api as sm
from scipy import stats

from demid.criticism.catalogue import Hypothesis, heteroscedasticity_lr
from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm
from demid.criticism.one_run import deleted_logp


def _model(k: int, seed: int):
    points = np.array(list(itertools.product((-1.0, 0.0, 1.0), repeat=k)) + [[0.0] * k] * 2)
    names = [f"f{j}" for j in range(k)]
    rng = np.random.default_rng(seed)
    mean = 10.0 + points @ rng.uniform(1, 3, k) + 0.5 * points[:, 0] ** 2
    y = mean + 0.05 * np.exp(0.8 * (mean - 10.0)) * rng.standard_normal(len(points))
    table = pd.DataFrame(20.0 + 5.0 * points, columns=names)
    table.insert(0, "run", np.arange(1, len(points) + 1))
    table["y"] = y
    data, _ = prepare_data(table, names, "y", 1.0, (), None)
    return data, Model(data, ModelForm())


@pytest.mark.parametrize("k,seed", [(2, 0), (2, 5), (3, 1)])
def test_each_deletion_tests_scatter_along_the_other_runs_fitted_values(k, seed):
    data, m = _model(k, seed)
    h = Hypothesis("heteroscedasticity", "fitted")
    y = m.z[:, None]
    got = deleted_logp(data, m, h, y)
    n = len(m.z)
    want = np.zeros((n, 1))
    for pos in range(n):
        keep = np.arange(n) != pos
        fitted = sm.OLS(m.z[keep], m.x[keep]).fit().fittedvalues
        lo, hi = fitted.min(), fitted.max()
        covariate = (fitted - (hi + lo) / 2) / ((hi - lo) / 2)
        df = int(keep.sum()) - np.linalg.matrix_rank(m.x[keep])
        lr = heteroscedasticity_lr(y[keep], m.x[keep], covariate)
        want[pos] = stats.f.logsf((df - 1) * np.expm1(lr / (n - 1)), 1, df - 1)
    np.testing.assert_allclose(got, want, rtol=1e-7, atol=1e-10)
    assert (got < 0).all()

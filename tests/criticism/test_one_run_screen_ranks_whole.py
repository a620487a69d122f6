"""The runs screened before the test of unequal scatter is redone without each (one_run._weakest_by_identity):
the SCREENED_RUNS runs whose deletion lowers its likelihood ratio most, the covariate of all runs held fixed.
Each run's ratio is computed here by refitting the weighted least squares without that run at every variance
slope of the grid (the profile of the runs left: their n - 1 residuals and their own weights), over 2-3 factors,
covariates a factor or the fitted value, scatter growing or falling, with and without a wild run."""
from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from demid.criticism.catalogue import GAMMA_GRID, Hypothesis
from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm
from demid.criticism.one_run import SCREENED_RUNS, _weakest_by_identity


def _deleted_lr(x, y, covariate):
    """Per run, 2 (max over the slopes - slope 0) of the profile log-likelihood of the other runs."""
    n = len(y)
    lr = np.empty(n)
    zero = int(np.argmin(np.abs(GAMMA_GRID)))
    for i in range(n):
        keep = np.arange(n) != i
        prof = []
        for g in GAMMA_GRID:
            sw = np.exp(-0.5 * g * covariate[keep])
            xw, yw = x[keep] * sw[:, None], y[keep] * sw
            beta = np.linalg.lstsq(xw, yw, rcond=None)[0]
            sse = float(np.sum((yw - xw @ beta) ** 2))
            prof.append(-0.5 * (n - 1) * np.log(sse / (n - 1)) + float(np.sum(np.log(sw))))
        lr[i] = 2.0 * (max(prof) - prof[zero])
    return lr


@pytest.mark.parametrize("k, slope, covariate, wild, seed", [
    (2, 1.5, "f0", True, 0), (2, -1.5, "f1", False, 1), (3, 2.0, "fitted", True, 2), (3, -1.0, "f2", True, 3)])
def test_the_screened_runs_are_those_whose_deletion_weakens_the_scatter_test_most(k, slope, covariate, wild, seed):
    rng = np.random.default_rng(seed)
    n = SCREENED_RUNS + 14
    x = rng.uniform(-1, 1, (n, k))
    y = 10 + 2 * x[:, 0] - x[:, 1] + 0.05 * np.exp(slope * x[:, -1]) * rng.standard_normal(n)
    if wild:
        y[5] += 0.4
    factors = [f"f{j}" for j in range(k)]
    table = pd.DataFrame({"run": np.arange(1, n + 1), **{f: x[:, j] for j, f in enumerate(factors)}, "y": y})
    data, _ = prepare_data(table, factors, "y", None, ())
    model = Model(data, ModelForm())
    if covariate == "fitted":
        fitted = model.x @ np.linalg.lstsq(model.x, model.z, rcond=None)[0]
        c = (fitted - (fitted.max() + fitted.min()) / 2) / (np.ptp(fitted) / 2)
    else:
        c = data.coded[:, factors.index(covariate)] / data.alpha
    lr = _deleted_lr(model.x, model.z, c)
    screened = _weakest_by_identity(data, model, Hypothesis("heteroscedasticity", covariate))
    expected = np.sort(np.argsort(lr, kind="stable")[:SCREENED_RUNS])
    assert np.sort(lr)[SCREENED_RUNS] - np.sort(lr)[SCREENED_RUNS - 1] > 1e-6  # no tie at the cut
    assert screened.tolist() == expected.tolist()

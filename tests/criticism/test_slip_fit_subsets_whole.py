"""A run's slip fit over any subset of its candidates (a run with one candidate slip, as a log factor whose
decades span more than its range gives): the Bayes factor is a sum over the slips, so the singletons' factors add
up to the whole list's; each singleton chooses its own slip with the t value of statsmodels' prediction from the
other runs; the recorded value's t does not depend on the candidates.  2-3 factors, responses of scale 0.01-100."""
from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
import statsmodels.api as sm
from scipy import stats

from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm
from demid.criticism.slips import slip_candidates, slip_fit
from demid.design import model_matrix

PRIOR = {1: 0.5, 2: 0.25, 3: 0.25}


@pytest.mark.parametrize("k, seed, scale, row", [(2, 0, 1.0, 3), (3, 1, 0.01, 0), (2, 2, 100.0, 11), (3, 3, 1.0, 7)])
def test_each_candidate_alone_and_their_bayes_factors_add_up(k, seed, scale, row):
    rng = np.random.default_rng(seed)
    n = 12 + 4 * k
    x = rng.uniform(0.5, 5.0, (n, k))
    y = scale * (4.0 + x[:, 0] - 0.2 * x[:, -1] ** 2 + 0.05 * rng.standard_normal(n))
    factors = [f"f{j}" for j in range(k)]
    table = pd.DataFrame({"run": np.arange(1, n + 1), **{f: x[:, j] for j, f in enumerate(factors)}, "y": y})
    data, _ = prepare_data(table, factors, "y", 1.0, (), None)
    model = Model(data, ModelForm())
    same_run = [c for c in slip_candidates(data, model) if c.row == row]
    assert len(same_run) >= 2
    others = np.arange(n) != row
    fit = sm.OLS(model.z[others], model.x[others]).fit()
    spread = float(np.ptp(model.z))
    whole = slip_fit(model, same_run, k)[1]
    factors_alone = []
    for c in same_run:
        chosen, info = slip_fit(model, [c], k)
        coded = data.coded[row].copy()
        coded[c.factor] = c.coded
        pred = fit.get_prediction(model_matrix(coded[None, :], model.mean_terms))
        se = float(np.sqrt(pred.se_mean[0] ** 2 + fit.scale))
        t = float((model.z[row] - pred.predicted_mean[0]) / se)
        assert chosen == c
        assert info["t_moved"] == pytest.approx(t, rel=1e-6, abs=1e-9)
        assert info["t_recorded"] == pytest.approx(whole["t_recorded"], rel=1e-12, abs=1e-12)
        expected = PRIOR[abs(c.power)] / (2 * k) * stats.norm.pdf(t) / se * spread
        assert info["bayes_factor"] == pytest.approx(expected, rel=1e-6, abs=1e-300)
        factors_alone.append(info["bayes_factor"])
    assert whole["bayes_factor"] == pytest.approx(sum(factors_alone), rel=1e-9, abs=1e-300)

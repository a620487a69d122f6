"""A slipped run's numbers as the findings quote them, against statsmodels' prediction of a new observation from
the other runs: the prediction error in standard errors at the slipped and at the recorded value, the slip
chosen (largest prior x density), and the Bayes factor of a slip against a mean shift uniform over the
responses' range (prior half on one decimal place, a quarter each on two and three, over factors and
directions); 2-3 factors, scales 0.01-100, a planted slip or none."""
from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
import statsmodels.api as sm
from hypothesis import given, settings, strategies as st
from scipy import stats

from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm
from demid.criticism.slips import slip_candidates, slip_fit
from demid.design import model_matrix

PRIOR = {1: 0.5, 2: 0.25, 3: 0.25}


@settings(max_examples=8, deadline=None, derandomize=True)
@given(k=st.integers(2, 3), seed=st.integers(0, 999), scale=st.sampled_from([0.01, 1.0, 100.0]),
       planted=st.booleans(), run_pick=st.integers(0, 10 ** 6))
def test_a_slips_t_values_choice_and_bayes_factor(k, seed, scale, planted, run_pick):
    rng = np.random.default_rng(seed)
    n = 12 + 4 * k
    x = rng.uniform(0.5, 5.0, (n, k))
    y = scale * (4.0 + x[:, 0] - 0.2 * x[:, -1] ** 2 + 0.05 * rng.standard_normal(n))
    row = run_pick % n
    if planted:  # the response of a run whose first factor was really ten times what is recorded
        true = x[row].copy()
        true[0] *= 10.0 ** -1
        y[row] = scale * (4.0 + true[0] - 0.2 * true[-1] ** 2)
    factors = [f"f{j}" for j in range(k)]
    table = pd.DataFrame({"run": np.arange(1, n + 1), **{f: x[:, j] for j, f in enumerate(factors)}, "y": y})
    data, _ = prepare_data(table, factors, "y", 1.0, (), None)
    model = Model(data, ModelForm())
    same_run = [c for c in slip_candidates(data, model) if c.row == row]
    if not same_run:
        return
    chosen, info = slip_fit(model, same_run, k)

    others = np.arange(n) != row
    x_all = model.x
    fit = sm.OLS(model.z[others], x_all[others]).fit()
    s2 = fit.scale

    def prediction(rows):
        pred = fit.get_prediction(rows)
        return pred.predicted_mean, np.sqrt(pred.se_mean ** 2 + s2)

    coded = np.repeat(data.coded[row][None, :], len(same_run), axis=0)
    for i, c in enumerate(same_run):
        coded[i, c.factor] = c.coded
    mean, se = prediction(model_matrix(coded, model.mean_terms))
    t = (model.z[row] - mean) / se
    mass = np.array([PRIOR[abs(c.power)] / (2 * k) for c in same_run]) * stats.norm.pdf(t) / se
    best = int(np.argmax(mass))
    assert chosen == same_run[best]
    assert info["t_moved"] == pytest.approx(t[best], rel=1e-6, abs=1e-9)
    mean0, se0 = prediction(x_all[row][None, :])
    assert info["t_recorded"] == pytest.approx(float((model.z[row] - mean0[0]) / se0[0]), rel=1e-6, abs=1e-9)
    assert info["bayes_factor"] == pytest.approx(float(np.sum(mass)) * float(np.ptp(model.z)), rel=1e-6)
    if planted:
        assert info["bayes_factor"] > 1.0 and (chosen.factor, chosen.power) == (0, -1)

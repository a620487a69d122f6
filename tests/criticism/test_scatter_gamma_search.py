"""Unequal scatter's weights searched without a model per step (above ASYMPTOTIC_RUNS runs): the
log-likelihood at each gamma is the fitted model's, and the gamma found is the one a model per step finds,
on tables with scatter growing along a factor or the fitted value, a run excluded, several seeds."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pandas as pd
import pytest

from demid.criticism import extensions
from demid.criticism.catalogue import Hypothesis
from demid.criticism.extensions import extend_for, weighted_loglik
from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm


def _data(seed: int, n: int):
    rng = np.random.default_rng(seed)
    names = ["f0", "f1", "f2"]
    u = rng.uniform(-1, 1, (n, 3))
    mean = 10 + u @ rng.uniform(-2, 2, 3) + 0.4 * u[:, 0] ** 2
    y = mean + 0.05 * np.exp(0.8 * u[:, 1]) * rng.standard_normal(n)  # the scatter grows along f1
    table = pd.DataFrame(2.0 + 1.5 * u, columns=names)
    table.insert(0, "run", np.arange(1, n + 1))
    table["y"] = y
    return prepare_data(table, names, "y", 1.0, (), None)[0]


@pytest.mark.parametrize("seed,n,covariate,dropped", [(0, 300, "f1", ()), (1, 500, "fitted", ()),
                                                      (2, 400, "f1", (7,)), (3, 260, "f0", (0, 11))])
def test_the_loglik_at_each_gamma_is_the_fitted_models(seed, n, covariate, dropped):
    data = _data(seed, n)
    base = Model(data, ModelForm(dropped=dropped))
    spec, _ = extend_for(data, base, Hypothesis("heteroscedasticity", covariate))
    at_zero = Model(data, replace(spec, weight_gamma=0.0))
    for gamma in (-2.5, -0.3, 0.0, 0.7, 3.0, spec.weight_gamma):
        fitted = Model(data, replace(spec, weight_gamma=gamma)).loglik
        assert weighted_loglik(at_zero, gamma) == pytest.approx(fitted, rel=1e-11, abs=1e-9)


@pytest.mark.parametrize("seed,n,covariate", [(4, 300, "f1"), (5, 600, "fitted"), (6, 400, "f2")])
def test_the_gamma_found_is_the_model_per_step_gamma(seed, n, covariate, monkeypatch):
    data = _data(seed, n)
    base = Model(data, ModelForm())
    h = Hypothesis("heteroscedasticity", covariate)
    fast, fast_info = extend_for(data, base, h)
    monkeypatch.setattr(extensions, "ASYMPTOTIC_RUNS", 10 ** 9)  # a model at each step, as on few runs
    direct, direct_info = extend_for(data, base, h)
    assert fast.weight_gamma == pytest.approx(direct.weight_gamma, abs=1e-5)
    assert fast_info["sd_ratio"] == pytest.approx(direct_info["sd_ratio"], rel=1e-5)
    if covariate == "f1":  # the simulated scatter: sd x exp(0.8) per coded unit, sd ratio e^1.6 over the range
        assert 2.5 < fast_info["sd_ratio"] < 8.0

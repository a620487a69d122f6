"""A cause's extension as the findings quote it, against computations written in the test over generated
tables (2-3 factors, run labels spaced 1 or 10 apart, responses of different scales): a drift's slope per run
and a step's shift (numpy least squares on the raw run numbers), a slipped value's recorded and fitting values
(the table's cell times 10^power), unequal scatter's gamma (a weighted Gaussian likelihood maximised by scipy)
and a catalogue row's numbers."""
from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings, strategies as st
from scipy import optimize

from demid.criticism.catalogue import GAMMA_BOUND, Hypothesis
from demid.criticism.extensions import catalogue_entry, drift_per_run, extend_for, step_price, step_size
from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm
from demid.criticism.slips import slip_candidates


def _table(n, k, seed, scale, spacing, drift=0.0, step_at=None, shift=0.0):
    rng = np.random.default_rng(seed)
    x = rng.uniform(1.0, 3.0, (n, k))
    runs = spacing * np.arange(1, n + 1)
    y = 10.0 + x[:, 0] - 0.4 * x[:, -1] ** 2 + drift * runs + 0.1 * rng.standard_normal(n)
    if step_at is not None:
        y = y + shift * (np.arange(n) >= step_at)
    cols = {"run": runs}
    cols.update({f"f{j}": x[:, j] for j in range(k)})
    cols["y"] = scale * y
    return pd.DataFrame(cols)


def _quadratic(x):
    n, k = x.shape
    cols = [np.ones(n)] + [x[:, j] for j in range(k)]
    cols += [x[:, i] * x[:, j] for i in range(k) for j in range(i, k)]
    return np.column_stack(cols)


@settings(max_examples=8, deadline=None, derandomize=True)
@given(k=st.integers(2, 3), n=st.integers(16, 30), seed=st.integers(0, 999), scale=st.sampled_from([0.001, 1.0, 50.0]),
       spacing=st.sampled_from([1, 10]), drift=st.floats(-0.2, 0.2), shift=st.floats(-2.0, 2.0),
       step_share=st.floats(0.3, 0.7))
def test_a_drifts_slope_and_a_steps_shift_are_least_squares_on_the_run_numbers(k, n, seed, scale, spacing, drift,
                                                                                shift, step_share):
    step_at = int(step_share * n)
    table = _table(n, k, seed, scale, spacing, drift, step_at, shift)
    factors = [f"f{j}" for j in range(k)]
    data, _ = prepare_data(table, factors, "y", 1.0, (), None)
    x = _quadratic(table[factors].to_numpy())
    y = table["y"].to_numpy()
    runs = table["run"].to_numpy(dtype=float)
    want_drift = np.linalg.lstsq(np.column_stack([x, runs]), y, rcond=None)[0][-1]
    assert drift_per_run(Model(data, ModelForm(drift=True))) == pytest.approx(want_drift, rel=1e-6, abs=1e-9 * scale)
    after = (np.arange(n) >= step_at).astype(float)
    want_step = np.linalg.lstsq(np.column_stack([x, after]), y, rcond=None)[0][-1]
    assert step_size(Model(data, ModelForm(step=step_at))) == pytest.approx(want_step, rel=1e-6, abs=1e-9 * scale)


@pytest.mark.parametrize("n_points", [1, 7, 25])
def test_a_steps_price_is_the_log_of_its_change_points(n_points):
    assert step_price(Hypothesis("step", 3, info={"change_points": n_points})) == pytest.approx(math.log(n_points))
    assert step_price(Hypothesis("drift", "run", info={"change_points": n_points})) == 0.0
    assert step_price(Hypothesis("step", 3)) == 0.0


@pytest.mark.parametrize("seed, k, log_first", [(1, 2, False), (2, 3, True), (3, 2, False)])
def test_a_slips_recorded_and_fitting_values_are_the_tables_cell_and_its_decimal_shift(seed, k, log_first):
    table = _table(18, k, seed, 1.0, 1)
    factors = [f"f{j}" for j in range(k)]
    data, _ = prepare_data(table, factors, "y", 1.0, ("f0",) if log_first else (), None)
    model = Model(data, ModelForm())
    cands = slip_candidates(data, model)
    assert cands
    for c in cands[:: max(1, len(cands) // 6)]:
        info_in = {"t_moved": 2.5, "bayes_factor": 3.0, "t_recorded": 0.5}
        form, info = extend_for(data, model, Hypothesis("factor_level", c, info=info_in))
        recorded = float(table[factors[c.factor]].iloc[c.row])
        assert info["factor"] == factors[c.factor]
        assert info["recorded_value"] == pytest.approx(recorded, rel=1e-12)
        assert info["fitting_value"] == pytest.approx(recorded * 10.0 ** c.power, rel=1e-9)
        assert info["slip"] == f"x1e{c.power:+d}"
        assert info["observed"] == float(table["y"].iloc[c.row])
        assert (info["t_moved"], info["bayes_factor"], info["t_recorded"]) == (2.5, 3.0, 0.5)
        assert form.moved == ((c.row, c.factor, c.coded),)


def _weighted_loglik(x, y, v, gamma):
    w = np.exp(-gamma * v)
    sw = np.sqrt(w)
    beta = np.linalg.lstsq(x * sw[:, None], y * sw, rcond=None)[0]
    ssr = float(np.sum(w * (y - x @ beta) ** 2))
    n = len(y)
    return -0.5 * n * (np.log(2 * np.pi * ssr / n) + 1.0) + 0.5 * float(np.sum(np.log(w)))


@pytest.mark.parametrize("seed, k, growth, covariate", [(4, 2, 1.5, "f0"), (5, 3, -1.0, "f1"), (6, 2, 0.0, "f1"),
                                                        (7, 2, 2.5, "f0")])
def test_unequal_scatters_gamma_maximises_the_weighted_likelihood(seed, k, growth, covariate):
    rng = np.random.default_rng(seed)
    table = _table(24, k, seed, 1.0, 1)
    j = int(covariate[1])
    v_raw = (table[covariate] - 2.0).to_numpy()
    table["y"] = table["y"] + 0.3 * np.exp(0.5 * growth * v_raw) * rng.standard_normal(len(table))
    factors = [f"f{i}" for i in range(k)]
    data, _ = prepare_data(table, factors, "y", 1.0, (), None)
    model = Model(data, ModelForm())
    form, info = extend_for(data, model, Hypothesis("heteroscedasticity", covariate))
    v = data.coded[:, j] / data.alpha
    x = _quadratic(table[factors].to_numpy())
    y = table["y"].to_numpy()
    res = optimize.minimize_scalar(lambda g: -_weighted_loglik(x, y, v, g), bounds=(-GAMMA_BOUND, GAMMA_BOUND),
                                   method="bounded", options={"xatol": 1e-9})
    assert form.weight_gamma == pytest.approx(res.x, abs=1e-4)
    assert info["sd_ratio"] == pytest.approx(math.exp(form.weight_gamma), rel=1e-12)
    assert form.weight_on == covariate
    np.testing.assert_allclose(form.weight_values, v, rtol=1e-12, atol=1e-15)
    # the likelihood of the fitted model is the one maximised
    assert Model(data, form).loglik == pytest.approx(_weighted_loglik(x, y, v, form.weight_gamma), rel=1e-9)


def test_a_catalogue_row_quotes_the_tests_numbers():
    table = _table(15, 2, 9, 1.0, 10)
    data, _ = prepare_data(table, ["f0", "f1"], "y", 1.0, (), None)
    rows = [(Hypothesis("outlier", 4, [], 3.2, math.log(0.012)), 50),
            (Hypothesis("step", 6, [], 7.5, math.log(0.2)), 70),
            (Hypothesis("response_transform", None, [], 1.1, math.log(0.5)), "boxcox"),
            (Hypothesis("lack_of_fit", None, [], 2.0, math.log(0.3)), ""),
            (Hypothesis("heteroscedasticity", "f1", ["fitted"], 4.0, math.log(0.04)), "f1")]
    for h, detail in rows:
        h.p_family = 0.25
        entry = catalogue_entry(data, h)
        assert entry["cause"] == h.cause and entry["detail"] == detail and entry["aliases"] == list(h.aliases)
        assert entry["statistic"] == h.statistic
        assert entry["p_nominal"] == pytest.approx(math.exp(h.logp), rel=1e-12)
        assert entry["p_family"] == 0.25

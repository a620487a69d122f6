"""The extension that answers a cause (criticism.extensions.extend_for) read whole over generated CCD tables: an
outlier's observed value and the value the other runs predict for it (a least-squares refit without the run,
written out with numpy, 0-2 runs already excluded); a Box-Cox transform's lambda-hat and its small-sample 95 %
interval (the profile log-likelihood computed here with numpy on the documented 0.01 grid, the interval where
the F form of the likelihood ratio stays below F(1, df)'s 95 % point), the lambda used (the first convenient
value inside the 99 % interval); drift and a step as the model forms they add."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import stats

from demid.criticism.catalogue import LAMBDA_FINE_GRID, NICE_LAMBDAS, Hypothesis
from demid.criticism.extensions import extend_for
from demid.criticism.models import TRANSFORM_NAMES, Model, ModelForm
from demid.design import model_matrix, quadratic_terms
from tests.criticism.test_models_properties import _data


@given(seed=st.integers(0, 1000), dropped=st.sampled_from([(), (3,), (0, 9)]), run=st.integers(0, 10))
@settings(max_examples=15, deadline=None, derandomize=True)
def test_an_outliers_predicted_value_is_the_refit_without_it(seed, dropped, run):
    data = _data(seed, 3)
    if run in dropped:
        run = 5
    model = Model(data, ModelForm(dropped=dropped))
    spec, info = extend_for(data, model, Hypothesis("outlier", run))
    assert spec == ModelForm(dropped=dropped + (run,))
    others = [i for i in range(data.n) if i not in dropped and i != run]
    x = model_matrix(data.coded, quadratic_terms(2))
    beta = np.linalg.lstsq(x[others], data.y[others], rcond=None)[0]
    assert info["observed"] == data.y[run]
    assert info["predicted_without"] == pytest.approx(float(x[run] @ beta), rel=1e-9)
    assert set(info) == {"observed", "predicted_without"}


def _profile(y: np.ndarray, x: np.ndarray) -> np.ndarray:
    n = len(y)
    out = []
    for lam in LAMBDA_FINE_GRID:
        z = np.log(y) if lam == 0 else (y ** lam - 1) / lam
        resid = z - x @ np.linalg.lstsq(x, z, rcond=None)[0]
        out.append(-n / 2 * np.log(resid @ resid / n) + (lam - 1) * np.sum(np.log(y)))
    return np.array(out)


def _lambda_by_hand(data, model) -> tuple[float, np.ndarray, np.ndarray]:
    """The profile's best lambda on the fine grid and the grid's lambdas inside its 95 % and 99 % F intervals."""
    prof = _profile(data.y, model_matrix(data.coded, quadratic_terms(2)))
    best = int(np.argmax(prof))
    n, df = data.n, model.df_resid - 1
    f_ratio = df * np.expm1(2 * (prof[best] - prof) / n)
    return (LAMBDA_FINE_GRID[best], LAMBDA_FINE_GRID[f_ratio <= stats.f.ppf(0.95, 1, df)],
            LAMBDA_FINE_GRID[f_ratio <= stats.f.ppf(0.99, 1, df)])


@given(seed=st.integers(0, 1000), power=st.sampled_from([0.0, 0.5, 1.0, -1.0]))
@settings(max_examples=8, deadline=None, derandomize=True)
def test_a_transforms_lambda_hat_interval_and_lambda_used(seed, power):
    data = _data(seed, 3)
    rng = np.random.default_rng(seed)
    eta = 2.0 + 0.3 * data.coded[:, 0] - 0.2 * data.coded[:, 1] + rng.normal(scale=0.03, size=data.n)
    data.y = np.exp(eta) if power == 0 else (1 + power * eta / 4) ** (1 / power) * 10
    model = Model(data, ModelForm())
    spec, info = extend_for(data, model, Hypothesis("response_transform", "boxcox"))
    best, inside, plausible = _lambda_by_hand(data, model)
    assert info["lambda_hat"] == pytest.approx(best, abs=1e-9)
    assert info["lambda_ci"] == pytest.approx([inside.min(), inside.max()], abs=1e-9)
    convenient = [v for v in (*TRANSFORM_NAMES, *NICE_LAMBDAS) if plausible.min() <= v <= plausible.max()]
    used = convenient[0] if convenient else round(best, 1)
    if abs(used - 1.0) < 1e-9 or (not convenient and used in TRANSFORM_NAMES):  # no transform, or a rejected one
        used = round(best, 2)
    assert spec.lam == pytest.approx(used, abs=1e-12)


def test_drift_and_a_step_are_the_model_forms_they_add():
    data = _data(4, 3)
    model = Model(data, ModelForm(dropped=(2,)))
    assert extend_for(data, model, Hypothesis("drift", "run")) == (ModelForm(dropped=(2,), drift=True), {})
    assert extend_for(data, model, Hypothesis("step", np.int64(6))) == (ModelForm(dropped=(2,), step=6), {})


@pytest.mark.parametrize("covariate", ["a", "fitted"])
def test_unequal_scatter_on_a_long_table_has_the_gamma_of_the_model_by_model_search(covariate, monkeypatch):
    """Above ASYMPTOTIC_RUNS runs the weights' gamma is searched from weighted sums of squares alone: the same
    gamma and spread ratio as the search that fits a model at every step (forced here), and a spread that grows
    along a (the table's scatter does) read as growing."""
    from demid.criticism import extensions
    from demid.criticism.level1 import prepare_data
    from tests.criticism.test_large_studies import _table

    data, _ = prepare_data(_table(300, 2, "scatter"), ["a", "b"], "y", 1.0, (), None)
    model = Model(data, ModelForm())
    h = Hypothesis("heteroscedasticity", covariate)
    by_sums, info = extend_for(data, model, h)
    monkeypatch.setattr(extensions, "ASYMPTOTIC_RUNS", 10 ** 9)
    by_models, info_models = extend_for(data, model, h)
    assert by_sums.weight_gamma == pytest.approx(by_models.weight_gamma, abs=1e-5)
    assert info["sd_ratio"] == pytest.approx(info_models["sd_ratio"], rel=1e-5)
    assert by_sums.weight_values == by_models.weight_values
    if covariate == "a":
        assert info["sd_ratio"] > 1.2

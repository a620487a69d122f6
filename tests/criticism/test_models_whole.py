"""Level 1's model fits (criticism.models), the numbers a finding reads from them, over generated CCD tables and
model forms: the summary's every field, the factors' round-off on the fit's scale, the extended surrogate's
prediction at new points and the model row of a later run, each against a weighted least-squares fit written out
with numpy; the axial distance of a CCD read back from its actual levels; the helpers' forms."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import special

from demid.criticism.models import (Model, ModelForm, infer_axial_distance, inv_boxcox, json_number, run_label,
                                    short_number, transform_name)
from demid.design import LEVERAGE_UNPREDICTABLE, ccd_points, model_matrix, quadratic_terms
from tests.criticism.test_models_properties import _data

_FORMS = st.fixed_dictionaries({
    "lam": st.sampled_from([None, 0.0, 0.5, -1.0]), "drift": st.booleans(),
    "dropped": st.sampled_from([(), (2,), (0, 9)]), "gamma": st.sampled_from([None, 0.7, -1.2]),
    "step": st.sampled_from([None, "middle"])})


def _model(seed: int, form: dict, round_off: bool = False) -> Model:
    data = _data(seed, 3)
    if round_off:
        data.factor_round_off = np.random.default_rng(seed).uniform(0.001, 0.01, data.n)
    weighted = form["gamma"] is not None
    # a step before the run labelled n // 2 (at the first run it would be the intercept again)
    step = None if form["step"] is None else int(np.flatnonzero(data.runs == data.n // 2)[0])
    return Model(data, ModelForm(drift=form["drift"], dropped=form["dropped"], lam=form["lam"], step=step,
                                 weight_on="a" if weighted else None, weight_gamma=form["gamma"] or 0.0,
                                 weight_values=tuple(data.coded[:, 0]) if weighted else ()))


def _design_columns(model: Model, rows: np.ndarray) -> np.ndarray:
    """The model matrix at the data's runs ``rows``, written out: quadratic terms, the run column centred on
    the kept runs over the runs' range, the step indicator less its mean over the kept runs."""
    data, keep = model.data, model.keep
    runs = data.runs.astype(float)
    cols = [model_matrix(data.coded[rows], quadratic_terms(2))]
    if model.spec.drift:
        cols.append(((runs[rows] - runs[keep].mean()) / max(np.ptp(runs), 1.0))[:, None])
    if model.spec.step is not None:
        after = (runs >= runs[model.spec.step]).astype(float)
        cols.append((after[rows] - after[keep].mean())[:, None])
    return np.column_stack(cols)


@given(seed=st.integers(0, 1000), form=_FORMS)
@settings(max_examples=20, deadline=None, derandomize=True)
def test_the_summary_and_the_round_off_are_those_of_the_weighted_fit(seed, form):
    model = _model(seed, form, round_off=True)
    data, keep = model.data, model.keep
    y = data.y[keep]
    z = y if form["lam"] is None else special.boxcox(y, form["lam"])
    x = _design_columns(model, np.flatnonzero(keep))
    w = np.exp(-form["gamma"] * data.coded[keep, 0]) if form["gamma"] is not None else np.ones(len(y))
    sw = np.sqrt(w)
    beta = np.linalg.lstsq(x * sw[:, None], z * sw, rcond=None)[0]
    fitted = x @ beta if form["lam"] is None else special.inv_boxcox(x @ beta, form["lam"])
    hat = np.diag((x * sw[:, None]) @ np.linalg.pinv(x * sw[:, None]))
    press = (z - x @ beta) / (1 - hat)
    loo = y - inv_boxcox(z - press, form["lam"])  # clipped as the helpers' test shows, so a far miss is finite
    loo = loo[hat < LEVERAGE_UNPREDICTABLE]
    summary = model.summary()
    assert summary["r2"] == pytest.approx(1 - np.sum((y - fitted) ** 2) / np.sum((y - y.mean()) ** 2), rel=1e-9)
    assert summary["rmse"] == pytest.approx(np.sqrt(np.mean((y - fitted) ** 2)), rel=1e-9)
    assert summary["loo_rmse"] == pytest.approx(np.sqrt(np.mean(loo ** 2)), rel=1e-8)
    assert summary["n_runs"] == len(y) == data.n - len(form["dropped"])
    rank = x.shape[1]
    extra = len(form["dropped"]) + (form["lam"] is not None) + (form["gamma"] is not None)
    assert summary["n_params"] == rank + 1 + extra
    k, n = rank + 1 + extra, data.n
    assert summary["aicc"] == (pytest.approx(-2 * model.loglik + 2 * k * n / (n - k - 1), rel=1e-12) if n - k - 1 > 0
                               else None)
    assert summary["transform"] == (None if form["lam"] is None else transform_name(form["lam"]))
    assert summary["weighting"] == ("a" if form["gamma"] is not None else None)
    assert summary["excluded_runs"] == [int(data.runs[i]) for i in form["dropped"]]
    assert len(summary["terms"]) == x.shape[1]
    # the factors' round-off on the scale the residuals are on: dz/dy = y^(lam - 1), times the weight's root
    derivative = 1.0 if form["lam"] is None else y ** (form["lam"] - 1.0)
    np.testing.assert_allclose(model.factor_round_off_w, data.factor_round_off[keep] * derivative * sw, rtol=1e-12)


@given(seed=st.integers(0, 1000), form=_FORMS)
@settings(max_examples=15, deadline=None, derandomize=True)
def test_the_extended_surrogate_and_a_later_runs_row_predict_as_the_fit(seed, form):
    model = _model(seed, form)
    data, keep = model.data, model.keep
    points = np.random.default_rng(seed).uniform(-1.4, 1.4, (7, 2))
    eta = model_matrix(points, quadratic_terms(2)) @ model.beta[:6]
    expected = eta if form["lam"] is None else special.inv_boxcox(eta, form["lam"])
    np.testing.assert_allclose(model.surrogate().predict(data.to_actual(points)), expected, rtol=1e-9)
    later = 3
    row = model.new_run_row(points, later=later)
    runs = data.runs.astype(float)
    tail = []
    if form["drift"]:
        tail.append((runs.max() + later - runs[keep].mean()) / max(np.ptp(runs), 1.0))
        assert model.surrogate().drift_per_run == pytest.approx(model.beta[model.names.index("run")]
                                                                / max(np.ptp(runs), 1.0), rel=1e-12)
    if form["step"] is not None:
        after = (runs >= data.n // 2).astype(float)
        tail.append(1.0 - after[keep].mean())
    np.testing.assert_allclose(row, np.column_stack([model_matrix(points, quadratic_terms(2)),
                                                     np.tile(tail, (len(points), 1))]), rtol=1e-12, atol=1e-15)


def test_the_round_off_of_a_table_without_printed_factors_is_none():
    assert _model(1, {"lam": 0.0, "drift": False, "dropped": (), "gamma": None, "step": None}).factor_round_off_w \
        is None


@given(alpha=st.floats(1.05, 2.5), centre=st.floats(-50, 50), unit=st.floats(0.01, 30), k=st.integers(2, 4),
       flip=st.booleans())
@settings(max_examples=30, deadline=None, derandomize=True)
def test_the_axial_distance_is_read_back_from_a_ccds_actual_levels(alpha, centre, unit, k, flip):
    coded = ccd_points(k, alpha, 2)
    actual = centre + unit * (-coded if flip else coded)
    assert infer_axial_distance(actual) == pytest.approx(alpha, rel=1e-5)
    # a factorial table (two levels) and a three-level one are no CCD
    assert infer_axial_distance(centre + unit * np.sign(coded)) == 1.0


@pytest.mark.parametrize("centre, unit", [(0.0, 1.0), (5.0, 0.3), (-40.0, 12.0)])
def test_inner_levels_a_millionth_of_the_half_range_from_the_ends_are_the_ends(centre, unit):
    """Coded levels are read to 6 decimals: inner levels at +-(1 - 1e-6) are the ends themselves (a face-centred
    design printed a little unevenly, alpha 1), at +-(1 - 2e-6) they are factorial levels of a CCD whose alpha is
    their inverse."""
    for gap, alpha in ((1e-6, 1.0), (2e-6, 1.0 / (1.0 - 2e-6))):
        coded = np.array([-1.0, -(1.0 - gap), 0.0, 1.0 - gap, 1.0, 0.0])
        actual = np.column_stack([centre + unit * coded, centre + unit * coded[::-1]])
        assert infer_axial_distance(actual) == pytest.approx(alpha, rel=1e-9, abs=0)


def test_helpers_read_as_documented():
    z = np.linspace(-2, 2, 9)
    for lam in (0.0, 0.5, -1.0, 2.0):
        np.testing.assert_allclose(inv_boxcox(z * (0.2 if lam else 1.0), lam),
                                   special.inv_boxcox(z * (0.2 if lam else 1.0), lam), rtol=1e-12)
    assert inv_boxcox(np.array([-3.0]), 0.5)[0] == pytest.approx(np.exp(np.log(1e-12) / 0.5))  # clipped, finite
    assert [transform_name(v) for v in (0.0, 0.5, -1.0, 0.25, 1e-10)] == ["log", "sqrt", "inverse", "boxcox:0.25",
                                                                          "log"]
    assert (run_label(np.float64(7.0)), run_label(7.5), run_label("B3"), run_label(np.int64(4))) == (7, 7.5, "B3", 4)
    assert isinstance(run_label(np.float64(7.0)), int)
    assert (short_number(123456.0), short_number(0.000123456, 3), json_number(np.inf), json_number("2.5")) == \
        ("1.235e+05", "0.000123", None, 2.5)

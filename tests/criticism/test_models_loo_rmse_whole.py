"""A model's leave-one-out RMSE over a selection of runs (criticism.models.Model.loo_rmse_on): the root mean square
of the leave-one-out errors of the selected runs the model predicts, computed here from refits without each run;
over a selection with no predicted run (none selected, or only runs of leverage 1) it is undefined: a float NaN,
which the summaries write as None."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest

from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm, json_number


def _model(points: np.ndarray) -> Model:
    a, b = points[:, 0], points[:, 1]
    y = 5.0 + a + b ** 2 + 0.3 * a * b + 0.05 * np.cos(7.0 * np.arange(len(a)))
    table = pd.DataFrame({"run": np.arange(1, len(a) + 1), "a": a, "b": b, "y": y})
    data, _ = prepare_data(table, ["a", "b"], "y", 1.0, ())
    return Model(data, ModelForm())


def _loo_errors(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    out = np.empty(len(y))
    for i in range(len(y)):
        keep = np.arange(len(y)) != i
        beta = np.linalg.lstsq(x[keep], y[keep], rcond=None)[0]
        out[i] = y[i] - x[i] @ beta
    return out


_GRID = np.array([[a, b] for a in (-1.0, 0.0, 1.0) for b in (-1.0, 0.0, 1.0)] + [[0.0, 0.0]])


def test_the_leave_one_out_rmse_of_selected_runs_is_that_of_refits_without_each():
    model = _model(_GRID)
    err = _loo_errors(model.x, model.y)
    for mask in (np.ones(len(_GRID), dtype=bool), np.arange(len(_GRID)) % 3 == 0):
        assert model.loo_rmse_on(mask) == pytest.approx(math.sqrt(np.mean(err[mask] ** 2)), rel=1e-9)


def test_over_no_predicted_run_the_leave_one_out_rmse_is_a_float_nan():
    model = _model(_GRID)
    rmse = model.loo_rmse_on(np.zeros(len(_GRID), dtype=bool))
    assert isinstance(rmse, float) and math.isnan(rmse) and json_number(rmse) is None
    saturated = _model(_GRID[[0, 2, 6, 8, 4, 1]])  # six runs, six coefficients: every leverage 1
    assert saturated.rank == 6 and not saturated.predictable.any()
    rmse = saturated.loo_rmse_on(np.ones(6, dtype=bool))
    assert isinstance(rmse, float) and math.isnan(rmse) and saturated.summary()["loo_rmse"] is None

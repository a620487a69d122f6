"""A finding's extra numbers (t statistics, a Bayes factor, a lambda interval) may be NaN or infinite where runs
are fitted exactly; the findings' JSON carries them as null, so the document stays valid (``allow_nan=False``)."""

import json
import math

import numpy as np
import pytest

from demid.criticism.level1 import Finding


def _finding(info):
    return Finding(response="y", cause="factor_level", detail=7, aliases=[], p_value=0.01, p_nominal=0.001,
                   statistic=3.5, message="m", loo_rmse_baseline=1.0, loo_rmse_extended=0.5, delta_aicc=-4.0,
                   compared_runs=13, info=info)


@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf, np.float64("nan"), np.float64("-inf")])
def test_non_finite_info_numbers_are_null_at_any_depth(bad):
    info = {"t_moved": bad, "t_recorded": 2.5, "bayes_factor": np.float64(bad), "lambda_ci": [bad, 0.25],
            "runs_before": 4, "factor": "a", "slip": -1, "alternatives": [{"cause": "outlier", "loglik_vs_named": bad,
                                                                          "detail": 7}]}
    out = _finding(info).to_json()
    text = json.dumps(out, allow_nan=False)  # raised ValueError before
    back = json.loads(text)
    assert back["t_moved"] is None and back["bayes_factor"] is None
    assert back["lambda_ci"] == [None, 0.25]
    assert back["alternatives"] == [{"cause": "outlier", "loglik_vs_named": None, "detail": 7}]
    assert back["t_recorded"] == 2.5 and back["runs_before"] == 4 and back["factor"] == "a" and back["slip"] == -1


def test_finite_info_numbers_keep_their_value_and_type():
    info = {"t_moved": np.float64(-1.2345678901234567), "bayes_factor": 21.0, "runs_before": 5, "lambda_hat": 0.5,
            "lambda_ci": (-0.25, 1.75)}
    out = _finding(info).to_json()
    assert out["t_moved"] == -1.2345678901234567 and out["bayes_factor"] == 21.0 and out["lambda_hat"] == 0.5
    assert type(out["runs_before"]) is int and out["runs_before"] == 5
    assert json.loads(json.dumps(out))["lambda_ci"] == [-0.25, 1.75]
    assert repr(out["t_moved"]) == repr(-1.2345678901234567)

"""A finding's extra numbers (t statistics, a Bayes factor, a lambda interval) may be NaN or infinite where runs
are fitted exactly; the criticism's JSON carries them as null, so the document stays valid (``allow_nan=False``):
``CriticismResult.dumps`` and the written file (``write_json``) alike."""

import json
import math

import numpy as np
import pytest

from demid.criticism import criticize
from demid.io import to_json_text

from ..generators import FACTORS, ccd_table


@pytest.fixture(scope="module")
def result():
    table, _ = ccd_table(12, 2, "outlier", 30.0)
    res = criticize(table, FACTORS[2], "y", n_null=19)
    assert res.findings
    return res


def _documents(res):
    """The document as dumps gives it and as the written file has it."""
    return json.loads(res.dumps()), json.loads(to_json_text(res.to_json()))


@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf, np.float64("nan"), np.float64("-inf")])
def test_non_finite_info_numbers_are_null_at_any_depth(result, bad):
    info = result.findings[0].info
    kept = dict(info)
    info.clear()
    info.update({"t_moved": bad, "t_recorded": 2.5, "bayes_factor": np.float64(bad), "lambda_ci": [bad, 0.25],
                 "runs_before": 4, "factor": "a", "slip": -1,
                 "alternatives": [{"cause": "outlier", "loglik_vs_named": bad, "detail": 7}]})
    try:
        for doc in _documents(result):  # dumps raised ValueError before
            back = doc["findings"][0]
            assert back["t_moved"] is None and back["bayes_factor"] is None
            assert back["lambda_ci"] == [None, 0.25]
            assert back["alternatives"] == [{"cause": "outlier", "loglik_vs_named": None, "detail": 7}]
            assert back["t_recorded"] == 2.5 and back["runs_before"] == 4 and back["factor"] == "a"
            assert back["slip"] == -1
    finally:
        info.clear()
        info.update(kept)


def test_finite_info_numbers_keep_their_value_and_type(result):
    info = result.findings[0].info
    kept = dict(info)
    info.update({"t_moved": np.float64(-1.2345678901234567), "bayes_factor": 21.0, "runs_before": 5,
                 "lambda_hat": 0.5, "lambda_ci": (-0.25, 1.75)})
    try:
        exact, written = _documents(result)
        back = exact["findings"][0]
        assert back["t_moved"] == -1.2345678901234567 and back["bayes_factor"] == 21.0 and back["lambda_hat"] == 0.5
        assert type(back["runs_before"]) is int and back["runs_before"] == 5
        assert back["lambda_ci"] == [-0.25, 1.75]
        assert written["findings"][0]["t_moved"] == float("%.10g" % -1.2345678901234567)  # the file's 10 digits
    finally:
        info.clear()
        info.update(kept)

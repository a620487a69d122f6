"""The verdict's message when a next box's grid is given (criticism.verdict.verdict_of with data.run_candidates):
the runs that decide or confirm are chosen on that grid and the message says so; replicates sit at the runs they
repeat, so a message proposing replicates (an unexplained misfit's, a simulated outlier's) never says its runs are
on the box grid.  Every part of the message is checked: the verdict's own text, the replicates' or confirming
runs' sentence with its run labels parsed back, the box sentence present or absent; and the detail's Q², RMSE and
leave-one-out error against statsmodels.  2-3 factor CCDs on ranges of either sign, run labels not row numbers."""

from __future__ import annotations

import math
import re
from dataclasses import replace
from types import SimpleNamespace

import numpy as np
import pytest
import statsmodels.api as sm

from demid import run_purposes
from demid.criticism.level1 import prepare_data
from demid.criticism.verdict import replicate_runs, verdict_of
from demid.design import model_matrix, quadratic_terms
from tests.generators import FACTORS, ccd_table

_BOX_SENTENCE = "The runs are chosen on the next wave's box grid"


def _prepared(seed, k, offset):
    table, _ = ccd_table(seed, k, "outlier", size=6.0)
    for f in FACTORS[k]:
        table[f] = offset + 2.5 * table[f]
    table["run"] = 300 - 3 * table["run"]
    data, fit = prepare_data(table, FACTORS[k], "y", None, ())
    grid = np.zeros((4, k))  # a next box's grid (coded): only its presence is read here
    return table, replace(data, run_candidates=grid), fit


def _statsmodels_numbers(table, data, k):
    x = model_matrix(data.coding.to_coded(table[FACTORS[k]].to_numpy()), quadratic_terms(k))
    y = table["y"].to_numpy()
    res = sm.OLS(y, x).fit()
    h = res.get_influence().hat_matrix_diag
    press = float(np.sum((res.resid / (1 - h)) ** 2))
    return {"rmse": math.sqrt(res.ssr / len(y)),  # the residual RMSE over the runs, as fit_statistics writes it
             "loo_rmse": math.sqrt(press / len(y)),
            "q2": 1 - press / float(np.sum((y - y.mean()) ** 2))}


def _check_numbers(detail, expected):
    for key, value in expected.items():
        assert detail[key] == pytest.approx(value, rel=1e-9)


@pytest.mark.parametrize("seed,k,offset", [(3, 2, -20.0), (11, 3, 0.0), (27, 2, 7.5)])
@pytest.mark.parametrize("simulated", [False, True])
def test_replicates_of_an_unexplained_misfit_are_not_said_to_be_on_the_box_grid(seed, k, offset, simulated):
    table, data, fit = _prepared(seed, k, offset)
    data = replace(data, simulated=simulated)
    unexplained = {"message": "y: misfit unexplained."}
    runs = replicate_runs(data, fit, [], unexplained)
    assert len(runs) == 2 and all("replicate_of" in r for r in runs)
    verdict, detail = verdict_of(data, fit, [], unexplained, [], 0.05, runs=runs)
    msg = detail["message"]
    assert _BOX_SENTENCE not in msg
    assert msg.startswith("y: misfit unexplained. Replicates of the runs that misfit most (")
    labels = [int(v) for v in re.search(r"misfit most \(([^)]*)\)", msg).group(1).replace("run ", "").split(", ")]
    assert labels == [r["replicate_of"] for r in runs]
    assert msg.endswith("the next wave (waves.next_runs) simulates them." if simulated
                        else "a next wave (next_runs) makes them.")
    assert verdict == "unexplained"
    _check_numbers(detail, _statsmodels_numbers(table, data, k))


@pytest.mark.parametrize("seed,k,offset", [(5, 2, -3.0), (8, 3, 12.0)])
def test_replicates_of_a_simulated_outlier_are_not_said_to_be_on_the_box_grid(seed, k, offset):
    table, data, fit = _prepared(seed, k, offset)
    data = replace(data, simulated=True)
    label = int(table["run"][4])
    finding = SimpleNamespace(cause="outlier", detail=label, message=f"y: run {label} is an outlier.")
    runs = replicate_runs(data, fit, [finding], None)
    assert [r["purpose"] for r in runs] == [run_purposes.CONFIRM] * 2
    verdict, detail = verdict_of(data, fit, [finding], None, [], 0.05, runs=runs)
    msg = detail["message"]
    assert _BOX_SENTENCE not in msg
    assert verdict == "defect"
    assert msg.startswith(f"y: defect named — run {label} is an outlier. 2 replicate(s) of run {label} are "
                          "proposed for the next wave")
    _check_numbers(detail, _statsmodels_numbers(table, data, k))


@pytest.mark.parametrize("seed,k,offset", [(5, 2, -3.0), (8, 3, 12.0)])
@pytest.mark.parametrize("n_runs", [1, 2])
def test_confirming_runs_of_a_named_cause_are_said_to_be_on_the_box_grid(seed, k, offset, n_runs):
    table, data, fit = _prepared(seed, k, offset)
    finding = SimpleNamespace(cause="drift", detail="run", message="y: drift in run order.")
    points = [{**{f: 0.25 * (i + 1) for f in FACTORS[k]}, "purpose": run_purposes.CONFIRM,
               "expected": {"drift": 1.0, "step": 2.0}} for i in range(n_runs)]
    verdict, detail = verdict_of(data, fit, [finding], None, [], 0.05, runs=points)
    msg = detail["message"]
    assert verdict == "defect"
    assert msg.startswith("y: defect named — drift in run order. The runs cannot rule out every rival (step:")
    assert f": {n_runs} more run{'s' if n_runs > 1 else ''} made after these" in msg
    _check_numbers(detail, _statsmodels_numbers(table, data, k))
    assert msg.count(_BOX_SENTENCE) == 1
    # without a next box's grid the runs are not said to be on it
    _, plain = verdict_of(replace(data, run_candidates=None), fit, [finding], None, [], 0.05, runs=points)
    assert _BOX_SENTENCE not in plain["message"]
    assert plain["message"] + " " + _BOX_SENTENCE + ", the only place where its table keeps them." == msg

"""A run whose leverage is exactly LEVERAGE_UNPREDICTABLE (0.99, to the last bit) is unpredictable from the
other runs, as everywhere else (Model.predicted, the surrogate's unpredictable runs): slip_ratios does not
judge a slip of it.  The run's response is the one a slip of its first factor by a decimal place would give,
so judging it would make it the best slip; the ratio and the candidate chosen are checked against refits with
numpy's least squares, each candidate's row moved, over the runs that are judged."""
from __future__ import annotations

import numpy as np
import pandas as pd

from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm
from demid.criticism.slips import slip_candidates, slip_ratios
from demid.design import LEVERAGE_UNPREDICTABLE, model_matrix

N_RUNS = 16
#: the last run's first factor near which its leverage computes to 0.99 exactly (a few ulps either side tried)
EDGE_START = 2.4356239873187113


def _study(last_first_factor: float):
    rng = np.random.default_rng(1)
    x = rng.uniform(0.5, 1.5, (N_RUNS, 2))
    y = 4.0 + x[:, 0] + 0.1 * rng.standard_normal(N_RUNS)
    x[-1, 0] = last_first_factor
    y[-1] = 4.0 + last_first_factor / 10.0  # the response of the first factor a decimal place lower
    table = pd.DataFrame({"run": np.arange(1, N_RUNS + 1), "f0": x[:, 0], "f1": x[:, 1], "y": y})
    data, _ = prepare_data(table, ["f0", "f1"], "y", 1.0, (), None)
    return data, Model(data, ModelForm())


def _study_at_the_edge():
    t = EDGE_START
    for _ in range(64):
        for candidate in (t, 2 * EDGE_START - t):
            data, model = _study(candidate)
            if model.hat[-1] == LEVERAGE_UNPREDICTABLE:
                return data, model
        t = np.nextafter(t, np.inf)
    raise AssertionError("no first factor near 2.4356 gives the last run a leverage of exactly 0.99")


def _brute_force_ratios(data, model, cands):
    """sse0 / SSE with the candidate's row moved (refit by least squares), for candidates of judged runs."""
    z = model.z
    x = model.x
    sse0 = float(np.sum((z - x @ np.linalg.lstsq(x, z, rcond=None)[0]) ** 2))
    out = {}
    for k, c in enumerate(cands):
        if model.hat[c.row] >= LEVERAGE_UNPREDICTABLE:
            continue
        coded = data.coded.copy()
        coded[c.row, c.factor] = c.coded
        moved = model_matrix(coded, model.mean_terms)
        sse = float(np.sum((z - moved @ np.linalg.lstsq(moved, z, rcond=None)[0]) ** 2))
        out[k] = sse0 / sse
    return out


def test_a_run_at_exactly_the_unpredictable_leverage_is_not_judged_a_slip():
    data, model = _study_at_the_edge()
    assert np.allclose(model.x, model_matrix(data.coded, model.mean_terms))
    cands = slip_candidates(data, model)
    assert any(c.row == N_RUNS - 1 for c in cands)
    best, arg = slip_ratios(model, cands, model.z[:, None])
    expected = _brute_force_ratios(data, model, cands)
    top = max(expected.values())
    first = min(k for k, v in expected.items() if v >= top * (1 - 1e-9))
    assert best[0] == np.float64(best[0]) and abs(best[0] - top) <= 1e-9 * top
    assert int(arg[0]) == first
    assert cands[int(arg[0])].row != N_RUNS - 1


def test_the_same_run_just_below_the_edge_is_judged_and_chosen():
    # one step of the first factor lower, the leverage is below 0.99: the slip of the last run is the best one
    data, model = _study(2.40)
    assert model.hat[-1] < LEVERAGE_UNPREDICTABLE
    cands = slip_candidates(data, model)
    best, arg = slip_ratios(model, cands, model.z[:, None])
    expected = _brute_force_ratios(data, model, cands)
    top = max(expected.values())
    assert abs(best[0] - top) <= 1e-9 * top
    assert cands[int(arg[0])].row == N_RUNS - 1


def test_the_outlier_price_counts_only_the_runs_below_the_unpredictable_leverage():
    # naming prices an outlier by how many runs it was picked from: the runs the others predict, not the one at
    # exactly 0.99 (the other runs' leverages from the hat matrix written out)
    from demid.criticism.catalogue import Round
    from demid.criticism.naming import _choices

    data, model = _study_at_the_edge()
    x = model.x
    hat = np.diag(x @ np.linalg.pinv(x.T @ x) @ x.T)
    assert np.all(hat[:-1] < LEVERAGE_UNPREDICTABLE - 1e-6)
    rnd = Round(data, model, 19, np.random.default_rng(0))
    assert _choices(rnd)["outlier"] == N_RUNS - 1

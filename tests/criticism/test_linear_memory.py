"""The criticism's memory grows linearly in the runs: the step-in-run-order test holds its change-points' step
columns a chunk at a time, never the n x n matrix of all of them (a table of 10,000 runs would need 800 MB)."""

from __future__ import annotations

import tracemalloc

import numpy as np
import pandas as pd
import pytest

from demid.criticism import catalogue, step_changes
from demid.criticism.catalogue import Round
from demid.criticism.step_changes import step_direction_chunks, step_starts
from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm, orthonormal_basis, residualize


def _random_table(n: int, seed: int = 0) -> pd.DataFrame:
    """n runs at random points of two factors, a quadratic response with noise and a shift after run n/2."""
    rng = np.random.default_rng(seed)
    x = rng.uniform(-1, 1, (n, 2))
    y = 20 + x[:, 0] - 0.5 * x[:, 1] + 0.3 * x[:, 0] ** 2 + 0.05 * rng.standard_normal(n)
    y[n // 2:] += 0.2
    return pd.DataFrame({"run": np.arange(1, n + 1), "a": x[:, 0], "b": x[:, 1], "y": y})


def _step_hypothesis(n: int, n_null: int = 4):
    """The step hypothesis of the first round on a table of n runs, and the peak memory its test traced."""
    data, _ = prepare_data(_random_table(n), ["a", "b"], "y", 1.0, (), None)
    model = Model(data, ModelForm())
    q = orthonormal_basis(model.xw)
    e_null = residualize(q, np.random.default_rng(1).standard_normal((len(model.y), n_null)))
    round_ = object.__new__(Round)  # one member of the family, not the whole round
    round_.hypotheses = []
    tracemalloc.start()
    try:
        round_._step(model, q, model.resid_w[:, None], e_null)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    return round_.hypotheses[0], peak, model, q


def test_step_test_on_5000_runs_never_holds_an_n_by_n_matrix():
    n = 5000
    h, peak, _, _ = _step_hypothesis(n)
    assert h.info["change_points"] == n - 3
    assert peak < 0.25 * n * n * 8, f"peak {peak / 1e6:.0f} MB: an n x n float array is {n * n * 8 / 1e6:.0f} MB"


def test_the_chunks_give_the_statistics_of_all_change_points_at_once(monkeypatch):
    """Cut into chunks of 7 change-points, the step test finds the change-point, F and joint null it finds
    with every step column at once (an independent computation: the columns stacked whole)."""
    whole, _, model, q = _step_hypothesis(60)
    starts, directions = next(step_direction_chunks(model, q, size=10_000))
    assert starts == step_starts(model, q) and directions.shape[1] == len(starts)
    f_obs = catalogue._added_variable_stats_many(model.resid_w[:, None], directions, model.df_resid - 1)[:, 0]
    assert whole.detail == starts[int(np.argmax(f_obs))] and whole.statistic == pytest.approx(f_obs.max(), rel=1e-12)
    monkeypatch.setattr(step_changes, "STEP_CHUNK", 7)
    chunked, _, _, _ = _step_hypothesis(60)
    assert chunked.detail == whole.detail and chunked.info == whole.info
    assert chunked.statistic == pytest.approx(whole.statistic, rel=1e-12)
    np.testing.assert_allclose(chunked.null_logp, whole.null_logp, rtol=1e-12)


def test_rival_steps_on_many_runs_have_the_aicc_of_their_fitted_models():
    """Above STEP_CHUNK runs the AICc of a step at each change-point comes from the base fit, not a fit per
    change-point (runs squared): it equals the AICc of the model fitted with that step."""
    from dataclasses import replace

    from demid.criticism.naming import _step_aiccs

    n = step_changes.STEP_CHUNK + 40
    data, _ = prepare_data(_random_table(n, seed=3), ["a", "b"], "y", 1.0, (), None)
    base = Model(data, ModelForm())
    found = list(_step_aiccs(data, base))
    assert [start for start, _ in found] == step_starts(base, orthonormal_basis(base.xw))
    for start, aicc in found[::25]:
        assert aicc == pytest.approx(Model(data, replace(base.spec, step=start)).aicc, rel=1e-9, abs=1e-9)

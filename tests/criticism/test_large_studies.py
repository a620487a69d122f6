"""Above ASYMPTOTIC_RUNS runs a round of the catalogue costs a fixed number of passes over the runs: the same
numbers as the per-change-point and indicator-matrix computations, and the asymptotic p-values of unequal scatter
and Box-Cox agree with their simulated ones near the decision threshold."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest

from demid.criticism import catalogue
from demid.criticism.catalogue import Round, _between_groups_ss
from demid.criticism.step_changes import step_projections
from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm
from demid.precision import _own_places


def _table(n: int, seed: int, kind: str = "clean") -> pd.DataFrame:
    rng = np.random.default_rng(seed)
    x = rng.uniform(-1, 1, (n, 2))
    mean = 20 + x[:, 0] - 0.5 * x[:, 1] + 0.3 * x[:, 0] ** 2
    sd = 0.05 * (np.exp(0.25 * x[:, 0]) if kind == "scatter" else 1.0)
    y = mean + sd * rng.standard_normal(n)
    runs = np.arange(1, n + 1)
    runs[5:8] = 5  # tied run labels step together
    return pd.DataFrame({"run": runs, "a": x[:, 0], "b": x[:, 1], "y": y})


def test_step_projections_equal_residualised_step_columns_built_one_by_one():
    data, _ = prepare_data(_table(80, 0), ["a", "b"], "y", 1.0, (), None)
    model = Model(data, ModelForm(dropped=(3,)))
    x = model.xw
    q = np.linalg.svd(x, full_matrices=False)[0]
    e = np.column_stack([model.resid_w, np.random.default_rng(1).standard_normal((len(model.y), 3))])
    starts, proj = step_projections(model, q, e)
    kept = np.flatnonzero(model.keep)
    labels = data.runs[kept].astype(float)
    order = np.argsort(labels, kind="stable")
    expected_starts, expected = [], []
    for c in range(2, len(kept) - 1):  # brute force: each step column, residualised by least squares
        after = (labels >= labels[order[c]]).astype(float)
        col = (after - after.mean()) * model.sw
        r = col - x @ np.linalg.lstsq(x, col, rcond=None)[0]
        if np.linalg.norm(r) > 1e-6 * np.linalg.norm(col):
            expected_starts.append(int(kept[order[c]]))
            expected.append(r @ e / np.linalg.norm(r))
    assert starts == expected_starts
    np.testing.assert_allclose(proj, np.array(expected), atol=1e-10)


def test_group_sums_equal_the_indicator_matrix():
    group = np.random.default_rng(2).integers(0, 40, 500)
    group = np.unique(group, return_inverse=True)[1]
    e = np.random.default_rng(3).standard_normal((500, 4))
    n_groups = int(group.max()) + 1
    by_sums = _between_groups_ss(group, n_groups, large=True)(e)
    brute = [sum(e[group == g, b].sum() ** 2 / np.sum(group == g) for g in range(n_groups)) for b in range(4)]
    np.testing.assert_allclose(by_sums, brute, rtol=1e-12)
    np.testing.assert_allclose(_between_groups_ss(group, n_groups, large=False)(e), brute, rtol=1e-12)


def test_own_places_at_once_equal_the_value_by_value_reading():
    rng = np.random.default_rng(0)
    values = np.concatenate([np.round(rng.uniform(-1e4, 1e4, 2000), d) for d in range(8)]
                            + [rng.standard_normal(100), [0.5, 2.5, 1.5e-3, 0.1 + 0.2, 1e-25]])
    values = values[values != 0]
    exponents = np.floor(np.log10(np.abs(values)))
    own = np.zeros(len(values))
    for i, v in enumerate(values):
        for digits in range(1, 13):
            scaled = v * 10.0 ** (digits - 1 - exponents[i])
            if abs(scaled - round(scaled)) <= 1e-12 * max(1.0, abs(scaled)):
                own[i] = 10.0 ** (exponents[i] - digits + 1)
                break
    got = _own_places(values)
    assert np.array_equal(got[0], exponents) and np.array_equal(got[1], own)  # bit for bit


def _round(n, seed, kind, exact, monkeypatch, n_null=999):
    data, _ = prepare_data(_table(n, seed, kind), ["a", "b"], "y", 1.0, (), None)
    monkeypatch.setattr(catalogue, "ASYMPTOTIC_RUNS", 10 ** 9 if exact else 0)
    return Round(data, Model(data, ModelForm()), n_null, np.random.default_rng(seed + 100))


@pytest.mark.workflow  # a benchmark-like batch of tables
@pytest.mark.parametrize("kind", ["clean", "scatter"])
def test_asymptotic_and_simulated_nulls_agree_at_300_runs(kind, monkeypatch):
    """Near the decision threshold (either p below 0.15) the F form's p and the simulated one (999 draws) agree
    within 0.03; the family rejects the same causes over four seeds."""
    for seed in range(4):
        exact = _round(300, seed, kind, True, monkeypatch)
        asymptotic = _round(300, seed, kind, False, monkeypatch)
        for he, ha in zip(exact.hypotheses, asymptotic.hypotheses):
            assert he.cause == ha.cause
            if he.cause == "heteroscedasticity":
                p_simulated = (1 + np.sum(he.null_logp <= he.logp + 1e-12)) / (len(he.null_logp) + 1)
            elif he.cause == "response_transform":
                p_simulated = math.exp(he.logp)
            else:
                continue
            p_f = math.exp(ha.logp)
            if min(p_simulated, p_f) < 0.15 and p_simulated > 5 / 1000:  # above the simulation's floor
                assert abs(p_simulated - p_f) < 0.03, (seed, he.cause, he.detail, p_simulated, p_f)
        assert [(h.cause, str(h.detail)) for h in exact.rejected(0.05)] == \
            [(h.cause, str(h.detail)) for h in asymptotic.rejected(0.05)]


def test_a_round_on_4000_runs_holds_no_n_by_n_array():
    import tracemalloc

    n = 4000
    data, _ = prepare_data(_table(n, 5), ["a", "b"], "y", 1.0, (), None)
    model = Model(data, ModelForm())
    tracemalloc.start()
    try:
        Round(data, model, 16, np.random.default_rng(0))
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < n * n * 8 / 8, f"peak {peak / 1e6:.0f} MB: an n x n float array is {n * n * 8 / 1e6:.0f} MB"

"""The catalogue family's adjusted p-values and statistics (criticism.catalogue) against computations written out
here: Westfall-Young step-down min-P by brute force (each hypothesis in order of its log p, the share of null draws
whose smallest log p over it and the ones after it is at most its own -- a tie, to 1e-12, counts -- kept
monotone), over 1-4 hypotheses, 1-40 null draws and null values on a coarse grid so that ties with the observed
values occur; the family weights (lack of fit 0.65 m, the others sharing the rest, mean 1); the added-variable F of a unit direction against
an OLS fit with and without it (statsmodels' F test); the F tail's log p with negative F read as 0."""

from __future__ import annotations

import numpy as np
import pytest
import statsmodels.api as sm
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import stats

from demid.criticism.catalogue import (LOF_SHARE, added_variable_stats, f_logp, family_weights, stepdown_minp,
                                       weighted_stepdown)

_SETTINGS = settings(max_examples=25, deadline=None, derandomize=True)


def _stepdown_by_hand(obs: np.ndarray, null: np.ndarray) -> list[float]:
    b, m = null.shape
    order = sorted(range(m), key=lambda j: (obs[j], j))
    out, running = [0.0] * m, 0.0
    for rank, j in enumerate(order):
        later = order[rank:]
        hits = sum(1 for row in range(b) if min(null[row, k] for k in later) <= obs[j] + 1e-12)
        running = max(running, (1 + hits) / (b + 1))
        out[j] = running
    return out


@given(m=st.integers(1, 4), b=st.integers(1, 40), seed=st.integers(0, 10 ** 6))
@_SETTINGS
def test_step_down_min_p_is_the_brute_force_with_ties_counted(m, b, seed):
    rng = np.random.default_rng(seed)
    grid = -np.arange(0, 6, 0.5)  # log p values on a grid: observed and null values tie
    # null values also exactly the documented 1e-12 above an observed one: still a tie
    null = rng.choice(np.concatenate([grid, grid + 1e-12]), size=(b, m))
    obs = rng.choice(grid, size=m)
    np.testing.assert_allclose(stepdown_minp(obs, null), _stepdown_by_hand(obs, null), rtol=0, atol=1e-15)


@given(m=st.integers(1, 5), with_lof=st.booleans(), b=st.integers(1, 30), seed=st.integers(0, 10 ** 6))
@_SETTINGS
def test_family_weights_and_the_weighted_step_down(m, with_lof, b, seed):
    rng = np.random.default_rng(seed)
    causes = list(rng.choice(["missing_term", "outlier", "drift", "heteroscedasticity", "step"], size=m))
    if with_lof:
        causes[int(rng.integers(m))] = "lack_of_fit"
    w = family_weights(causes)
    if with_lof and m > 1:
        expected = [LOF_SHARE * m if c == "lack_of_fit" else (1 - LOF_SHARE) * m / (m - 1) for c in causes]
    else:
        expected = [1.0] * m
    np.testing.assert_allclose(w, expected, rtol=1e-12)
    assert w.mean() == pytest.approx(1.0)
    obs = np.log(rng.uniform(1e-4, 1, m))
    null = np.log(rng.uniform(1e-4, 1, (b, m)))
    np.testing.assert_allclose(weighted_stepdown(causes, obs, null),
                               _stepdown_by_hand(obs - np.log(expected), null - np.log(expected)), atol=1e-15)


@given(n=st.integers(6, 20), p=st.integers(1, 4), columns=st.integers(1, 3), seed=st.integers(0, 10 ** 6))
@_SETTINGS
def test_the_added_variable_f_is_statsmodels_f_test_of_the_added_column(n, p, columns, seed):
    rng = np.random.default_rng(seed)
    x = np.column_stack([np.ones(n), rng.normal(size=(n, p - 1))])
    z = rng.normal(size=n)
    y = rng.normal(size=(n, columns)) * 10.0 ** rng.integers(-3, 4)
    q = np.linalg.qr(x)[0]
    e = y - q @ (q.T @ y)
    r = z - q @ (q.T @ z)
    u = r / np.linalg.norm(r)
    df2 = n - p - 1
    f = added_variable_stats(e, u, df2)
    for j in range(columns):
        fit = sm.OLS(y[:, j], np.column_stack([x, z])).fit()
        expected = float(fit.f_test(np.eye(p + 1)[-1:]).fvalue)
        assert f[j] == pytest.approx(expected, rel=1e-7)
        assert f_logp(f[j], df2) == pytest.approx(stats.f.logsf(expected, 1, df2), rel=1e-7, abs=1e-12)
    np.testing.assert_allclose(added_variable_stats(e, u, df2, np.sum(e * e, axis=0)), f, rtol=1e-12)
    assert f_logp(-3.0, df2) == 0.0 and f_logp(0.0, df2) == 0.0

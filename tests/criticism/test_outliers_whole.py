"""The outlier member of the catalogue (criticism.outliers) over generated least-squares fits of 6-30 runs and 2-6
columns, several residual columns at once: each run's externally studentised residual against statsmodels'
influence measures, the largest |t| per column against the whole array, and the family p-value against the
Bonferroni bound 2 n P(T > t) written out with scipy."""

from __future__ import annotations

import numpy as np
import statsmodels.api as sm
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import stats

from demid.criticism.outliers import outlier_logp, outlier_null_max, outlier_stats
from demid.design import LEVERAGE_UNPREDICTABLE


def _fit(seed: int, n: int, p: int, columns: int):
    """A random design of n runs and p columns, and the residuals and leverages of `columns` responses."""
    rng = np.random.default_rng(seed)
    x = np.column_stack([np.ones(n), rng.normal(size=(n, p - 1))])
    y = rng.normal(size=(n, columns)) * 10.0 ** rng.integers(-3, 4) + rng.normal() * 50
    hat_matrix = x @ np.linalg.pinv(x)
    return x, y, y - hat_matrix @ y, np.diag(hat_matrix).copy()


@given(seed=st.integers(0, 10 ** 6), n=st.integers(6, 30), p=st.integers(2, 4), columns=st.integers(1, 3))
@settings(max_examples=30, deadline=None, derandomize=True)
def test_each_runs_t_is_the_externally_studentised_residual_of_statsmodels(seed, n, p, columns):
    x, y, e, hat = _fit(seed, n, p, columns)
    t = outlier_stats(e, hat, n - p)
    assert t.shape == (n, columns)
    for b in range(columns):
        expected = sm.OLS(y[:, b], x).fit().get_influence().resid_studentized_external
        np.testing.assert_allclose(t[:, b], expected, rtol=1e-8, atol=1e-10)
    np.testing.assert_allclose(outlier_null_max(e, hat, n - p), np.max(np.abs(t), axis=0), rtol=1e-13)


def test_a_run_the_others_cannot_predict_gets_no_t_and_the_others_keep_theirs():
    """A run at the leverage limit or above (its own column) has t = 0; a run just below it is studentised."""
    rng = np.random.default_rng(4)
    n = 12
    x = np.column_stack([np.ones(n), rng.normal(size=n), np.zeros(n)])
    x[5, 2] = 1.0  # run 5 alone sets its column: leverage 1
    y = rng.normal(size=(n, 2))
    hat_matrix = x @ np.linalg.pinv(x)
    e, hat = y - hat_matrix @ y, np.diag(hat_matrix).copy()
    assert hat[5] > LEVERAGE_UNPREDICTABLE
    t = outlier_stats(e, hat, n - 3)
    assert np.all(t[5] == 0.0)
    h = np.delete(hat, 5)
    s2 = (np.sum(e * e, axis=0) - np.delete(e, 5, axis=0) ** 2 / (1 - h[:, None])) / (n - 3 - 1)
    np.testing.assert_allclose(np.delete(t, 5, axis=0), np.delete(e, 5, axis=0) / np.sqrt(s2 * (1 - h[:, None])),
                               rtol=1e-10)
    hat_at = hat.copy()
    hat_at[0] = LEVERAGE_UNPREDICTABLE  # exactly at the limit: left out as well
    assert np.all(outlier_stats(e, hat_at, n - 3)[0] == 0.0)


@given(tmax=st.floats(0.0, 40.0), n=st.integers(3, 500), df=st.integers(2, 200))
@settings(max_examples=60, deadline=None, derandomize=True)
def test_the_family_p_value_is_the_bonferroni_bound_over_the_runs_capped_at_one(tmax, n, df):
    expected = min(1.0, 2.0 * n * stats.t.sf(tmax, df - 1))
    got = float(outlier_logp(tmax, n, df))
    assert got <= 0.0
    if expected > 1e-300:
        assert np.exp(got) == np.float64(expected) or abs(np.exp(got) - expected) <= 1e-9 * expected

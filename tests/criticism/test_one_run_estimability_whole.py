"""A missing term's test with each run left out (criticism.one_run.deleted_logp) at the edge of estimability: the
term is tested without a run only when its part beyond the model fitted to the other runs is more than 1e-7 of
the term column's norm (the threshold is relative: a term column of norm 6 whose remainder is 3e-7 is not
estimable, one whose remainder is 1e-3 is).  A 3x3 factorial in coded units plus a run far out on a (a = 1.6) and
one just off a = 1 (a = 1 + delta): without the far run, the cubic a^3 is told from the quadratic only by delta.
Every entry is checked against statsmodels' F test of the term added to the quadratic on the runs kept (the
log of its upper tail), or against 0 where the term is not estimable; two response columns."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest
import statsmodels.api as sm
from scipy import stats

from demid.criticism.one_run import deleted_logp
from demid.design import model_matrix, quadratic_terms

_CUBE = (3, 0)


def _setup(delta: float, scale: float):
    grid = np.array([(a, b) for a in (-1.0, 0.0, 1.0) for b in (-1.0, 0.0, 1.0)])
    coded = scale * np.vstack([grid, [[1.6, 0.0], [1.0 + delta, 0.5]]])
    x = model_matrix(coded, quadratic_terms(2))
    model = SimpleNamespace(coded=coded, x=x, keep=np.ones(len(coded), dtype=bool))
    h = SimpleNamespace(cause="missing_term", detail=SimpleNamespace(terms=[_CUBE]))
    rng = np.random.default_rng(7)
    y = np.column_stack([1.0 + coded[:, 0] - 0.5 * coded[:, 1] ** 2 + 0.3 * coded[:, 0] ** 3,
                         -2.0 + 0.2 * coded[:, 1]]) + 0.1 * rng.standard_normal((len(coded), 2))
    return model, h, y


def _remainder(x, column, keep):
    q, _ = np.linalg.qr(x[keep])
    u = column[keep] - q @ (q.T @ column[keep])
    return np.linalg.norm(u)


def _expected(model, y, column, far):
    n = len(y)
    out = np.zeros((n, y.shape[1]))
    for pos in range(n):
        keep = np.arange(n) != pos
        if pos == far and _remainder(model.x, column, keep) <= 1e-7 * np.linalg.norm(column):
            continue  # not estimable without the far run: log p 0
        for b in range(y.shape[1]):
            small = sm.OLS(y[keep, b], model.x[keep]).fit()
            big = sm.OLS(y[keep, b], np.column_stack([model.x[keep], column[keep]])).fit()
            f_stat, p_value, _ = big.compare_f_test(small)
            assert big.df_resid == keep.sum() - 7
            out[pos, b] = stats.f.logsf(f_stat, 1, big.df_resid)
    return out


@pytest.mark.parametrize("scale", [1.0, 1.5])
@pytest.mark.parametrize("delta,estimable", [(1e-3, True), (None, False)])
def test_a_term_estimable_only_through_a_remainder_below_the_relative_threshold_is_not_tested(scale, delta,
                                                                                             estimable):
    if delta is None:
        # a delta whose remainder without the far run lies between 1e-7 and 1e-7 times the column's norm
        model, _, _ = _setup(1e-7, scale)
        column = model_matrix(model.coded, [_CUBE])[:, 0]
        keep = np.arange(len(column)) != 9
        ratio = _remainder(model.x, column, keep) / 1e-7
        delta = 1e-7 * 0.5 * (1.0 + np.linalg.norm(column)) / ratio  # aims at the middle of the window
    model, h, y = _setup(delta, scale)
    column = model_matrix(model.coded, [_CUBE])[:, 0]
    far = 9
    remainder = _remainder(model.x, column, np.arange(len(y)) != far)
    norm = np.linalg.norm(column)
    if estimable:
        assert remainder > 1e-5 * norm
    else:
        assert 1.2e-7 < remainder < 0.8e-7 * norm  # absolute 1e-7 would test it, the relative threshold does not
    got = deleted_logp(None, model, h, y)
    want = _expected(model, y, column, far)
    assert (got[far] == 0.0).all() != estimable
    np.testing.assert_allclose(got, want, rtol=1e-6, atol=1e-9)

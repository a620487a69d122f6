"""The run a whole-design cause rests on, against refits written in the test: for each run left out, the
cause's nominal test redone with numpy's least squares (a missing term's and drift's added-variable F, a
Box-Cox likelihood ratio in F form), over generated tables of 2-3 factors, 3 to 20 runs more than the quadratic's terms, responses of
different scales and some dropped runs; the worst deletion is the run with the largest p, quoted as p."""
from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings, strategies as st
from scipy import stats

from demid.criticism.aliasing import TermClass
from demid.criticism.catalogue import Hypothesis
from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm
from demid.criticism.one_run import deleted_logp, worst_deletion

LAMBDAS = np.round(np.arange(-2.0, 2.0001, 0.05), 10)


def _table(n, k, seed, scale, curve):
    rng = np.random.default_rng(seed)
    x = rng.uniform(0.1, 1.0, (n, k))
    y = scale * (5.0 + x[:, 0] - 0.5 * x[:, -1] + curve * x[:, 0] ** 3
                 + 0.03 * np.arange(n) / n + 0.05 * rng.standard_normal(n))
    cols = {"run": np.arange(1, n + 1)}
    cols.update({f"f{j}": x[:, j] for j in range(k)})
    cols["y"] = y
    return pd.DataFrame(cols)


def _sse(x, y):
    beta = np.linalg.lstsq(x, y, rcond=None)[0]
    return float(np.sum((y - x @ beta) ** 2))


def _boxcox_lr(x, y):
    n = len(y)
    prof = []
    for lam in LAMBDAS:
        z = np.log(y) if lam == 0 else (y ** lam - 1.0) / lam
        prof.append(-0.5 * n * np.log(_sse(x, z) / n) + (lam - 1.0) * np.sum(np.log(y)))
    prof = np.array(prof)
    return 2.0 * (prof.max() - prof[int(np.flatnonzero(LAMBDAS == 1.0)[0])])


def _refit_logp(model, cause, column):
    """Nominal log p of the cause's test without each kept run (0 where fewer than 3 residual df are left)."""
    n = len(model.z)
    out = np.zeros(n)
    for pos in range(n):
        keep = np.arange(n) != pos
        x, y = model.x[keep], model.z[keep]
        df = int(keep.sum()) - np.linalg.matrix_rank(x)
        if df < 3:
            continue
        if cause == "response_transform":
            stat = (df - 1) * np.expm1(_boxcox_lr(x, y) / (n - 1))
        else:
            sse0 = _sse(x, y)
            sse1 = _sse(np.column_stack([x, column[keep]]), y)
            stat = (sse0 - sse1) / (sse1 / (df - 1))
        out[pos] = stats.f.logsf(max(stat, 0.0), 1, df - 1)
    return out


@pytest.mark.parametrize("cause", ["missing_term", "drift", "response_transform"])
@settings(max_examples=3, deadline=None, derandomize=True)
@given(k=st.integers(2, 3), spare=st.integers(3, 20), seed=st.integers(0, 999),
       scale=st.sampled_from([0.01, 1.0, 300.0]), curve=st.sampled_from([0.0, 0.6]),
       n_dropped=st.integers(0, 2))
def test_each_deletion_and_the_worst_one_match_refits_without_each_run(cause, k, spare, seed, scale, curve, n_dropped):
    n = (k + 1) * (k + 2) // 2 + n_dropped + spare  # 3 spare: without a run 2 residual df, too few to test (p = 1)
    table = _table(n, k, seed, scale, curve)
    factors = [f"f{j}" for j in range(k)]
    data, _ = prepare_data(table, factors, "y", 1.0, (), None)
    model = Model(data, ModelForm(dropped=tuple(range(2, 2 + 3 * n_dropped, 3))))
    kept = np.flatnonzero(model.keep)
    if cause == "missing_term":
        term = (3,) + (0,) * (k - 1)
        h = Hypothesis(cause, TermClass([term], None))
        column = model.coded[:, 0] ** 3
    elif cause == "drift":
        h = Hypothesis(cause, "run")
        column = data.runs[kept].astype(float)
    else:
        h = Hypothesis(cause, None)
        column = None
    want = _refit_logp(model, cause, column)
    got = deleted_logp(data, model, h, model.z[:, None])[:, 0]
    np.testing.assert_allclose(got, want, rtol=1e-6, atol=1e-9)
    worst = worst_deletion(data, model, h)
    assert worst.row == int(kept[int(np.argmax(want))])
    assert worst.p_without == pytest.approx(float(np.exp(want.max())), rel=1e-6)


def test_causes_of_one_run_and_weighted_models_have_no_worst_deletion():
    table = _table(20, 2, 1, 1.0, 0.0)
    data, _ = prepare_data(table, ["f0", "f1"], "y", 1.0, (), None)
    plain = Model(data, ModelForm())
    assert worst_deletion(data, plain, Hypothesis("outlier", 3)) is None
    assert worst_deletion(data, plain, Hypothesis("factor_level", None)) is None
    weighted = Model(data, ModelForm(weight_on="f0", weight_gamma=0.5,
                                     weight_values=tuple(float(v) for v in data.coded[:, 0] / data.alpha)))
    assert worst_deletion(data, weighted, Hypothesis("drift", "run")) is None
    assert worst_deletion(data, plain, Hypothesis("drift", "run")) is not None

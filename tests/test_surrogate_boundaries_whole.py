"""A fit at the boundaries of its rules, against computations written out here: a block column holding one level
is no blocking (the same fit as none), two levels are; the normality test runs from exactly three runs (scipy's
Shapiro-Wilk on the residuals) and not on two; a fit with exactly as many runs as terms has no residual scatter,
one run more has it (least squares written out)."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from scipy import stats

from demid.design import quadratic_terms
from demid.surrogate import fit_response


def _table(n, seed=3):
    rng = np.random.default_rng(seed)
    x = np.linspace(1.0, 3.0, n)
    return pd.DataFrame({"run": np.arange(1, n + 1), "a": x, "y": 2.0 + 0.7 * x + rng.normal(scale=0.3, size=n)})


def test_a_block_column_of_one_level_is_no_blocking_and_of_two_is():
    table = _table(8)
    plain = fit_response(table, ["a"], "y", terms=[(0,), (1,)])
    one = fit_response(table.assign(block="day 1"), ["a"], "y", terms=[(0,), (1,)])
    assert one.blocks is None and one.term_names == plain.term_names
    np.testing.assert_array_equal(one.results.params.to_numpy(), plain.results.params.to_numpy())
    two = fit_response(table.assign(block=["day 1"] * 4 + ["day 2"] * 4), ["a"], "y", terms=[(0,), (1,)])
    assert two.blocks is not None and len(two.results.params) == 3


@pytest.mark.parametrize("n", [3, 4, 6])
def test_the_normality_test_runs_from_three_runs(n):
    fit = fit_response(_table(n), ["a"], "y", terms=[(0,), (1,)])
    w, p = stats.shapiro(fit.results.resid.to_numpy())
    got = fit.diagnostics()
    assert got.shapiro_w == pytest.approx(w, rel=1e-12) and got.shapiro_p == pytest.approx(p, rel=1e-9)


def test_no_normality_test_on_two_runs():
    got = fit_response(_table(2), ["a"], "y", terms=[(0,), (1,)]).diagnostics()
    assert np.isnan(got.shapiro_w) and np.isnan(got.shapiro_p)


@pytest.mark.parametrize("extra", [0, 1, 2])
def test_the_residual_scatter_needs_one_run_more_than_terms(extra):
    terms = quadratic_terms(1)  # three terms
    table = _table(3 + extra, seed=5)
    fit = fit_response(table, ["a"], "y", terms=terms)
    stats_ = fit.statistics()
    x = np.column_stack([np.ones(len(table)), fit.coded[:, 0], fit.coded[:, 0] ** 2])
    y = table["y"].to_numpy()
    beta, *_ = np.linalg.lstsq(x, y, rcond=None)
    sse = float(np.sum((y - x @ beta) ** 2))
    sst = float(np.sum((y - y.mean()) ** 2))
    n, p = len(y), 3
    if extra == 0:
        assert np.isnan(stats_.resid_std) and np.isnan(stats_.adj_r2)
    else:
        assert stats_.resid_std == pytest.approx(np.sqrt(sse / (n - p)), rel=1e-9)
        assert stats_.adj_r2 == pytest.approx(1 - (sse / (n - p)) / (sst / (n - 1)), rel=1e-9, abs=1e-12)
    assert stats_.r2 == pytest.approx(1 - sse / sst, rel=1e-9, abs=1e-12)

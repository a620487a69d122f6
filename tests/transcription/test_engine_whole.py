"""The transcription check's refit engine against least squares written out per hypothesis with numpy and scipy:
for one design and many response columns (DesignFit) and for many designs and one response (evaluate_designs),
every statistic (R², adjusted R², RMSE, residual SD, Q² from PRESS, the sums of squares, the lack-of-fit F, its
degrees of freedom and p-value) and the coefficients in coded and in actual units (the latter from a fit on the
actual-unit model matrix), over generated designs of one to three factors with and without replicates, linear or
quadratic models, and run counts on both sides of the projection limit (256 runs)."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import stats

from demid.design import Coding, model_matrix, quadratic_terms
from demid.transcription.engine import DesignFit, _coded_to_actual_matrix, evaluate_designs, lack_of_fit_p

SETTINGS = settings(max_examples=10, deadline=None, derandomize=True)


def _reference(coded, y, terms, coding):
    """Every statistic of the least-squares fit of y on the coded model, written out."""
    x = model_matrix(coded, terms)
    n, p = x.shape
    rank = np.linalg.matrix_rank(x)
    beta, *_ = np.linalg.lstsq(x, y, rcond=None)
    resid = y - x @ beta
    hat = np.diag(x @ np.linalg.pinv(x))
    sse, sst = resid @ resid, np.sum((y - y.mean()) ** 2)
    keys = [tuple(np.round(row, 6)) for row in coded]
    groups = {key: [i for i, other in enumerate(keys) if other == key] for key in keys}
    ss_pe = sum(np.sum((y[idx] - y[idx].mean()) ** 2) for idx in groups.values())
    df_pe = n - len(groups)
    df_lof = n - rank - df_pe
    lof_f = ((sse - ss_pe) / df_lof) / (ss_pe / df_pe) if df_lof > 0 and df_pe > 0 and ss_pe > 0 else np.nan
    actual_beta, *_ = np.linalg.lstsq(model_matrix(coding.to_actual(coded), terms), y, rcond=None)
    return {
        "r2": 1 - sse / sst, "adj_r2": 1 - (sse / (n - p)) / (sst / (n - 1)) if n > p else np.nan,
        "rmse": np.sqrt(sse / n), "resid_std": np.sqrt(sse / (n - p)) if n > p else np.nan,
        "q2": 1 - np.sum((resid / (1 - hat)) ** 2) / sst if np.all(hat < 1 - 1e-9) else np.nan,
        "ss_model": sst - sse, "ss_residual": sse, "ss_lof": sse - ss_pe, "ss_pure_error": ss_pe, "ss_total": sst,
        "lof_f": lof_f, "lof_p": stats.f.sf(lof_f, df_lof, df_pe) if np.isfinite(lof_f) else np.nan,
        "_df_lof": df_lof, "_df_pe": df_pe, "_n": n, "_df_model_resid": n - p,
        "b_coded": beta, "b_actual": actual_beta,
    }


def _design(rng, k, n, replicates):
    base = rng.choice([-1.0, 0.0, 1.0, 1.5, -1.5], size=(n, k))
    base[: 2 ** k] = np.array([[(1.0 if (r >> i) & 1 else -1.0) for i in range(k)] for r in range(2 ** k)])[:n]
    if replicates:
        base[-replicates:] = base[:replicates]
    return base + rng.choice([0.0, 0.03], size=(n, k)) * (not replicates)


def _check(got, want, column, coefficients):
    for name in ("r2", "adj_r2", "rmse", "resid_std", "q2", "ss_model", "ss_residual", "ss_lof", "ss_pure_error",
                 "ss_total", "lof_f", "lof_p", "_df_lof", "_df_pe", "_n", "_df_model_resid"):
        value = np.atleast_1d(got[name])[column]
        if np.isnan(want[name]):
            assert np.isnan(value), name
        else:
            assert value == pytest.approx(want[name], rel=1e-7, abs=1e-9 * max(1.0, want["ss_total"])), name
    for key, (units, index) in coefficients.items():
        assert np.atleast_1d(got[key])[column] == pytest.approx(want[f"b_{units}"][index], rel=1e-6, abs=1e-8), key


@given(seed=st.integers(0, 10_000), k=st.integers(1, 3), quadratic=st.booleans(), extra=st.integers(1, 8),
       replicates=st.sampled_from([0, 2, 4]), columns=st.integers(1, 4))
@SETTINGS
def test_one_design_many_responses_every_statistic_and_coefficient(seed, k, quadratic, extra, replicates, columns):
    rng = np.random.default_rng(seed)
    terms = quadratic_terms(k) if quadratic else quadratic_terms(k)[:k + 1]
    n = len(terms) + extra + replicates
    coded = _design(rng, k, n, replicates)
    coding = Coding(tuple(f"x{i}" for i in range(k)), tuple(rng.uniform(-5, 5, k)), tuple(rng.uniform(0.5, 3, k)))
    y = rng.normal(size=(n, columns)) * 3 + 10
    coefficients = {"b0": ("coded", 0), "a1": ("actual", 1), "a0": ("actual", 0)}
    fit = DesignFit(coded, terms, coding, need_actual=True)
    got = lack_of_fit_p(fit.evaluate(y, coefficients))
    for c in range(columns):
        _check(got, _reference(coded, y[:, c], terms, coding), c, coefficients)


@given(seed=st.integers(0, 10_000), k=st.integers(1, 3), designs=st.integers(1, 4),
       replicates=st.sampled_from([0, 3]), many_runs=st.sampled_from([False, False, True]))
@SETTINGS
def test_many_designs_one_response_every_statistic_and_coefficient(seed, k, designs, replicates, many_runs):
    rng = np.random.default_rng(seed)
    terms = quadratic_terms(k)
    n = 260 if many_runs else len(terms) + 4 + replicates
    coded = np.stack([_design(rng, k, n, replicates) for _ in range(designs)])
    codings = [Coding(tuple(f"x{i}" for i in range(k)), tuple(rng.uniform(-5, 5, k)), tuple(rng.uniform(0.5, 3, k)))
               for _ in range(designs)]
    y = rng.normal(size=n) * 2 - 7
    coefficients = {"b1": ("coded", 1), "a0": ("actual", 0), "a_last": ("actual", len(terms) - 1)}
    to_actual = [_coded_to_actual_matrix(c, terms) for c in codings]
    got = lack_of_fit_p(evaluate_designs(coded, y, terms, to_actual, coefficients))
    for m in range(designs):
        _check(got, _reference(coded[m], y, terms, codings[m]), m, coefficients)

"""Every field of a fit's statistics (Table 2) against a least-squares fit written out with numpy, over generated
designs of one to three factors, linear or quadratic terms, with or without blocks, and run counts from saturated
(no residual degrees of freedom: the scaled statistics are undefined, not an error) to well above the parameters."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.design import LEVERAGE_UNPREDICTABLE
from demid.surrogate import fit_response

SETTINGS = settings(max_examples=12, deadline=None, derandomize=True)


def _terms(k: int, quadratic: bool) -> list[tuple[int, ...]]:
    unit = [tuple(int(i == j) for i in range(k)) for j in range(k)]
    terms = [tuple([0] * k), *unit]
    if quadratic:
        terms += [tuple(2 * int(i == j) for i in range(k)) for j in range(k)]
    return terms


def _columns(x: np.ndarray, terms) -> np.ndarray:
    return np.column_stack([np.prod(x ** np.array(t), axis=1) for t in terms])


def _reference(x_model: np.ndarray, y: np.ndarray):
    """SSE, SST, leverages and leave-one-out residuals of the least-squares fit of y on x_model."""
    beta, *_ = np.linalg.lstsq(x_model, y, rcond=None)
    resid = y - x_model @ beta
    hat = np.diag(x_model @ np.linalg.pinv(x_model))
    return float(resid @ resid), float(np.sum((y - y.mean()) ** 2)), hat, resid


def _close(actual, expected, rel=1e-7, abs_=1e-9):
    if isinstance(expected, float) and math.isnan(expected):
        return isinstance(actual, float) and math.isnan(actual)
    return math.isclose(actual, expected, rel_tol=rel, abs_tol=abs_)


@given(k=st.integers(1, 3), quadratic=st.booleans(), extra=st.sampled_from([0, 1, 3, 9]),
       n_blocks=st.sampled_from([1, 1, 2, 3]), seed=st.integers(0, 10_000), scale=st.sampled_from([1e-3, 1.0, 250.0]))
@SETTINGS
def test_every_statistic_matches_least_squares_written_out(k, quadratic, extra, n_blocks, seed, scale):
    rng = np.random.default_rng(seed)
    terms = _terms(k, quadratic)
    p = len(terms) + n_blocks - 1
    n = p + extra
    lower, upper = rng.uniform(-5, 1, size=k), rng.uniform(2, 8, size=k)
    x = rng.uniform(lower, upper, size=(n, k))
    y = scale * (rng.normal(size=n) + x @ rng.normal(size=k))
    factors = [f"f{i + 1}" for i in range(k)]
    table = pd.DataFrame(x, columns=factors)
    table.insert(0, "run", np.arange(1, n + 1))
    table["y"] = y
    blocks = None
    if n_blocks > 1:
        # every block holds at least one run, the rest drawn at random
        blocks = np.concatenate([np.arange(n_blocks), rng.integers(0, n_blocks, size=n - n_blocks)])
        table["block"] = [f"B{b + 1}" for b in blocks]
    fit = fit_response(table, factors, "y", terms=terms)
    stats = fit.statistics()

    coded = fit.coded
    x_model = _columns(coded, terms)
    if blocks is not None:
        # any coding of the blocks spans the same column space: indicators of all blocks but the first
        x_model = np.column_stack([x_model] + [(blocks == b).astype(float) for b in range(1, n_blocks)])
    sse, sst, hat, resid = _reference(x_model, y)
    df_res = n - p
    assert (stats.response, stats.n_runs, stats.n_params) == ("y", n, p)
    assert _close(stats.r2, 1.0 - sse / sst)
    assert _close(stats.rmse, math.sqrt(sse / n), abs_=1e-9 * scale)
    if df_res > 0:
        assert _close(stats.adj_r2, 1.0 - (sse / df_res) / (sst / (n - 1)))
        assert _close(stats.resid_std, math.sqrt(sse / df_res), abs_=1e-9 * scale)
    else:
        assert math.isnan(stats.adj_r2) and math.isnan(stats.resid_std)
    if np.any(hat >= LEVERAGE_UNPREDICTABLE):
        assert math.isnan(stats.press) and math.isnan(stats.q2)
    else:
        press = float(np.sum((resid / (1.0 - hat)) ** 2))
        assert _close(stats.press, press, rel=1e-6, abs_=1e-9 * scale ** 2)
        assert _close(stats.q2, 1.0 - press / sst, rel=1e-6)
    for value in (stats.r2, stats.adj_r2, stats.rmse, stats.resid_std, stats.press, stats.q2):
        assert type(value) is float  # written to JSON and the report as plain numbers

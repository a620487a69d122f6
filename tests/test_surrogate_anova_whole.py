"""A fit's ANOVA, every row and number, against least squares written out in the test over generated tables: one to
three factors on a three-level grid with replicated centre runs, one to three blocks of unequal sizes, responses of
either sign and scale.  Blocks first (their sum of squares is the spread of the block means), the model adjusted for
them, each term group's partial sum of squares (the rise of the residual sum of squares when the group is dropped,
block terms kept), the residual split into lack of fit and pure error (replicates within their block), every F and
p-value from scipy's F distribution, in the order the fit step stores them."""

from __future__ import annotations

import itertools

import numpy as np
import pandas as pd
import pytest
from hypothesis import Phase, given, settings
from hypothesis import strategies as st
from scipy import stats

from demid.design import Coding
from demid.surrogate import fit_response


def _columns(x):
    """Intercept, linear, two-factor interaction and pure quadratic columns, by group."""
    k = x.shape[1]
    groups = {"Intercept": [np.ones(len(x))], "Linear": [x[:, i] for i in range(k)],
              "Two-factor interaction": [x[:, i] * x[:, j] for i, j in itertools.combinations(range(k), 2)],
              "Pure quadratic": [x[:, i] ** 2 for i in range(k)]}
    return {g: np.column_stack(c) for g, c in groups.items() if c}


def _sse(matrix, y):
    beta, *_ = np.linalg.lstsq(matrix, y, rcond=None)
    return float(np.sum((y - matrix @ beta) ** 2))


def _f_row(ss, df, ss_den, df_den):
    if df <= 0 or df_den <= 0:
        return np.nan, np.nan  # no test without degrees of freedom on both sides
    f = (ss / df) / (ss_den / df_den)
    return f, stats.f.sf(f, df, df_den)


@given(seed=st.integers(0, 10_000), k=st.integers(1, 3), n_blocks=st.integers(1, 3), sign=st.sampled_from([-1, 1]),
       scale=st.sampled_from([1e-3, 1.0, 1e4]), centres=st.integers(2, 4))
@settings(max_examples=9, deadline=None, derandomize=True, phases=(Phase.explicit, Phase.generate))
def test_every_row_of_a_fit_s_anova_against_least_squares(seed, k, n_blocks, sign, scale, centres):
    rng = np.random.default_rng(seed)
    factors = ["a", "b", "c"][:k]
    points = np.array(list(itertools.product([-1.0, 0.0, 1.0], repeat=k)))
    # each block a whole three-level grid with its own centre runs (the first block two more): blocks orthogonal
    # to the polynomial, of unequal sizes
    per_block = [np.vstack([points, np.zeros((centres + 2 * (b == 0), k))]) for b in range(n_blocks)]
    x = np.vstack(per_block)
    blocks = np.concatenate([np.full(len(part), b) for b, part in enumerate(per_block)])
    n = len(x)
    cols = _columns(x)
    beta = rng.normal(size=sum(c.shape[1] for c in cols.values()))
    y = sign * scale * (5.0 + np.column_stack(list(cols.values())) @ beta + rng.normal(0, 0.3, n)
                        + np.array([0.0, 0.8, -0.5])[blocks])
    table = pd.DataFrame(x, columns=factors)
    table["y"] = y
    if n_blocks > 1:
        table["block"] = blocks + 1
    fit = fit_response(table, factors, "y", coding=Coding(tuple(factors), (0.0,) * k, (1.0,) * k))

    labels = sorted(set(blocks))
    dummies = np.column_stack([(blocks == b).astype(float) for b in labels[1:]]) if len(labels) > 1 \
        else np.zeros((n, 0))
    full = np.column_stack([*cols.values(), dummies])
    sse = _sse(full, y)
    sst = float(np.sum((y - y.mean()) ** 2))
    ss_block = float(sum(np.sum(blocks == b) * (y[blocks == b].mean() - y.mean()) ** 2 for b in labels))
    p_poly = full.shape[1] - dummies.shape[1]
    df_res = n - full.shape[1]
    keys = [tuple(row) + (b,) for row, b in zip(x, blocks)]
    replicate_groups = {key: y[[i for i, other in enumerate(keys) if other == key]] for key in set(keys)}
    ss_pe = float(sum(np.sum((g - g.mean()) ** 2) for g in replicate_groups.values()))
    df_pe = n - len(replicate_groups)

    anova = fit.anova()
    scale_ss = max(sst, 1e-300)
    for got, expected in [(anova.ss_total, sst), (anova.ss_residual, sse), (anova.ss_block, ss_block),
                          (anova.ss_model, sst - sse - ss_block), (anova.ss_pure_error, ss_pe),
                          (anova.ss_lof, sse - ss_pe)]:
        assert got == pytest.approx(expected, rel=1e-7, abs=1e-9 * scale_ss)
    assert (anova.df_total, anova.df_model, anova.df_block, anova.df_residual, anova.df_pure_error, anova.df_lof) \
        == (n - 1, p_poly - 1, len(labels) - 1, df_res, df_pe, df_res - df_pe)

    expected_rows = [("Blocks", ss_block, len(labels) - 1, *_f_row(ss_block, len(labels) - 1, sse, df_res))] \
        if len(labels) > 1 else []
    expected_rows.append(("Model", sst - sse - ss_block, p_poly - 1, *_f_row(sst - sse - ss_block, p_poly - 1, sse,
                                                                          df_res)))
    for group, matrix in cols.items():
        if group == "Intercept":
            continue
        reduced = np.column_stack([m for g, m in cols.items() if g != group] + [dummies])
        ss = _sse(reduced, y) - sse
        expected_rows.append((group, ss, matrix.shape[1], *_f_row(ss, matrix.shape[1], sse, df_res)))
    expected_rows += [("Residual", sse, df_res, np.nan, np.nan),
                      ("Lack of fit", sse - ss_pe, df_res - df_pe, *_f_row(sse - ss_pe, df_res - df_pe, ss_pe, df_pe)),
                      ("Pure error", ss_pe, df_pe, np.nan, np.nan), ("Total (corrected)", sst, n - 1, np.nan, np.nan)]
    frame = fit.anova_frame()
    assert list(frame["source"]) == [row[0] for row in expected_rows]
    assert list(frame["df"]) == [row[2] for row in expected_rows]
    np.testing.assert_allclose(frame["sum_sq"].to_numpy(float), [row[1] for row in expected_rows], rtol=1e-7,
                               atol=1e-9 * scale_ss)
    np.testing.assert_allclose(frame["mean_sq"].to_numpy(float), [row[1] / row[2] if row[2] > 0 else np.nan for row in expected_rows],
                               rtol=1e-7, atol=1e-9 * scale_ss)
    np.testing.assert_allclose(frame["F"].to_numpy(float), [row[3] for row in expected_rows], rtol=1e-6)
    np.testing.assert_allclose(frame["p_value"].to_numpy(float), [row[4] for row in expected_rows], rtol=1e-5,
                               atol=1e-12)

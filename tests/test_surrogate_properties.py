"""The fit's stored ANOVA rows per term group and the response error the factors' printed precision adds, over
generated CCDs of two and three factors, against computations made apart: each group's partial sum of squares
from least-squares fits without it, and the round-off from the fitted surface's gradient by finite differences."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import stats

from demid.precision import factor_print_quantum
from demid.surrogate import fit_response

from .helpers import make_ccd_table

SETTINGS = settings(max_examples=6, deadline=None, derandomize=True)


def _coded_columns(coded):
    """The full quadratic in coded units, by group (the reference for each group's partial sum of squares)."""
    k = coded.shape[1]
    linear = [coded[:, i] for i in range(k)]
    interaction = [coded[:, i] * coded[:, j] for i in range(k) for j in range(i + 1, k)]
    square = [coded[:, i] ** 2 for i in range(k)]
    return {"Linear": linear, "Two-factor interaction": interaction, "Pure quadratic": square}


def _sse(columns, y):
    x = np.column_stack([np.ones(len(y)), *columns])
    beta, *_ = np.linalg.lstsq(x, y, rcond=None)
    return float(np.sum((y - x @ beta) ** 2))


@given(k=st.sampled_from([2, 3]), seed=st.integers(0, 1000), noise=st.sampled_from([0.05, 1.0, 30.0]))
@SETTINGS
def test_each_term_groups_row_is_its_partial_sum_of_squares_f_and_p(k, seed, noise):
    rng = np.random.default_rng(seed)
    coef = rng.normal(size=1 + 2 * k + k * (k - 1) // 2)
    lower, upper = rng.uniform(0.5, 2.0, size=k), rng.uniform(3.0, 9.0, size=k)
    alpha = 1.41421 if k == 2 else 1.68179
    centre, unit = (lower + upper) / 2, (upper - lower) / (2 * alpha)

    def responses(x):
        z = (x - centre) / unit
        groups = _coded_columns(z)
        columns = [np.ones(len(x)), *groups["Linear"], *groups["Two-factor interaction"], *groups["Pure quadratic"]]
        return {"y": np.column_stack(columns) @ coef}

    table = make_ccd_table(responses, lower, upper, alpha=alpha, noise=noise, seed=seed)
    factors = [f"x{i + 1}" for i in range(k)]
    fit = fit_response(table, factors, "y", alpha=alpha)
    frame = fit.anova_frame().set_index("source")
    coded = (table[factors].to_numpy() - centre) / unit
    y = table["y"].to_numpy()
    groups = _coded_columns(coded)
    sse_full = _sse([c for g in groups.values() for c in g], y)
    df_residual = len(y) - (1 + sum(len(g) for g in groups.values()))
    assert list(frame.index[:4]) == ["Model", "Linear", "Two-factor interaction", "Pure quadratic"]
    for name, columns in groups.items():
        others = [c for g, cols in groups.items() if g != name for c in cols]
        ss = _sse(others, y) - sse_full
        f = (ss / len(columns)) / (sse_full / df_residual)
        row = frame.loc[name]
        assert row["df"] == len(columns)
        assert row["sum_sq"] == pytest.approx(ss, rel=1e-7, abs=1e-9 * np.sum(y ** 2))
        assert row["mean_sq"] == pytest.approx(ss / len(columns), rel=1e-7, abs=1e-9 * np.sum(y ** 2))
        assert row["F"] == pytest.approx(f, rel=1e-6)
        assert row["p_value"] == pytest.approx(stats.f.sf(f, len(columns), df_residual), rel=1e-6, abs=1e-300)


@given(k=st.sampled_from([2, 3]), seed=st.integers(0, 1000), decimals=st.integers(3, 5))
@SETTINGS
def test_the_factors_round_off_is_the_surfaces_gradient_times_their_printed_place(k, seed, decimals):
    """sd per run = sqrt(sum_j (dy/dx_j q_j)^2 / 12), q_j the printed place of a rounded factor value."""
    rng = np.random.default_rng(seed)
    coef = rng.normal(size=1 + 2 * k + k * (k - 1) // 2) * 10
    alpha = 1.41421 if k == 2 else 1.68179

    def responses(x):
        z = (x - 20.0) / 10.0
        columns = [np.ones(len(x)), *(z.T), *(z[:, i] * z[:, j] for i in range(k) for j in range(i + 1, k)),
                   *(z.T ** 2)]
        return {"y": np.column_stack(columns) @ coef}

    table = make_ccd_table(responses, np.full(k, 10.0), np.full(k, 30.0), alpha=alpha, center_runs=3, seed=seed)
    factors = [f"x{i + 1}" for i in range(k)]
    table[factors] = table[factors].round(decimals)
    table["y"] = responses(table[factors].to_numpy())["y"]
    fit = fit_response(table, factors, "y", alpha=alpha)
    x = table[factors].to_numpy()
    surface = fit.surrogate()
    h = 1e-5
    gradient = np.column_stack([(surface.predict(x + h * np.eye(k)[j]) - surface.predict(x - h * np.eye(k)[j]))
                                / (2 * h) for j in range(k)])
    quantum = np.column_stack([factor_print_quantum(x[:, j]) for j in range(k)])
    assert quantum.max() > 0  # premise: the derived axial levels look rounded
    expected = np.sqrt(np.sum((gradient * quantum) ** 2, axis=1) / 12.0)
    np.testing.assert_allclose(fit.factor_round_off, expected, rtol=1e-5, atol=1e-12)

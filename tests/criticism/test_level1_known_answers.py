"""Known answers for level 1's reported numbers: a factor value recorded ten times too large is named, and the
leave-one-out errors before and after are those of the plain quadratic refitted here (hat matrix, numpy) on the
table as recorded and with the named cell set to the value that fits."""

from __future__ import annotations

import numpy as np
import pytest

from demid.criticism import criticize

from ..generators import FACTORS, off_catalogue_table


def _loo_rmse(table, factors, response="y") -> float:
    x = table[factors].to_numpy(dtype=float)
    a, b = x[:, 0], x[:, 1]
    design = np.column_stack([np.ones(len(a)), a, b, a * a, a * b, b * b])  # the quadratic in actual units
    hat = design @ np.linalg.pinv(design)
    y = table[response].to_numpy(dtype=float)
    loo = (y - hat @ y) / (1 - np.diag(hat))
    return float(np.sqrt(np.mean(loo ** 2)))


def _prediction_t(table, fixed, run, moved) -> float:
    """(y_i - x_i b) / (s sqrt(1 + x_i (X'X)^-1 x_i')) with b, s and X from the quadratic fitted to the other
    runs, x_i the run's row at its recorded (or moved) factor values: its externally studentised residual."""
    def rows(frame):
        a, b = (frame[f].to_numpy(dtype=float) for f in FACTORS[2])
        return np.column_stack([np.ones(len(a)), a, b, a * a, a * b, b * b])

    i = int(np.flatnonzero(table["run"].to_numpy() == run)[0])
    x, y = rows(table), table["y"].to_numpy(dtype=float)
    others = np.arange(len(y)) != i
    inv = np.linalg.inv(x[others].T @ x[others])
    beta = inv @ x[others].T @ y[others]
    s = np.sqrt(np.sum((y[others] - x[others] @ beta) ** 2) / (others.sum() - x.shape[1]))
    row = rows(fixed if moved else table)[i]
    return float((y[i] - row @ beta) / (s * np.sqrt(1 + row @ inv @ row)))


@pytest.mark.parametrize("seed", [2, 3])
def test_a_slipped_factor_value_is_moved_and_the_loo_errors_are_the_refits(seed):
    table, planted = off_catalogue_table(seed, 2, "slip", factor="gamma", rows=(3,))
    result = criticize(table, FACTORS[2], "y", n_null=199)
    finding = result.findings[0]
    assert finding.cause == "factor_level" and finding.detail == planted.runs[0]
    recorded = float(table.loc[table["run"] == planted.runs[0], "gamma"].iloc[0])
    assert finding.info["recorded_value"] == pytest.approx(recorded)
    assert finding.info["fitting_value"] == pytest.approx(recorded / 10)
    fixed = table.copy()
    fixed.loc[fixed["run"] == planted.runs[0], "gamma"] = recorded / 10
    assert finding.loo_rmse_baseline == pytest.approx(_loo_rmse(table, FACTORS[2]), rel=1e-9)
    assert finding.loo_rmse_extended == pytest.approx(_loo_rmse(fixed, FACTORS[2]), rel=1e-9)
    assert finding.loo_rmse_extended < finding.loo_rmse_baseline / 3
    # the run's prediction from the other runs, in standard errors, at the recorded and at the moved value
    assert finding.info["t_recorded"] == pytest.approx(_prediction_t(table, fixed, planted.runs[0], False), rel=1e-7)
    assert finding.info["t_moved"] == pytest.approx(_prediction_t(table, fixed, planted.runs[0], True), rel=1e-7)
    # the moved value is not in the table: no lack-of-fit test is reported for the extension, never the baseline's
    assert result.extended["lof_f"] is None and result.extended["lof_p"] is None
    assert result.baseline["lof_f"] is not None
    ratio = _loo_rmse(fixed, FACTORS[2]) / _loo_rmse(table, FACTORS[2])
    assert result.summary == (f"y: 1 finding(s) at a family-wise 5 % level: factor_level ({planted.runs[0]}); "
                              f"together they change the leave-one-out error by {100 * (ratio - 1):+.0f} %.")


@pytest.mark.parametrize("seed", [0, 3])
def test_the_extended_lack_of_fit_test_is_the_classical_one_with_the_named_term(seed):
    # a cubic term planted: named, and the extension's lack-of-fit F is the textbook one of the quadratic plus
    # gamma^3 (actual units span the same polynomials): pure error from the repeated design points
    from scipy import stats

    from ..generators import ccd_table

    table, _ = ccd_table(seed, 2, "term", 6.0)
    result = criticize(table, FACTORS[2], "y", n_null=199)
    assert [(f.cause, f.detail) for f in result.findings] == [("missing_term", "gamma^3")]
    x = table[FACTORS[2]].to_numpy(dtype=float)
    a, b = x[:, 0], x[:, 1]
    design = np.column_stack([np.ones(len(a)), a, b, a * a, a * b, b * b, b ** 3])
    y = table["y"].to_numpy(dtype=float)
    sse = float(np.sum((y - design @ np.linalg.lstsq(design, y, rcond=None)[0]) ** 2))
    points, group = np.unique(np.round(x, 9), axis=0, return_inverse=True)
    group = group.ravel()
    sspe = float(sum(np.sum((y[group == g] - y[group == g].mean()) ** 2) for g in range(len(points))))
    df_lof, df_pe = len(points) - design.shape[1], len(y) - len(points)
    f_lof = ((sse - sspe) / df_lof) / (sspe / df_pe)
    assert result.extended["lof_f"] == pytest.approx(f_lof, rel=1e-6)
    assert result.extended["lof_p"] == pytest.approx(stats.f.sf(f_lof, df_lof, df_pe), rel=1e-6)

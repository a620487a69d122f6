"""Level 1's rounds (criticism.level1._rounds through criticize): a second cause is named when its extension also
predicts left-out runs better.  Two outliers planted in a replicated 3-factor CCD (34 runs) are both named, in
turn, and each finding's leave-one-out RMSE before and after is checked against refits written here (the full
quadratic in the factors' actual units, which the coding does not change; PRESS residuals e_i / (1 - h_ii)) over
the runs both models keep."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from demid.criticism import criticize
from tests.generators import ccd_table


def _quadratic(x):
    k = x.shape[1]
    cols = [np.ones(len(x)), *x.T, *(x[:, i] * x[:, j] for i, j in itertools.combinations_with_replacement(range(k), 2))]
    return np.column_stack(cols)


def _loo(x, y, fitted, scored):
    """Leave-one-out errors of a least-squares fit on the ``fitted`` rows, at the ``scored`` rows."""
    xf = x[fitted]
    h = np.einsum("ij,ji->i", xf, np.linalg.pinv(xf))
    resid = y[fitted] - xf @ np.linalg.lstsq(xf, y[fitted], rcond=None)[0]
    loo = dict(zip(np.flatnonzero(fitted).tolist(), resid / (1 - h)))
    return np.array([loo[i] for i in np.flatnonzero(scored)])


@pytest.mark.parametrize("shifts", [{5: 40.0, 2: -60.0}])
def test_two_outliers_are_named_in_turn_each_predicting_left_out_runs_better(shifts):
    table, _ = ccd_table(0, 3, replicates=2)
    factors = [c for c in table.columns if c not in ("run", "y")]
    y = table["y"].to_numpy(float).copy()
    for row, shift in shifts.items():
        y[row] += shift
    table["y"] = y
    result = criticize(table, factors, "y", n_null=199)
    assert [f.cause for f in result.findings] == ["outlier", "outlier"]
    runs = table["run"].to_numpy()
    rows = [int(np.flatnonzero(runs == f.detail)[0]) for f in result.findings]
    assert sorted(rows) == sorted(shifts)
    assert rows[0] == max(shifts, key=lambda r: abs(shifts[r]))  # the larger shift first
    x = _quadratic(table[factors].to_numpy(float))
    kept = np.ones(len(y), dtype=bool)
    for finding, row in zip(result.findings, rows):
        after = kept.copy()
        after[row] = False
        before_err, after_err = _loo(x, y, kept, after), _loo(x, y, after, after)
        assert finding.compared_runs == int(after.sum())
        assert finding.loo_rmse_baseline == pytest.approx(float(np.sqrt(np.mean(before_err ** 2))), rel=1e-9)
        assert finding.loo_rmse_extended == pytest.approx(float(np.sqrt(np.mean(after_err ** 2))), rel=1e-9)
        assert finding.loo_rmse_extended < finding.loo_rmse_baseline
        kept = after

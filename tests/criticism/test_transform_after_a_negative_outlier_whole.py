"""A response transform is tested only where it is defined at every run, the runs already named outliers too:
a transformed model's likelihood, which the AICc and the naming of causes compare, counts each excluded run's
Box-Cox Jacobian (log y).  A 3x3 factorial with five centre runs and three outliers, the second 200 below the
surface (a negative response): once it is dropped the other runs are all positive, and a later round must not
test (or fit) a transform of the table.  The criticism then runs without a warning, and every finding's AICc
change is finite and is the refit's (Gaussian least squares with one mean shift per outlier named)."""
from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest

from demid.criticism import criticize


def _table() -> pd.DataFrame:
    levels = np.array([-1.0, 0.0, 1.0])
    a, b = (g.ravel() for g in np.meshgrid(levels, levels))
    a, b = np.append(a, np.zeros(5)), np.append(b, np.zeros(5))
    y = 10 + 2 * a - b + 0.5 * a * b + a * a + 0.05 * np.random.default_rng(0).standard_normal(len(a))
    y[[1, 6, 3]] += [1000.0, -200.0, 50.0]
    return pd.DataFrame({"run": np.arange(1, len(a) + 1), "a": a + 2, "b": b + 2, "y": y})


def _aicc(y, x, dropped):
    kept = ~np.isin(np.arange(len(y)), dropped)
    resid = y[kept] - x[kept] @ np.linalg.lstsq(x[kept], y[kept], rcond=None)[0]
    n, k = len(y), x.shape[1] + 1 + len(dropped)
    llf = -0.5 * n * (np.log(2 * np.pi * float(resid @ resid) / n) + 1.0)
    return -2 * llf + 2 * k + 2 * k * (k + 1) / (n - k - 1)


def test_no_transform_is_tested_once_a_negative_run_is_dropped():
    table = _table()
    result = criticize(table, ["a", "b"], "y", n_null=99)
    assert len(result.findings) == 3  # a third round is made (three findings at most, by default)
    assert [f.cause for f in result.findings][:2] == ["outlier", "outlier"]
    assert [f.detail for f in result.findings][:2] == [2, 7]
    assert "response_transform" not in [f.cause for f in result.findings]
    assert all(math.isfinite(f.delta_aicc) for f in result.findings)
    a, b, y = (table[c].to_numpy(float) for c in ("a", "b", "y"))
    x = np.column_stack([np.ones_like(a), a, b, a * b, a * a, b * b])
    second = result.findings[1]
    assert second.delta_aicc == pytest.approx(_aicc(y, x, [1, 6]) - _aicc(y, x, [1]), rel=1e-9)

"""The catalogue is tested from exactly 3 residual degrees of freedom on (each added-variable test then keeps 2),
and below that level 1 says so with the run and coefficient counts: 2-3 factors, the quadratic's p coefficients,
p + 2 runs (nothing tested, the sentence's numbers parsed back) and p + 3 runs (a catalogue)."""
from __future__ import annotations

import re

import numpy as np
import pandas as pd
import pytest

from demid.criticism import criticize


def _table(k: int, n: int, seed: int) -> pd.DataFrame:
    rng = np.random.default_rng(seed)
    x = rng.uniform(-1.0, 1.0, (n, k))
    x[:2] = [[-1.0] * k, [1.0] * k]  # the coding's extremes
    y = 5 + x @ rng.normal(size=k) + 0.5 * (x ** 2).sum(axis=1) + 0.3 * rng.standard_normal(n)
    return pd.DataFrame({"run": np.arange(1, n + 1), **{f"f{j}": x[:, j] for j in range(k)}, "y": y})


@pytest.mark.parametrize("k, spare", [(2, 2), (2, 3), (3, 2), (3, 3)])
def test_the_catalogue_starts_at_three_spare_runs(k, spare):
    p = (k + 1) * (k + 2) // 2
    table = _table(k, p + spare, 10 * k + spare)
    result = criticize(table, [f"f{j}" for j in range(k)], "y", n_null=99)
    assert result._baseline_model.df_resid == spare
    if spare < 3:
        assert result.catalogue == [] and result.findings == []
        said = re.fullmatch(r"y: nothing could be tested: (\d+) runs leave too few spare runs beyond the (\d+) "
                            r"quadratic coefficients\.", result.summary)
        assert said and (int(said.group(1)), int(said.group(2))) == (p + spare, p)
    else:
        causes = {c["cause"] for c in result.catalogue}
        assert "outlier" in causes  # (a cubic term may not be estimable from so few runs)
        assert "nothing could be tested" not in result.summary

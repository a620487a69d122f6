"""Level 1's rounds stop when too few spare runs are left for a further round's tests: after a finding, another
round is made while the extended model keeps at least 4 residual degrees of freedom (each added-variable test of
the next round then has at least 3), and not at 3.  Two outliers planted in a 3x3 factorial with 2 or 1 centre
replicates (11 or 10 runs, the quadratic's 6 terms): after the first outlier the model keeps exactly 4 or 3."""
from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from demid.criticism import criticize


def _two_outliers(centre_runs: int) -> pd.DataFrame:
    levels = np.array([-1.0, 0.0, 1.0])
    a, b = (g.ravel() for g in np.meshgrid(levels, levels))
    a, b = np.append(a, np.zeros(centre_runs)), np.append(b, np.zeros(centre_runs))
    y = 10 + 2 * a - b + 0.5 * a * b + a * a + 0.05 * np.random.default_rng(0).standard_normal(len(a))
    y[1] += 1000.0  # the larger outlier, named first
    y[6] -= 15.0
    return pd.DataFrame({"run": np.arange(1, len(a) + 1), "a": a + 2, "b": b + 2, "y": y})


@pytest.mark.parametrize("centre_runs, named_runs", [(2, [2, 7]), (1, [2])])
def test_a_second_round_is_made_at_exactly_four_spare_degrees_of_freedom_not_three(centre_runs, named_runs):
    table = _two_outliers(centre_runs)
    result = criticize(table, ["a", "b"], "y", n_null=199)
    assert [f.cause for f in result.findings] == ["outlier"] * len(named_runs)
    assert [f.detail for f in result.findings] == named_runs
    # spare degrees of freedom: runs - 6 quadratic terms - one per outlier named
    assert result._extended_model.df_resid == len(table) - 6 - len(named_runs)

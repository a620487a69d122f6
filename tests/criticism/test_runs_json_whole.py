"""The runs level 1 writes to its JSON (CriticismResult.to_json()["runs"], through dumps): per run its label as
in the table (an int for a whole number), then observed, fitted, residual, leave-one-out residual, externally
studentised residual and leverage as JSON numbers (floats, whole-number values included; null where undefined),
against statsmodels' OLS of the full quadratic.  Responses printed to 0-2 decimals, 2-3 factors."""
from __future__ import annotations

import itertools
import json

import numpy as np
import pandas as pd
import pytest
import statsmodels.api as sm

from demid.criticism import criticize


@pytest.mark.parametrize("k, decimals", [(2, 0), (3, 2)])
def test_the_runs_json_is_the_ols_influence_of_the_quadratic(k, decimals):
    rng = np.random.default_rng(k)
    x = np.array(list(itertools.product([-1.0, 0.0, 1.0], repeat=k)))
    y = np.round(20 + 3 * x @ rng.uniform(1, 2, k) + (x ** 2).sum(axis=1) + rng.normal(size=len(x)), decimals)
    runs = rng.permutation(len(x)) + 1
    table = pd.DataFrame({"run": runs, **{f"f{j}": x[:, j] for j in range(k)}, "y": y})
    result = criticize(table, [f"f{j}" for j in range(k)], "y", n_null=19)
    rows = json.loads(result.dumps())["runs"]
    pairs = itertools.combinations_with_replacement(range(k), 2)
    cols = [np.ones(len(x)), *x.T, *(x[:, i] * x[:, j] for i, j in pairs)]
    ols = sm.OLS(y, np.column_stack(cols)).fit()
    infl = ols.get_influence()
    h = infl.hat_matrix_diag
    assert [r["run"] for r in rows] == runs.tolist()
    assert all(type(r["run"]) is int for r in rows)
    assert all(type(r[c]) is float for r in rows for c in ("observed", "fitted", "residual", "leverage"))
    for name, want in (("observed", y), ("fitted", ols.fittedvalues), ("residual", ols.resid),
                       ("loo_residual", ols.resid / (1 - h)), ("student_resid", infl.resid_studentized_external),
                       ("leverage", h)):
        np.testing.assert_allclose([r[name] for r in rows], want, rtol=1e-9, atol=1e-9, err_msg=name)
    assert list(rows[0]) == ["run", "observed", "fitted", "residual", "loo_residual", "student_resid", "leverage"]

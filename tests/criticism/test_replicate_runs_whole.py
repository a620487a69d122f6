"""The replicates level 1 proposes at runs already made (criticism.verdict.replicate_runs), every field against the
table and statsmodels: a simulated table's outlier gets two replicates at its own factor values (to ten significant
digits), to confirm; an unexplained misfit gets one replicate of each of the two runs of largest |externally
studentised residual| of the quadratic fit (statsmodels' influence, ties to the earlier row), to decide; a typed
table's outlier, or a named cause other than an outlier, gets none.  2-3 factor CCDs, factors on ranges of any
sign and scale, run labels in any order; runs tied exactly (a counted response of few values) in the table's row
order."""

from __future__ import annotations

from dataclasses import replace
from types import SimpleNamespace

import numpy as np
import pandas as pd
import pytest
import statsmodels.api as sm
from hypothesis import given, settings
from hypothesis import strategies as st

from demid import run_purposes
from demid.criticism.level1 import prepare_data
from demid.criticism.verdict import OUTLIER_REPLICATES, UNEXPLAINED_REPLICATED_RUNS, replicate_runs
from demid.design import model_matrix, quadratic_terms, rotatable_alpha
from tests.generators import FACTORS, ccd_table, design


def _table(seed: int, k: int, offset: float, scale: float):
    table, _ = ccd_table(seed, k, "outlier", size=6.0)
    for f in FACTORS[k]:
        table[f] = offset + scale * table[f]
    table["run"] = 100 + 7 * table["run"]
    return table


@given(seed=st.integers(0, 500), k=st.integers(2, 3), offset=st.sampled_from([-40.0, 0.0, 3.5]),
       scale=st.sampled_from([0.001, 1.0, 250.0]), pick=st.integers(0, 100))
@settings(max_examples=10, deadline=None, derandomize=True)
def test_replicates_of_an_outlier_and_of_the_worst_runs_of_an_unexplained_misfit(seed, k, offset, scale, pick):
    table = _table(seed, k, offset, scale)
    factors = FACTORS[k]
    data, fit = prepare_data(table, factors, "y", None, ())
    row = pick % len(table)
    label = int(table["run"][row])
    outlier = [SimpleNamespace(cause="outlier", detail=label)]
    simulated = replace(data, simulated=True)
    runs = replicate_runs(simulated, fit, outlier, None)
    point = {f: float(f"{table[f][row]:.10g}") for f in factors}
    assert runs == [{**point, "purpose": run_purposes.CONFIRM, "replicate_of": label}] * OUTLIER_REPLICATES
    # a later finding (another outlier, a term) does not move them: they serve the first cause named
    later = int(table["run"][(row + 1) % len(table)])
    for then in (SimpleNamespace(cause="outlier", detail=later), SimpleNamespace(cause="drift", detail="run")):
        assert replicate_runs(simulated, fit, outlier + [then], None) == runs
    assert replicate_runs(data, fit, outlier, None) == []  # a typed table: its outlier may be a slip
    assert replicate_runs(simulated, fit, [SimpleNamespace(cause="drift", detail="run")], None) == []
    # an unexplained misfit: the runs of largest |externally studentised residual| of the quadratic
    x = model_matrix(data.coding.to_coded(table[factors].to_numpy()), quadratic_terms(k))
    student = sm.OLS(table["y"].to_numpy(), x).fit().get_influence().resid_studentized_external
    worst = sorted(range(len(table)), key=lambda i: (-round(abs(student[i]), 9), i))[:UNEXPLAINED_REPLICATED_RUNS]
    runs = replicate_runs(data, fit, [], {"message": "misfit"})
    assert runs == [{**{f: float(f"{table[f][i]:.10g}") for f in factors}, "purpose": run_purposes.DECIDE,
                     "replicate_of": int(table["run"][i])} for i in worst]



@pytest.mark.parametrize("k, alpha", [(2, 1.0), (2, 2.0), (3, 1.0), (3, rotatable_alpha(3))])
def test_runs_tied_in_misfit_are_proposed_in_the_tables_order(k, alpha):
    """A counted response of few values (0, 1, 2) leaves runs tied exactly in |externally studentised residual|
    (runs at one point with one value, as a deterministic simulator's repeated centre runs): the runs proposed are
    those first in the level-1 residual table (fit.influence, its studentised residuals against statsmodels) by
    |residual|, ties to the earlier row of the table whatever the run labels, so that the proposal does not
    depend on the sorting algorithm.  Rows in random order, labels scattered; several tables per design."""
    rng = np.random.default_rng(round(100 * alpha) + k)
    factors, coding, coded, _ = design(k, alpha=alpha)
    x_all = model_matrix(coded, quadratic_terms(k))
    for _ in range(7):
        order = rng.permutation(len(coded))
        table = pd.DataFrame(coding.to_actual(coded[order]), columns=factors)
        table.insert(0, "run", rng.choice(np.arange(1, 5 * len(coded)), len(coded), replace=False))
        table["y"] = rng.integers(0, 3, len(coded)).astype(float)
        data, fit = prepare_data(table, factors, "y", None, ())
        frame = fit.influence()
        student = sm.OLS(table["y"].to_numpy(), x_all[order]).fit().get_influence().resid_studentized_external
        np.testing.assert_allclose(frame["student_resid"], student, rtol=1e-7, atol=1e-9)
        assert frame["run"].tolist() == table["run"].tolist()
        size = np.abs(frame["student_resid"].to_numpy())
        worst = sorted(range(len(table)), key=lambda i: (-size[i], i))[:UNEXPLAINED_REPLICATED_RUNS]
        runs = replicate_runs(data, fit, [], {"message": "misfit"})
        assert [r["replicate_of"] for r in runs] == [int(table["run"][i]) for i in worst]
        assert all(r["purpose"] == run_purposes.DECIDE for r in runs)

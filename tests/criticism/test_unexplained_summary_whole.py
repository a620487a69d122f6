"""The summary of a response whose misfit no catalogue cause explains (criticism.level1.criticize): it is the
unexplained evidence's own message, naming the tests that fired and their family-wise p-values (parsed back against
the evidence), not the summary of a named cause; and the runs it proposes: one replicate of each of the two runs
whose externally studentised residuals (statsmodels) are largest, which its message names."""

from __future__ import annotations

import re

import numpy as np
import pytest
import statsmodels.api as sm

from demid.criticism import criticize
from demid.design import model_matrix, quadratic_terms
from tests.generators import FACTORS, off_catalogue_table


def test_an_unexplained_misfits_summary_is_its_evidence_message():
    table, _ = off_catalogue_table(0, 2, "batch", size=6.0)
    result = criticize(table, FACTORS[2], "y", n_null=199)
    assert result.verdict == "unexplained" and result.unexplained and result.run_order.drift_tested
    assert result.summary == result.unexplained["message"]
    assert result.summary.startswith("y: the runs show misfit that no catalogued cause accounts for.")
    quoted = [float(p) for p in re.findall(r"family-wise p = ([0-9.e+-]+)\)", result.summary)]
    fired = [e["p_family"] for e in result.unexplained["tests"] + result.unexplained["remaining"]]
    assert quoted and quoted == [float(f"{p:.3g}") for p in fired]


def test_an_unexplained_misfit_proposes_one_replicate_of_each_of_the_two_runs_that_misfit_most():
    table, _ = off_catalogue_table(0, 2, "batch", size=6.0)
    result = criticize(table, FACTORS[2], "y", n_null=199)
    assert result.verdict == "unexplained"
    x = table[FACTORS[2]].to_numpy(dtype=float)
    lo, hi = x.min(axis=0), x.max(axis=0)
    ols = sm.OLS(table["y"].to_numpy(), model_matrix((x - (lo + hi) / 2) / (hi - lo), quadratic_terms(2))).fit()
    worst = np.argsort(-np.abs(ols.get_influence().resid_studentized_external), kind="stable")[:2]
    runs = result.discriminating_runs
    assert [r["replicate_of"] for r in runs] == [int(table["run"].iloc[i]) for i in worst]
    for r, i in zip(runs, worst):
        assert [r[f] for f in FACTORS[2]] == pytest.approx(list(x[i]), rel=1e-9)
    which = ", ".join(f"run {r['replicate_of']}" for r in runs)
    assert f"Replicates of the runs that misfit most ({which})" in result.verdict_message
    assert result.runs_for_next_wave

"""Runs demid made itself: a simulated run off the surface is scatter or a simulator failure, never a typing
or export slip, and is replicated; a misfit no cause explains proposes replicates of the runs that misfit most,
so that the next wave can name the cause."""

from __future__ import annotations

import json

import numpy as np
import pandas as pd
import pytest

from demid import run_purposes
from demid.criticism import criticize
from demid.criticism.verdict import OUTLIER_REPLICATES, UNEXPLAINED_REPLICATED_RUNS
from demid.design import Coding, ccd_points, rotatable_alpha
from demid.wave_runs import deciding_runs
from demid.surrogate import fit_response

from ..generators import FACTORS, ccd_table


def _named_outlier(seed):
    table, planted = ccd_table(seed, 2, "outlier", 15)
    result = criticize(table, FACTORS[2], "y", n_null=999, simulated=True)
    named = result.findings and result.findings[0].cause == "outlier" and result.findings[0].detail == planted.run
    return table, planted, result, named


def test_a_simulated_outlier_is_scatter_or_a_failure_and_is_replicated():
    checked = 0
    for seed in range(4):
        table, planted, result, named = _named_outlier(seed)
        if not named:
            continue
        checked += 1
        message = result.verdict_message
        assert "a transcription or export error is the usual cause" not in message
        assert "demid simulated that run itself" in message and "seed-to-seed scatter" in message
        # replicates at the run's own point, as many as stated, read by the next wave as confirming runs
        point = table.loc[table["run"] == planted.run, FACTORS[2]].iloc[0].to_dict()
        assert len(result.discriminating_runs) == OUTLIER_REPLICATES
        for run in result.discriminating_runs:
            assert {f: run[f] for f in FACTORS[2]} == pytest.approx(point, rel=1e-9)
            assert run["purpose"] == run_purposes.CONFIRM and run["replicate_of"] == planted.run
        assert f"{OUTLIER_REPLICATES} replicate(s) of run {planted.run}" in message
        proposed = deciding_runs(result.to_frame(), FACTORS[2])
        assert len(proposed) == OUTLIER_REPLICATES and {p["purpose"] for p in proposed} == {run_purposes.CONFIRM}
        # a hand-made table keeps the transcription reading
        hand = criticize(table, FACTORS[2], "y", n_null=999)
        assert "a transcription or export error is the usual cause" in hand.findings[0].message
        assert not any("replicate_of" in r for r in hand.discriminating_runs)
    assert checked >= 2


def test_an_unexplained_misfit_proposes_replicates_of_the_runs_that_misfit_most():
    """The regime change of test_honest_causes (three runs with a > 0.5 moved by +-20): a misfit no cause
    explains, it now proposes one replicate of each of the runs of largest |studentised residual|."""
    alpha = rotatable_alpha(2)
    coded = ccd_points(2, alpha, 5)
    moved = coded[:, 0] > 0.5
    seen = 0
    for seed in (3, 4, 5, 6, 7):
        rng = np.random.default_rng(seed)
        step = np.where(moved, 20.0, 0.0) * np.where(coded[:, 1] > -0.5, 1.0, -1.0)
        y = 100 + 5 * coded[:, 0] - 3 * coded[:, 1] + step + rng.normal(size=len(coded))
        coding = Coding(("a", "b"), (0.0, 0.0), (1.0, 1.0))
        table = pd.DataFrame(coding.to_actual(coded), columns=["a", "b"])
        table.insert(0, "run", rng.permutation(len(coded)) + 1)
        table["y"] = y
        for simulated in (False, True):
            result = criticize(table, ["a", "b"], "y", n_null=999, simulated=simulated)
            if not result.unexplained or result.findings or result.candidates:
                continue  # (its Q² may be below 0: "does not predict" then carries the unexplained misfit)
            seen += 1
            influence = fit_response(table, ["a", "b"], "y").influence()
            worst = influence.loc[influence["student_resid"].abs().sort_values(ascending=False).index, "run"]
            expected = [int(r) for r in worst.head(UNEXPLAINED_REPLICATED_RUNS)]
            runs = result.discriminating_runs
            assert [r["replicate_of"] for r in runs] == expected
            for run in runs:
                row = table.loc[table["run"] == run["replicate_of"]].iloc[0]
                assert (run["a"], run["b"]) == pytest.approx((row["a"], row["b"]), rel=1e-9)
                assert run["purpose"] == run_purposes.DECIDE
            assert result.runs_for_next_wave
            assert "Replicates of the runs that misfit most" in result.verdict_message
            frame = result.to_frame()
            row = frame[frame["cause"] == "unexplained"].iloc[0]
            assert [r["replicate_of"] for r in json.loads(row["discriminating_runs"])] == expected
            assert len(deciding_runs(frame, ["a", "b"])) == UNEXPLAINED_REPLICATED_RUNS
    assert seen >= 2

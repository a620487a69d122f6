"""Level 1's table (CriticismResult.to_frame): one row per finding with the finding's numbers, or one unexplained
row whose leave-one-out RMSE is the baseline's (PRESS of the quadratic, numpy) before and after and whose change in
AICc is 0; the runs a next wave makes on the row they serve (the first finding's, else the last row), as the JSON of
the result's discriminating runs.  Two outliers planted in 11 runs, named (2 findings) or left unexplained; one
ambiguous row where the runs cannot tell the readings of one run apart."""
from __future__ import annotations

import json

import numpy as np
import pandas as pd
import pytest

from demid.criticism import criticize
from tests.criticism.test_level1_spare_runs_whole import _fit, _quadratic, _two_outliers

COLUMNS = ["response", "cause", "detail", "aliases", "p_value", "loo_rmse_baseline", "loo_rmse_extended",
           "delta_aicc", "message", "verdict"]


@pytest.mark.parametrize("max_findings", [1, 2])
def test_the_frame_is_the_findings_or_the_unexplained_row(max_findings):
    table = _two_outliers(2)
    result = criticize(table, ["a", "b"], "y", n_null=199, max_findings=max_findings)
    frame = result.to_frame()
    extra = ["discriminating_runs"] if result.runs_for_next_wave else []
    assert list(frame.columns) == COLUMNS + extra
    assert (frame["response"] == "y").all() and (frame["verdict"] == result.verdict).all()
    if result.findings:
        assert len(frame) == len(result.findings) == 2 and not result.unexplained
        for (_, row), f in zip(frame.iterrows(), result.findings):
            assert (row["cause"], row["detail"], row["aliases"]) == (f.cause, str(f.detail), ";".join(f.aliases))
            assert (row["p_value"], row["loo_rmse_baseline"], row["loo_rmse_extended"], row["delta_aicc"]) == \
                (f.p_value, f.loo_rmse_baseline, f.loo_rmse_extended, f.delta_aicc)
            assert row["message"] == f.message
    else:
        u = result.unexplained
        assert len(frame) == 1 and u
        row = frame.iloc[0]
        a, b, y = (table[c].to_numpy(float) for c in ("a", "b", "y"))
        _, press = _fit(_quadratic(a, b), y)
        loo = float(np.sqrt(np.nanmean(press ** 2)))
        assert (row["cause"], row["detail"], row["aliases"], row["message"]) == \
            ("unexplained", u["detail"], "", u["message"])
        assert row["p_value"] == u["p_value"] and row["delta_aicc"] == 0.0
        assert row["loo_rmse_baseline"] == pytest.approx(loo, rel=1e-9)
        assert row["loo_rmse_extended"] == pytest.approx(loo, rel=1e-9)
    if extra:
        served = 0 if result.findings else len(frame) - 1
        assert json.loads(frame["discriminating_runs"].iloc[served]) == result.discriminating_runs
        others = frame["discriminating_runs"].drop(frame.index[served])
        assert others.isna().all()


def test_an_ambiguous_result_is_one_row_naming_its_candidates():
    """A 3x3 factorial with one centre replicate and its centre run 30 standard deviations off: the runs do not tell
    its readings apart, so the table has one ambiguous row listing the candidates, the baseline's leave-one-out RMSE
    before and after and no change in AICc."""
    rng = np.random.default_rng(0)
    points = [(a, b) for a in (-1.0, 0.0, 1.0) for b in (-1.0, 0.0, 1.0)] + [(0.0, 0.0)]
    a, b = np.array(points).T
    y = 5 + a - 2 * b + 0.5 * a * b + rng.normal(scale=0.1, size=len(a))
    y[4] += 3.0
    table = pd.DataFrame({"run": rng.permutation(len(a)) + 1, "a": a, "b": b, "y": y})
    result = criticize(table, ["a", "b"], "y", n_null=99)
    assert result.verdict == "ambiguous" and len(result.candidates) > 1 and not result.findings
    frame = result.to_frame()
    assert len(frame) == 1
    row = frame.iloc[0]
    assert (row["cause"], row["verdict"], row["message"]) == ("ambiguous", "ambiguous", result.verdict_message)
    assert row["detail"] == ";".join(f"{c['cause']} ({c['detail']})" for c in result.candidates)
    _, press = _fit(_quadratic(a, b), y)
    loo = float(np.sqrt(np.nanmean(press ** 2)))
    assert row["loo_rmse_baseline"] == pytest.approx(loo, rel=1e-9)
    assert row["loo_rmse_extended"] == pytest.approx(loo, rel=1e-9)
    assert row["delta_aicc"] == 0.0 and row["p_value"] is None

"""The typo screen's window (demid.transcription.likely_typos): a repair of a run's printed cell fits when it lands
within three leave-one-out standard errors of the other runs' prediction, three exactly included.  The screen's
residuals are set here to binary-exact numbers (leverage 0.75, residual 9.75, studentised residual 19.5 at the
run printed 61.0: prediction 61 - 9.75 / 0.25 = 22, scale 0.5 / 0.5 = 1, prediction error sqrt(1 + 3) = 2), so
the swapped digits' 16.0 lies exactly 6 = 3 x 2 from the prediction, and a hair beyond when the error is a
hair smaller."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

import demid.transcription.typos as typos
from demid.data import validate_material
from demid.spec import MaterialSpec


def _validated(tmp_path, printed: float = 61.0):
    """A plane over a 3 x 3 grid with run 5 printed as ``printed`` (by default 61.0 where 16.0 was meant)."""
    points = np.array([(a, b) for a in (0.1, 0.5, 0.9) for b in (1.0, 6.0, 11.0)])
    y = np.round(30 + 10 * points[:, 0] + points[:, 1], 2)
    y[4] = printed
    table = pd.DataFrame({"run": np.arange(1, 10), "x1": points[:, 0], "x2": points[:, 1], "y": y})
    path = tmp_path / "t.csv"
    table.to_csv(path, index=False)
    spec = MaterialSpec.from_material("m", {
        "data": str(path), "design": {"type": "custom"},
        "factors": {"x1": {"lower": 0.1, "upper": 0.9}, "x2": {"lower": 1, "upper": 11}}, "responses": {"y": {}}})
    return validate_material(spec), spec


def _screen(student_at_run_5):
    def screen(coded, observed, terms, df):
        assert observed[4] == 61.0 and df == 2  # nine runs, six coefficients
        leverage, residual, student = np.full(9, 0.5), np.full(9, 0.1), np.full(9, 0.2)
        leverage[4], residual[4], student[4] = 0.75, 9.75, student_at_run_5
        return {"leverage": leverage, "residual": residual, "student_resid": student}
    return screen


@pytest.mark.parametrize("student, flagged", [(19.5, True), (19.5 * (1 - 1e-9), True), (19.5 * (1 + 1e-9), False)],
                         ids=["exactly three errors", "within", "a hair beyond"])
def test_a_repair_exactly_three_prediction_errors_off_fits(tmp_path, monkeypatch, student, flagged):
    validated, spec = _validated(tmp_path)
    monkeypatch.setattr(typos, "_screen_residuals", _screen(student))
    flags = typos.likely_typos(validated, spec)
    if not flagged:
        assert flags == []
        return
    assert [(f["run"], f["column"], f["found"], f["suggested"], f["kind"]) for f in flags] == [
        (5, "y", 61.0, 16.0, "transposition")]
    flag = flags[0]
    assert flag["predicted_from_other_runs"] == 22.0
    if student == 19.5:
        assert flag["prediction_se"] == 2.0 and abs(16.0 - 22.0) == 3 * 2.0

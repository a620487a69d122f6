"""The typo screen's other repairs (demid.transcription.likely_typos): beside the repair it names (the commonest slip
that lands within three prediction errors of the other runs' prediction), it lists the repairs more than two
errors from the named one that either fit better by more than one error or are of a slip at least as common.
Run 5 prints 6.1 where the other runs predict 63.5 with an error of 1 (the screen's residuals are set here): the
point shifted gives 61 (2.5 off), the named repair; a digit dropped gives 60.1 to 69.1 and 66.1, of which 63.1
and 64.1 fit better by more than one error and lie more than two from 61; 65.1 and 66.1 fit, but neither better
by more than an error nor by a slip as common; 61.1 and 62.1 lie within two errors of 61."""

from __future__ import annotations

import numpy as np
import pytest

import demid.transcription.typos as typos
from tests.transcription.test_likely_typos_three_se_whole import _validated


def _screen(coded, observed, terms, df):
    """Leverage 0.75 at run 5: the residual -14.35 puts the prediction from the other runs at 6.1 + 14.35 / 0.25
    = 63.5, and a studentised residual of -57.4 its error at (0.25 / 0.5) * sqrt(1 + 3) = 1."""
    leverage, residual, student = np.full(9, 0.5), np.full(9, 0.1), np.full(9, 0.2)
    leverage[4], residual[4], student[4] = 0.75, -14.35, -57.4
    return {"leverage": leverage, "residual": residual, "student_resid": student}


def test_the_other_repairs_are_those_fitting_better_by_an_error_or_of_as_common_a_slip(tmp_path, monkeypatch):
    validated, spec = _validated(tmp_path, 6.1)
    monkeypatch.setattr(typos, "_screen_residuals", _screen)
    (flag,) = typos.likely_typos(validated, spec)
    assert (flag["run"], flag["column"], flag["found"], flag["suggested"], flag["kind"]) == (
        5, "y", 6.1, 61.0, "decimal_shift")
    assert flag["predicted_from_other_runs"] == pytest.approx(63.5, rel=1e-12)
    assert flag["prediction_se"] == pytest.approx(1.0, rel=1e-12)
    assert [(r["value"], r["kind"]) for r in flag["other_repairs"]] == [(63.1, "digit_dropped"),
                                                                        (64.1, "digit_dropped")]

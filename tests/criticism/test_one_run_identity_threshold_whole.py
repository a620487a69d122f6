"""A missing term's test without each run from the one fit (criticism.one_run.deleted_logp_by_identity) at the edge
of estimability agrees with the refit per run (deleted_logp) and with statsmodels: the term is tested without a
run only when its part beyond the model fitted to the other runs is more than 1e-7 of the whole term column's
norm.  The setup of test_one_run_estimability_whole (a 3x3 factorial, a run far out on a, one at a = 1 + delta) with
the remainder without the far run placed between 1e-7 times the column's norm without that run and with it (where
a threshold on the column without the run would test the term), below both, and well above; two scales."""

from __future__ import annotations

import numpy as np
import pytest

from demid.criticism.one_run import deleted_logp, deleted_logp_by_identity
from demid.design import model_matrix
from tests.criticism.test_one_run_estimability_whole import _CUBE, _expected, _remainder, _setup

_FAR = 9


@pytest.mark.parametrize("scale", [1.0, 1.5])
@pytest.mark.parametrize("where", ["between the norms", "below both", "well above"])
def test_the_identity_tests_a_term_without_a_run_exactly_when_the_refit_does(scale, where):
    model, _, _ = _setup(1e-7, scale)
    column = model_matrix(model.coded, [_CUBE])[:, 0]
    per_delta = _remainder(model.x, column, np.arange(len(column)) != _FAR) / 1e-7  # the remainder is ~ delta
    norm = np.linalg.norm(column)
    without = np.sqrt(norm ** 2 - column[_FAR] ** 2)
    aim = {"between the norms": 0.5 * (without + norm), "below both": 0.5 * (1.0 + without),
           "well above": 1e4 * norm}[where]
    model, h, y = _setup(1e-7 * aim / per_delta, scale)
    column = model_matrix(model.coded, [_CUBE])[:, 0]
    remainder = _remainder(model.x, column, np.arange(len(y)) != _FAR)
    if where == "between the norms":
        assert 1e-7 * np.sqrt(norm ** 2 - column[_FAR] ** 2) * 1.05 < remainder < 1e-7 * norm / 1.05
    got = deleted_logp_by_identity(None, model, h, y)
    assert (got[_FAR] == 0.0).all() == (where != "well above")
    np.testing.assert_allclose(got, deleted_logp(None, model, h, y), rtol=1e-6, atol=1e-9)
    np.testing.assert_allclose(got, _expected(model, y, column, _FAR), rtol=1e-6, atol=1e-9)

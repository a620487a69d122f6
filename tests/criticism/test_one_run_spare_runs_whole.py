"""The run a whole-design cause rests on (criticism.one_run) at the edge of testability: a two-factor quadratic
(six terms) on 8 to 12 runs, so that a run left out leaves 1 to 5 residual degrees of freedom.  The documented
rule is that a test needs at least 3 (with 2 or fewer its p is 1, log p 0); exactly 3 is tested.  Each run's
deleted test is checked against refits written in the test, and the deletions from the one fit (the
leave-one-out identities) against the refits, at every one of these sizes."""

from __future__ import annotations

import numpy as np
import pytest

from demid.criticism.aliasing import TermClass
from demid.criticism.catalogue import Hypothesis
from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm
from demid.criticism.one_run import deleted_logp, deleted_logp_by_identity
from tests.criticism.test_one_run_whole import _refit_logp, _table


def _case(cause: str, spare: int, seed: int):
    n = 6 + spare
    table = _table(n, 2, seed, 1.0, 0.6)
    data, _ = prepare_data(table, ["f0", "f1"], "y", 1.0, (), None)
    model = Model(data, ModelForm())
    if cause == "missing_term":
        return data, model, Hypothesis(cause, TermClass([(3, 0)], None)), model.coded[:, 0] ** 3
    if cause == "drift":
        return data, model, Hypothesis(cause, "run"), data.runs.astype(float)
    return data, model, Hypothesis(cause, None), None


@pytest.mark.parametrize("cause", ["missing_term", "drift", "response_transform"])
@pytest.mark.parametrize("spare", [2, 3, 4, 5, 6])
def test_deleted_tests_need_three_residual_degrees_of_freedom_and_three_suffice(cause, spare):
    data, model, h, column = _case(cause, spare, seed=spare)
    want = _refit_logp(model, cause, column)
    got = deleted_logp(data, model, h, model.z[:, None])[:, 0]
    residual_df = spare - 1  # runs left minus the six terms
    if residual_df < 3:
        assert np.all(got == 0.0)
    else:
        assert np.mean(got < 0.0) > 0.5  # tests were run (a Box-Cox LR may be 0: lambda-hat 1)
    np.testing.assert_allclose(got, want, rtol=1e-6, atol=1e-9)
    by_identity = deleted_logp_by_identity(data, model, h, model.z[:, None])[:, 0]
    np.testing.assert_allclose(by_identity, want, rtol=1e-6, atol=1e-9)

"""The verdict's naming rules (criticism.verdict) exactly at their thresholds: a cause whose nominal p is exactly
OVERWHELMING_P (1e-4) is singled out whatever test of another kind is stronger, one a hair less significant is not
(the strongest rival of another kind is returned, whatever the order of the hypotheses); unequal scatter rests on
one run only when its test without that run gives p above ONE_RUN_P (0.05): exactly 0.05 is still significant."""

from __future__ import annotations

import math

import numpy as np
import pytest

from demid.criticism import verdict
from demid.criticism.catalogue import Hypothesis
from demid.criticism.one_run import Deletion
from demid.criticism.verdict import ONE_RUN_P, OVERWHELMING_P, rests_on_one_run, strongest_rival


@pytest.mark.parametrize("named_cause,detail", [("missing_term", "a^3"), ("outlier", 4), ("drift", "run"),
                                                ("heteroscedasticity", "a")])
@pytest.mark.parametrize("reverse", [False, True])
def test_a_cause_at_exactly_the_overwhelming_p_is_singled_out_and_a_hair_above_it_is_not(named_cause, detail,
                                                                                       reverse):
    at = math.log(OVERWHELMING_P)
    above = float(np.nextafter(at, 0.0))
    rivals = [Hypothesis("lack_of_fit", None, logp=at - 3.0), Hypothesis("response_transform", None, logp=at - 1.0),
              Hypothesis("step", 7, logp=at - 5.0 if named_cause != "drift" else at + 1.0)]  # drift: same kind, weaker
    for own, singled_out in ((at, True), (above, False)):
        named = Hypothesis(named_cause, detail, logp=own)
        hypotheses = [named, *rivals]
        if reverse:
            hypotheses = hypotheses[::-1]
        rival = strongest_rival(named, hypotheses)
        if singled_out:
            assert rival is None
        else:
            other_kind = [g for g in rivals if not (named_cause == "drift" and g.cause == "step")]
            assert rival is min(other_kind, key=lambda g: g.logp)


@pytest.mark.parametrize("p_without,rests", [(ONE_RUN_P, False), (float(np.nextafter(ONE_RUN_P, 1.0)), True),
                                             (0.5, True), (0.01, False)])
def test_unequal_scatter_rests_on_one_run_only_above_the_one_run_level(p_without, rests, monkeypatch):
    monkeypatch.setattr(verdict, "worst_deletion", lambda data, model, h: Deletion(3, p_without))
    het = Hypothesis("heteroscedasticity", "a", logp=math.log(1e-3))
    out = rests_on_one_run(None, None, het)
    assert (out is not None) == rests
    if rests:
        assert (out.row, out.p_without) == (3, p_without)
    assert rests_on_one_run(None, None, Hypothesis("missing_term", "a^3", logp=-9.0)) is None

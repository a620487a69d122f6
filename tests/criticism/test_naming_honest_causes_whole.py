"""What level 1 keeps of its named causes (criticism.naming.honest_causes), the whole return against the rule in
its docstring: a named cause that leaves a family member rejected at the stricter residual level (p_family <=
RESIDUAL_MISFIT_LEVEL * alpha, exactly at it included) is dropped and the misfit reported unexplained, quoting the
tests that fired, the cause tried and the tests it leaves; the candidate not singled out is quoted only when no
cause was named (a later round's candidate, after a cause was named, is not the misfit's candidate); misfit without
a named cause is unexplained; the naming record quotes the residual tests at the family level.  The rounds are
stand-ins holding catalogue hypotheses with the p-values written here; 1-3 fired tests, alpha 0.05 and 0.1."""

from __future__ import annotations

import re
from types import SimpleNamespace

import numpy as np
import pytest

from demid.criticism.catalogue import Hypothesis
from demid.criticism.naming import honest_causes
from demid.criticism.verdict import RESIDUAL_MISFIT_LEVEL

_DATA = SimpleNamespace(runs=np.arange(201, 214))


def _round(hypotheses, alpha):
    return SimpleNamespace(hypotheses=hypotheses, misfit=lambda a: [h for h in hypotheses if h.p_family <= a])


def _term(name, p, logp=-6.0):
    return Hypothesis("missing_term", None, aliases=[name], statistic=9.5, logp=logp, p_family=p)


def _why(alpha):
    rival = {"cause": "drift", "detail": "run", "aliases": [], "statistic": 12.0, "p_nominal": 0.00123,
             "p_family": 0.004}
    return {"cause": "missing_term", "detail": "a^3", "rival": rival}


def _entry(h):
    return {"cause": h.cause, "detail": h.aliases[0], "aliases": list(h.aliases), "statistic": h.statistic,
            "p_nominal": float(np.exp(h.logp)), "p_family": h.p_family}


@pytest.mark.parametrize("alpha", [0.05, 0.1])
@pytest.mark.parametrize("n_fired", [1, 2, 3])
@pytest.mark.parametrize("residual_at", [0.5, 1.0, 1.0 + 1e-9, 3.0])  # residual p over the stricter level
@pytest.mark.parametrize("later_candidate", [False, True])
def test_a_named_cause_leaving_misfit_at_the_stricter_level_is_dropped_without_a_later_candidate(
        alpha, n_fired, residual_at, later_candidate):
    fired = [_term(f"a^{3 + i}", alpha * (0.01 + 0.2 * i), logp=-8.0 + i) for i in range(n_fired)]
    first = _round(fired + [_term("b^3", 0.9)], alpha)
    residual_p = residual_at * RESIDUAL_MISFIT_LEVEL * alpha
    left = [_term("a:b^2", residual_p), _term("b^4", 0.7)]
    last = _round(left, alpha)
    finding = SimpleNamespace(cause="missing_term", detail="a^3", info={"alternatives": [{"cause": "drift"}]})
    base, extended = object(), object()
    why = _why(alpha) if later_candidate else None
    findings, model, unexplained, naming = honest_causes(_DATA, "y", [finding], extended, base, first, last,
                                                         why, alpha)
    dropped = residual_p <= RESIDUAL_MISFIT_LEVEL * alpha
    # the naming record: the residual tests at the family level, the first cause and its alternatives
    expected_naming = {"residual_min_p": min(residual_p, 0.7),
                       "residual_tests": [_entry(left[0])] if residual_p <= alpha else [],
                       "first_alternatives": [{"cause": "drift"}], "first_cause": "missing_term",
                       "first_detail": "a^3"}
    if why is not None:
        expected_naming["not_singled_out"] = why
    assert naming == expected_naming
    if not dropped:
        assert findings == [finding] and model is extended and unexplained is None
        return
    assert findings == [] and model is base
    assert unexplained["candidate"] is None  # a later round's candidate is not quoted
    assert unexplained["tests"] == [_entry(h) for h in fired]
    assert unexplained["tried"] == [{"cause": "missing_term", "detail": "a^3"}]
    assert unexplained["remaining"] == [_entry(left[0])]
    assert unexplained["p_value"] == min(h.p_family for h in fired + left[:1])
    assert unexplained["detail"] == "missing_term"
    msg = unexplained["message"]
    assert "not singled out" not in msg
    assert msg.startswith(f"y: the runs show misfit that no catalogued cause accounts for. Tests that fired at the "
                          f"family-wise {100 * alpha:g} % level: ")
    quoted = [float(v) for v in re.findall(r"family-wise p = ([0-9.e+-]+)\)", msg)]
    assert quoted == pytest.approx([h.p_family for h in fired] + [residual_p], rel=5e-3)
    assert "The best catalogue explanation, missing term a^3, leaves misfit behind (missing term a:b^2" in msg


@pytest.mark.parametrize("alpha", [0.05, 0.1])
@pytest.mark.parametrize("with_candidate", [False, True])
def test_misfit_without_a_named_cause_is_unexplained_and_quotes_the_candidate_not_singled_out(alpha,
                                                                                                with_candidate):
    fired = [_term("a^3", alpha), _term("b^3", 0.3 * alpha)]  # the first exactly at the family level
    first = _round(fired + [_term("a:b^2", 2 * alpha)], alpha)
    why = _why(alpha) if with_candidate else None
    findings, model, unexplained, naming = honest_causes(_DATA, "y", [], "extended", "base", first, first, why,
                                                         alpha)
    assert findings == [] and model == "base"
    assert naming == ({"not_singled_out": why} if why else {})
    assert unexplained["candidate"] == why and unexplained["tried"] == [] and unexplained["remaining"] == []
    assert unexplained["tests"] == [_entry(h) for h in fired]
    assert unexplained["p_value"] == 0.3 * alpha
    msg = unexplained["message"]
    assert ("The strongest catalogue candidate, missing term a^3, is not singled out: run-order drift is at least "
            "as significant (nominal p = 0.0012), so no cause is named." in msg) == with_candidate
    assert "The best catalogue explanation" not in msg


def test_no_misfit_and_no_cause_is_not_unexplained():
    first = _round([_term("a^3", 0.4)], 0.05)
    assert honest_causes(_DATA, "y", [], "extended", "base", first, first, None, 0.05) == ([], "extended", None, {})


@pytest.mark.parametrize("alpha", [0.05, 0.1])
def test_of_several_named_causes_the_naming_record_quotes_the_first_named(alpha):
    first = _round([_term("a^3", 0.2 * alpha), _term("b^3", 0.9)], alpha)
    last = _round([_term("b^4", 0.8)], alpha)
    named = [SimpleNamespace(cause="missing_term", detail="a^3", info={"alternatives": [{"cause": "step"}]}),
             SimpleNamespace(cause="outlier", detail=7, info={"alternatives": []}),
             SimpleNamespace(cause="drift", detail="run", info={})]
    findings, model, unexplained, naming = honest_causes(_DATA, "y", named, "extended", "base", first, last,
                                                         None, alpha)
    assert findings == named and model == "extended" and unexplained is None
    assert naming == {"residual_min_p": 0.8, "residual_tests": [], "first_alternatives": [{"cause": "step"}],
                      "first_cause": "missing_term", "first_detail": "a^3"}

"""Which cause the ambiguity check reads (criticism.naming.ambiguity): when a cause was named, its first finding,
whatever a later round left not singled out (a candidate resting on one run, or one with a rival outside the
catalogue such as lack of fit) -- the candidates and the runs that would confirm or decide are those of the named
cause alone."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from demid.criticism.level1 import _rounds, prepare_data
from demid.criticism.models import Model, ModelForm
from demid.criticism.naming import ambiguity
from tests.generators import FACTORS, ccd_table

_LATER = [
    {"cause": "heteroscedasticity", "detail": "mu_r", "one_run": {"run": 3, "p_without": 0.2}},
    {"cause": "drift", "detail": "run", "rival": {"cause": "lack_of_fit", "detail": "", "p_nominal": 1e-3}},
    {"cause": "outlier", "detail": 4, "rival": {"cause": "drift", "detail": "run", "p_nominal": 1e-3}},
]


@pytest.mark.parametrize("kind,seed,size", [("term", 0, 6.0), ("outlier", 3, 8.0)])
def test_a_named_cause_decides_the_ambiguity_whatever_a_later_round_left(kind, seed, size):
    table, _ = ccd_table(seed, 2, kind, size)
    data, _ = prepare_data(table, FACTORS[2], "y", None, ())
    base = Model(data, ModelForm())
    findings, _, _, _, first_round, _, _ = _rounds(data, "y", base, 199, np.random.default_rng(0), 0.05, 3)
    assert findings
    alone = ambiguity(data, base, first_round, findings, None)
    assert alone[0] or alone[1]  # candidates, or runs that would confirm the named cause
    for later in _LATER:
        assert ambiguity(data, base, first_round, findings, later) == alone


@pytest.mark.parametrize("seed", [1, 5])
def test_two_close_candidates_of_a_cause_not_singled_out_are_both_reported(seed):
    """A cubic term named, or not singled out for a rival slip of one run, whose rival's extension fits within the
    ambiguity margin: exactly two candidates, both reported (best first, the second's AICc behind it), with runs to
    decide -- not the runs that would confirm the named one."""
    from demid.criticism.discrimination import AMBIGUOUS_AICC, close_candidates
    from demid.criticism.naming import candidate_entries

    table, _ = ccd_table(seed, 2, "term", 4.0 if seed == 1 else 3.0)
    data, _ = prepare_data(table, FACTORS[2], "y", None, ())
    base = Model(data, ModelForm())
    _, _, _, _, first_round, _, _ = _rounds(data, "y", base, 199, np.random.default_rng(0), 0.05, 3)
    entries = candidate_entries(data, base, first_round)
    close = close_candidates(entries, named=("missing_term", "gamma^3"))
    assert len(close) == 2
    rival = next(c for c in close if c["cause"] != "missing_term")
    later = {"cause": "missing_term", "detail": "gamma^3",
             "rival": {"cause": rival["cause"], "detail": rival["detail"], "p_nominal": 1e-3}}
    named = [SimpleNamespace(cause="missing_term", detail="gamma^3")]  # the same cause named instead
    for findings, not_singled_out in (([], later), (named, None)):
        candidates, runs = ambiguity(data, base, first_round, findings, not_singled_out)
        assert [(c["cause"], c["detail"]) for c in candidates] == [(c["cause"], c["detail"]) for c in close]
        assert candidates[0]["delta_aicc"] == 0.0 and 0.0 <= candidates[1]["delta_aicc"] <= AMBIGUOUS_AICC
        assert candidates[1]["delta_aicc"] == pytest.approx(close[1]["aicc"] - close[0]["aicc"], rel=1e-9)
        assert runs

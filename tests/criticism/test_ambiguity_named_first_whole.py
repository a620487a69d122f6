"""Which cause the ambiguity check reads (criticism.naming.ambiguity): when a cause was named, its first finding,
whatever a later round left not singled out (a candidate resting on one run, or one with a rival outside the
catalogue such as lack of fit) -- the candidates and the runs that would confirm or decide are those of the named
cause alone."""

from __future__ import annotations

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

"""A cause not singled out for a rival of another kind: the candidates the ambiguity lists are the close ones
around it (discrimination.close_candidates) with their AICc gain over the quadratic and their lag behind the
best, each computed here from the entries' fitted models; a rival that is no catalogue cause (lack of fit), or
one the runs tell apart, leaves no ambiguity."""
from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from demid.criticism.catalogue import Round
from demid.criticism.discrimination import close_candidates
from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm
from demid.criticism.naming import ambiguity, candidate_entries


def _study(seed, k=2, n=16):
    rng = np.random.default_rng(seed)
    x = rng.uniform(1.0, 3.0, (n, k))
    y = 3.0 + x[:, 0] - 0.3 * x[:, -1] ** 2 + 0.1 * rng.standard_normal(n)
    factors = [f"f{j}" for j in range(k)]
    table = pd.DataFrame({"run": np.arange(1, n + 1), **{f: x[:, j] for j, f in enumerate(factors)}, "y": y})
    data, _ = prepare_data(table, factors, "y", 1.0, (), None)
    base = Model(data, ModelForm())
    return data, base, Round(data, base, 19, np.random.default_rng(seed))


@pytest.mark.parametrize("seed", [3, 8])
def test_a_candidate_not_singled_out_lists_the_close_causes_with_their_gains(seed):
    data, base, first_round = _study(seed)
    entries = candidate_entries(data, base, first_round)
    close = close_candidates(entries)
    assert len(close) >= 2  # noise only: several extensions fit about equally
    named, rival = close[0], close[1]
    not_singled_out = {"cause": named["cause"], "detail": named["detail"],
                       "rival": {"cause": rival["cause"], "detail": rival["detail"], "p_nominal": 0.01}}
    candidates, runs = ambiguity(data, base, first_round, [], not_singled_out)
    around = close_candidates(entries, named=(named["cause"], named["detail"]))
    assert [(c["cause"], c["detail"]) for c in candidates] == [(e["cause"], e["detail"]) for e in around]
    for c, e in zip(candidates, around):
        assert c["gain"] == pytest.approx(base.aicc - e["aicc"], rel=1e-12, abs=1e-12)
        assert c["delta_aicc"] == pytest.approx(e["aicc"] - around[0]["aicc"], rel=1e-12, abs=1e-12)
        assert c["delta_aicc"] >= 0.0
    # lack of fit names no cause the runs could tell apart: no ambiguity to list
    lof = {**not_singled_out, "rival": {"cause": "lack_of_fit", "detail": "", "p_nominal": 0.01}}
    assert ambiguity(data, base, first_round, [], lof) == ([], [])
    # a rival the runs tell apart from the candidate (not among the close ones): none either
    far = {**not_singled_out, "rival": {"cause": "drift", "detail": "no such run", "p_nominal": 0.01}}
    assert ambiguity(data, base, first_round, [], far) == ([], [])
    # without a rival, and without a first round, nothing is ambiguous
    assert ambiguity(data, base, first_round, [], {"cause": named["cause"], "detail": named["detail"]}) == ([], [])
    assert ambiguity(data, base, None, [], not_singled_out) == ([], [])

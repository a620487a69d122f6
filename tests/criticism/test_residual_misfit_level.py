"""After the named extensions, a family member still rejected at RESIDUAL_MISFIT_LEVEL times the family level
(at it or below) turns the named causes into unexplained misfit; just above it they stand.  The unexplained
record's p is the smallest family p of the tests that fired and of those left."""
from __future__ import annotations

import types

import numpy as np
import pandas as pd
import pytest

from demid.criticism.catalogue import Hypothesis
from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm
from demid.criticism.naming import honest_causes
from demid.criticism.verdict import RESIDUAL_MISFIT_LEVEL


def _round(hypotheses):
    return types.SimpleNamespace(hypotheses=hypotheses,
                                 misfit=lambda a: [h for h in hypotheses if h.p_family <= a])


@pytest.mark.parametrize("alpha", [0.05, 0.1])
@pytest.mark.parametrize("offset, unexplained", [(0.0, True), (-1e-6, True), (1e-6, False)])
def test_a_member_left_at_the_residual_level_makes_the_misfit_unexplained(alpha, offset, unexplained):
    rng = np.random.default_rng(0)
    table = pd.DataFrame({"run": np.arange(1, 15), "a": rng.uniform(1, 3, 14), "b": rng.uniform(1, 3, 14)})
    table["y"] = 2.0 + table["a"] + 0.1 * rng.standard_normal(14)
    data, _ = prepare_data(table, ["a", "b"], "y", 1.0, (), None)
    base = Model(data, ModelForm())
    named = Model(data, ModelForm(drift=True))
    first = Hypothesis("drift", "run", logp=-9.0, p_family=0.001)
    left = Hypothesis("lack_of_fit", None, logp=-3.0, p_family=RESIDUAL_MISFIT_LEVEL * alpha + offset)
    finding = types.SimpleNamespace(cause="drift", detail="run", info={})
    findings, model, record, naming = honest_causes(data, "y", [finding], named, base, _round([first]),
                                                    _round([left]), None, alpha)
    assert naming["residual_min_p"] == left.p_family
    if unexplained:
        assert findings == [] and model is base
        assert record["p_value"] == pytest.approx(min(0.001, left.p_family))
        assert [e["cause"] for e in record["remaining"]] == ["lack_of_fit"]
    else:
        assert findings == [finding] and model is named and record is None

"""The AICc of a step at every change-point (criticism.naming's candidates) on a long table, from the base fit's
sums (above STEP_CHUNK runs) against a model fitted with the step at each change-point checked, with and without
variance weights."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from demid.criticism.level1 import prepare_data
from demid.criticism.models import Model, ModelForm
from demid.criticism.naming import _step_aiccs
from tests.criticism.test_large_studies import _table


@pytest.mark.parametrize("gamma", [None, 0.8])
def test_a_steps_aicc_at_every_change_point_is_the_fitted_models(gamma):
    data, _ = prepare_data(_table(300, 4, "scatter"), ["a", "b"], "y", 1.0, (), None)
    spec = ModelForm() if gamma is None else ModelForm(weight_on="a", weight_gamma=gamma,
                                                       weight_values=tuple(data.coded[:, 0]))
    base = Model(data, spec)
    aiccs = list(_step_aiccs(data, base))
    assert len(aiccs) == 300 - 3
    for start, aicc in aiccs[:2] + aiccs[150:152] + aiccs[-2:]:
        assert aicc == pytest.approx(Model(data, replace(spec, step=start)).aicc, rel=1e-9, abs=1e-7)

"""The Box-Cox transform used (criticism.extensions.extend_for) when a convenient lambda is exactly the end of
the 99 % interval: the interval's ends are points of the 0.01 grid, so a convenient value can be one, and it
counts as inside (the data do not reject it at the 1 % level).  A CCD with 8 centre runs whose response is a
power 1/1.08 of a plane: the 99 % interval computed here (numpy profile on the documented grid) starts exactly at
lambda = 0, and the log is used."""
from __future__ import annotations

import numpy as np
import pytest

from demid.criticism.catalogue import Hypothesis
from demid.criticism.extensions import extend_for
from demid.criticism.models import Model, ModelForm
from tests.criticism.test_extensions_whole import _lambda_by_hand
from tests.criticism.test_models_properties import _data


def test_a_convenient_lambda_at_the_end_of_the_99_percent_interval_is_used():
    data = _data(1, 8)
    rng = np.random.default_rng(1)
    power = 1.08
    eta = 4.0 + 1.5 * data.coded[:, 0] - 1.0 * data.coded[:, 1] + rng.normal(scale=0.02, size=data.n)
    data.y = (1 + power * eta / 8) ** (1 / power) * 10
    model = Model(data, ModelForm())
    best, inside, plausible = _lambda_by_hand(data, model)
    assert plausible.min() == 0.0 and plausible.max() > 0.5  # log at the edge, sqrt well inside
    spec, info = extend_for(data, model, Hypothesis("response_transform", "boxcox"))
    assert spec.lam == 0.0
    assert info["lambda_hat"] == pytest.approx(best, abs=1e-9)
    assert info["lambda_ci"] == pytest.approx([inside.min(), inside.max()], abs=1e-9)

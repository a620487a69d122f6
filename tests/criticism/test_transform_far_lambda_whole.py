"""A Box-Cox transform whose 99 % interval holds no convenient lambda (criticism.extensions.extend_for): responses
built with lambda 2.7 or -2.6 and little noise, so that neither log, sqrt, inverse nor any of the nice values lies
inside; the lambda used is then lambda-hat to one decimal.  Lambda-hat, the 95 % interval and the lambda used
against the profile computed here with numpy (tests/criticism/test_extensions_whole.py's)."""

from __future__ import annotations

import numpy as np
import pytest

from demid.criticism.catalogue import NICE_LAMBDAS, Hypothesis
from demid.criticism.extensions import extend_for
from demid.criticism.models import TRANSFORM_NAMES, Model, ModelForm
from tests.criticism.test_extensions_whole import _lambda_by_hand
from tests.criticism.test_models_properties import _data


@pytest.mark.parametrize("power", [2.7, -2.6])
@pytest.mark.parametrize("seed", [0, 1])
def test_a_lambda_far_from_every_convenient_value_is_used_to_one_decimal(power, seed):
    data = _data(seed, 3)
    rng = np.random.default_rng(seed)
    eta = 2.0 + 0.6 * data.coded[:, 0] - 0.4 * data.coded[:, 1] + rng.normal(scale=1e-4, size=data.n)
    data.y = (1 + power * eta / 10) ** (1 / power) * 10
    model = Model(data, ModelForm())
    spec, info = extend_for(data, model, Hypothesis("response_transform", "boxcox"))
    best, inside, plausible = _lambda_by_hand(data, model)
    assert not [v for v in (*TRANSFORM_NAMES, *NICE_LAMBDAS) if plausible.min() <= v <= plausible.max()]
    assert info["lambda_hat"] == pytest.approx(best, abs=1e-9)
    assert info["lambda_ci"] == pytest.approx([inside.min(), inside.max()], abs=1e-9)
    assert spec.lam == pytest.approx(round(float(best), 1), abs=1e-12)
    assert abs(spec.lam - power) <= 0.25


# lambda-hat, the seed, and the lambda the rule gives: 0.05 and -0.05 are halfway between two tenths, one of them
# the log the runs reject, so the other; 0.04 to one decimal is that log, so lambda-hat to two decimals
@pytest.mark.parametrize("power,seed,used", [(0.05, 0, 0.1), (-0.05, 3, -0.1), (0.04, 0, 0.04)])
def test_lambda_hat_next_to_a_log_the_runs_reject_is_not_rounded_to_it(power, seed, used):
    data = _data(seed, 3)
    rng = np.random.default_rng(seed)
    slope, noise = (1.5, 1e-3) if power < 0 else (3.0, 3e-3)
    eta = 2.0 + slope * data.coded[:, 0] - 0.7 * slope * data.coded[:, 1] + rng.normal(scale=noise, size=data.n)
    data.y = (1 + power * eta) ** (1 / power)
    model = Model(data, ModelForm())
    best, inside, plausible = _lambda_by_hand(data, model)
    assert best == pytest.approx(power, abs=1e-12)
    assert not [v for v in (*TRANSFORM_NAMES, *NICE_LAMBDAS) if plausible.min() <= v <= plausible.max()]
    spec, info = extend_for(data, model, Hypothesis("response_transform", "boxcox"))
    assert info["lambda_hat"] == pytest.approx(best, abs=1e-9)
    assert spec.lam == pytest.approx(used, abs=1e-12)
    assert spec.lam not in TRANSFORM_NAMES and plausible.min() <= spec.lam <= plausible.max()

"""The Box-Cox transform used (criticism.extensions.extend_for) when a convenient lambda is exactly the end of
the 99 % interval: the interval's ends are points of the 0.01 grid, so a convenient value can be one, and it
counts as inside (the data do not reject it at the 1 % level).  A CCD with 8 centre runs whose response is a
power 1/1.08 of a plane: the 99 % interval computed here (numpy profile on the documented grid) starts exactly at
lambda = 0, and the log is used; and lambda-hat near 1 with no convenient value in the interval, used to two
decimals (one decimal would read 1, no transform); and lambda-hat to one decimal used though just outside the
interval when it is neither 1 nor a named transform."""
from __future__ import annotations

import numpy as np
import pytest

from demid.criticism.catalogue import NICE_LAMBDAS, Hypothesis
from demid.criticism.extensions import extend_for
from demid.criticism.models import TRANSFORM_NAMES, Model, ModelForm
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


def _boxcox_plane(power: float):
    """Two factors, eight runs: a response whose Box-Cox transform with ``power`` is a plane spanning about 1 to 30,
    with a hundredth of noise; its model and what _lambda_by_hand reads from it."""
    data = _data(2, 8)
    rng = np.random.default_rng(2)
    z = 12.5 + 7.0 * data.coded[:, 0] - 5.0 * data.coded[:, 1] + rng.normal(scale=0.01, size=data.n)
    data.y = (1 + power * z) ** (1 / power)
    model = Model(data, ModelForm())
    return (data, model, *_lambda_by_hand(data, model))


@pytest.mark.parametrize("power", [0.97, 1.03])
def test_a_lambda_near_one_without_a_convenient_value_is_used_to_two_decimals(power):
    """A Box-Cox power of a plane close to 1 on a response spanning 1 to about 30: the 99 % interval is a few
    hundredths wide around it and holds no convenient lambda; lambda-hat to one decimal would be 1 (no transform at
    all), so the transform used is lambda-hat to two decimals."""
    data, model, best, inside, plausible = _boxcox_plane(power)
    assert not [v for v in (*TRANSFORM_NAMES, *NICE_LAMBDAS) if plausible.min() <= v <= plausible.max()]
    assert round(best, 1) == 1.0 and round(best, 2) != 1.0
    spec, info = extend_for(data, model, Hypothesis("response_transform", "boxcox"))
    assert spec.lam == pytest.approx(round(best, 2), abs=1e-12)
    assert info["lambda_hat"] == pytest.approx(best, abs=1e-9)
    assert info["lambda_ci"] == pytest.approx([inside.min(), inside.max()], abs=1e-9)


@pytest.mark.parametrize("power", [0.63, 0.84])
def test_a_lambda_without_a_convenient_value_is_used_to_one_decimal_even_outside_the_interval(power):
    """A Box-Cox power of a plane away from 1 and from every convenient value, with a 99 % interval a few
    hundredths wide: lambda-hat to one decimal is neither 1 nor a named transform, so it is the transform used,
    though it lies just outside the interval (two decimals only where one decimal reads 1 or names a transform)."""
    data, model, best, inside, plausible = _boxcox_plane(power)
    assert not [v for v in (*TRANSFORM_NAMES, *NICE_LAMBDAS) if plausible.min() <= v <= plausible.max()]
    one_decimal = round(best, 1)
    assert one_decimal != 1.0 and one_decimal not in TRANSFORM_NAMES
    assert not plausible.min() <= one_decimal <= plausible.max()
    spec, info = extend_for(data, model, Hypothesis("response_transform", "boxcox"))
    assert spec.lam == pytest.approx(one_decimal, abs=1e-12)
    assert info["lambda_hat"] == pytest.approx(best, abs=1e-9)
    assert info["lambda_ci"] == pytest.approx([inside.min(), inside.max()], abs=1e-9)


def test_a_convenient_lambda_at_the_upper_end_of_the_99_percent_interval_is_used():
    """The log at the interval's upper end counts as inside too: it is used before the inverse, which lies inside
    further down (a negative power of a plane: lambda-hat about -0.4, the 99 % interval ending exactly at 0)."""
    data = _data(0, 8)
    rng = np.random.default_rng(0)
    power = -0.58
    eta = 4.0 + 1.5 * data.coded[:, 0] - 1.0 * data.coded[:, 1] + rng.normal(scale=0.01, size=data.n)
    data.y = (1 + power * eta / 8) ** (1 / power) * 10
    model = Model(data, ModelForm())
    best, inside, plausible = _lambda_by_hand(data, model)
    assert plausible.max() == 0.0 and plausible.min() <= -1.0 < best
    spec, info = extend_for(data, model, Hypothesis("response_transform", "boxcox"))
    assert spec.lam == 0.0
    assert info["lambda_hat"] == pytest.approx(best, abs=1e-9)
    assert info["lambda_ci"] == pytest.approx([inside.min(), inside.max()], abs=1e-9)

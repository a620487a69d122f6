"""The Box-Cox lambda's 95 % and 99 % intervals (criticism.extensions.extend_for) are closed: a grid lambda whose F
ratio df (exp(2 (l_max - l(lambda)) / n) - 1) equals the F(1, df) quantile exactly belongs to them.  A tie of that
ratio with the quantile to the last bit is no table one can write down, so the quantile is set to the ratio of a
chosen grid lambda (computed as the profile is, on the fit's orthonormal basis); the interval must then end exactly
there, and one step of 0.01 further in when the quantile is a hair below it."""
from __future__ import annotations

import types

import numpy as np
import pytest
from scipy import stats

from demid.criticism import extensions
from demid.criticism.catalogue import LAMBDA_FINE_GRID, Hypothesis, boxcox_profile
from demid.criticism.models import Model, ModelForm, orthonormal_basis
from tests.criticism.test_models_properties import _data


def _ratios(model):
    prof = boxcox_profile(model.y[:, None], orthonormal_basis(model.xw), LAMBDA_FINE_GRID)[:, 0]
    n, df = len(model.y), model.df_resid - 1
    return df * np.expm1(2 * (prof.max() - prof) / n), df


def _quantile_at(level, value, df):
    """scipy.stats with F(1, df)'s ``level`` quantile replaced by ``value`` (the other level as scipy has it)."""
    def ppf(q, dfn, dfd):
        return value if q == level else stats.f.ppf(q, dfn, dfd)
    return types.SimpleNamespace(f=types.SimpleNamespace(ppf=ppf))


@pytest.mark.parametrize("seed", [1, 2])
@pytest.mark.parametrize("end", ["upper", "lower"])
def test_a_lambda_exactly_on_the_95_percent_bound_is_inside_the_interval(seed, end, monkeypatch):
    data = _data(seed, 3)
    model = Model(data, ModelForm())
    ratio, df = _ratios(model)
    best = int(np.argmin(ratio))
    # a grid lambda 0.3 from the best on the chosen side: the interval's end when the quantile is its ratio
    edge = best + 30 if end == "upper" else best - 30
    side = slice(best, None) if end == "upper" else slice(None, best + 1)
    assert np.all(np.diff(ratio[side]) > 0 if end == "upper" else np.diff(ratio[side]) < 0)  # one-sided rise
    for quantile, expected in ((ratio[edge], edge), (np.nextafter(ratio[edge], 0.0), edge - 1 if end == "upper"
                                                     else edge + 1)):
        monkeypatch.setattr(extensions, "stats", _quantile_at(0.95, quantile, df))
        _, info = extensions.extend_for(data, model, Hypothesis("response_transform", "boxcox"))
        inside = LAMBDA_FINE_GRID[ratio <= quantile]
        assert info["lambda_ci"] == [float(inside.min()), float(inside.max())]
        assert (info["lambda_ci"][1] if end == "upper" else info["lambda_ci"][0]) == LAMBDA_FINE_GRID[expected]

"""The model helpers' numbers where the earlier tests held something fixed: the axial distance of a CCD whose other
factors are no CCD (inner levels off-centre to either side, a centre level off zero, different alphas per factor,
the median of them), AICc at exactly no spare degree of freedom and one, and a model's summary of a response of any
scale (R² is scale-free; a response whose spread is below one is no constant), each against the closed form."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.criticism.models import Model, ModelForm, aicc_of, aicc_of_many, infer_axial_distance
from tests.criticism.test_models_properties import _data

_SETTINGS = settings(max_examples=12, deadline=None, derandomize=True)


def _column(levels, centre, unit, rng):
    """A factor column of ``levels`` (coded), each run twice, in actual units, shuffled."""
    coded = np.repeat(np.asarray(levels, dtype=float), 2)
    return centre + unit * rng.permutation(coded)


@given(alphas=st.lists(st.floats(1.1, 2.4), min_size=1, max_size=3), skew=st.floats(0.01, 0.3),
       below=st.booleans(), centre=st.floats(-40, 40), unit=st.floats(0.05, 20), seed=st.integers(0, 99))
@_SETTINGS
def test_the_axial_distance_is_the_median_of_the_ccd_factors_alone(alphas, skew, below, centre, unit, seed):
    rng = np.random.default_rng(seed)
    cols = [_column([-a, -1, 0, 1, a], centre, unit, rng) for a in alphas]
    # no CCD: inner levels unequally far from the centre (the larger one inside or outside), a centre off zero
    lopsided = [-2.0, -1.0 + (skew if below else -skew), 0.0, 1.0, 2.0]
    cols.append(_column(lopsided, centre, unit, rng))
    cols.append(_column([-2.0, -1.0, skew, 1.0, 2.0], centre, unit, rng))
    cols.append(_column([-1.0, 0.0, 1.0, 0.0, 1.0], centre, unit, rng))  # three levels
    cols.append(np.full(len(cols[0]), centre))  # a factor held constant
    order = rng.permutation(len(cols))
    actual = np.column_stack([cols[i] for i in order])
    assert infer_axial_distance(actual) == pytest.approx(float(np.median(alphas)), rel=1e-5)
    # only the no-CCD columns: the documented 1.0
    assert infer_axial_distance(np.column_stack(cols[len(alphas):])) == 1.0


@pytest.mark.parametrize("spare", [-1, 0, 1, 2, 5])
def test_aicc_at_no_spare_degree_of_freedom_is_nan_and_above_it_the_closed_form(spare):
    k = 4
    n = k + 1 + spare
    llf = np.array([-3.5, 0.25, 12.0])
    many = aicc_of_many(llf, n, k)
    assert many.shape == llf.shape
    if spare <= 0:
        assert np.isnan(many).all() and np.isnan(aicc_of(-3.5, n, k))
        return
    expected = -2 * llf + 2 * k + 2 * k * (k + 1) / (n - k - 1)
    np.testing.assert_allclose(many, expected, rtol=1e-12)
    assert aicc_of(float(llf[1]), n, k) == pytest.approx(expected[1], rel=1e-12)


@given(seed=st.integers(0, 500), scale=st.sampled_from([1e-6, 1e-3, 0.05, 1.0, 300.0, 1e5]), shift=st.booleans())
@_SETTINGS
def test_a_summarys_r2_does_not_depend_on_the_responses_scale(seed, scale, shift):
    data = _data(seed, 3)
    data.y = data.y * scale + (scale if shift else 0.0)
    summary = Model(data, ModelForm()).summary()
    y = data.y
    x = Model(data, ModelForm()).x
    fitted = x @ np.linalg.lstsq(x, y, rcond=None)[0]
    sst, sse = np.sum((y - y.mean()) ** 2), np.sum((y - fitted) ** 2)
    assert sst < 1 or scale >= 1  # the small scales give a total sum of squares below one
    assert summary["r2"] == pytest.approx(1 - sse / sst, rel=1e-9)
    assert summary["rmse"] == pytest.approx(np.sqrt(sse / len(y)), rel=1e-9)
    # a constant response has no R², whatever round-off its mean carries (0.1 or 1e-6 on 13 runs)
    data.y = np.full(len(y), scale if shift else 0.1)
    assert Model(data, ModelForm()).summary()["r2"] is None

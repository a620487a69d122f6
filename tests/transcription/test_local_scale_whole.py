"""The typo screen's level-dependent scale (Harvey's model) on residuals some of which are exactly zero (runs the
fit passes through, a replicate pair's mean): the log-variance line is fitted to the positive squared residuals
alone, from three of them on, and normalised over every run; with fewer than three, or all of them at one fitted
level, the scale is one everywhere.  Written out with numpy's polyfit, over 3-40 runs, 0-10 zero residuals and
leverages up to one."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import Phase, given, settings
from hypothesis import strategies as st

from demid.transcription.typos import local_scale


def _harvey(fitted, residual, leverage):
    raw = residual ** 2 / np.clip(1 - leverage, 1e-12, None)
    positive = raw > 0
    if positive.sum() < 3 or np.ptp(fitted[positive]) == 0:
        return np.ones_like(residual)
    slope, intercept = np.polyfit(fitted[positive], np.log(raw[positive]), 1)
    variance = np.exp(intercept + slope * fitted)
    variance *= np.mean(raw / variance)
    return np.sqrt(variance / np.mean(raw))


@given(seed=st.integers(0, 10_000), positive=st.integers(3, 30), zeros=st.integers(0, 10),
       level=st.sampled_from([-50.0, 0.0, 3.0, 1e4]), slope=st.sampled_from([0.0, 0.4, -0.3]))
@settings(max_examples=15, deadline=None, derandomize=True, phases=[Phase.explicit, Phase.generate])
def test_the_scale_is_fitted_to_the_positive_squared_residuals_and_normalised_over_every_run(seed, positive, zeros,
                                                                                               level, slope):
    rng = np.random.default_rng(seed)
    n = positive + zeros
    fitted = level + rng.uniform(0, 10, n)
    residual = rng.normal(size=n) * np.exp(slope * (fitted - level) / 2) + 0.01
    residual[rng.permutation(n)[:zeros]] = 0.0
    leverage = rng.uniform(0.0, 0.6, n)
    scale = local_scale(fitted, residual, leverage)
    want = _harvey(fitted, residual, leverage)
    assert not np.all(want == 1.0)  # three or more positive residuals at different levels: a fitted line
    np.testing.assert_allclose(scale, want, rtol=1e-7)
    raw = residual ** 2 / (1 - leverage)
    # normalised: the squared residuals over the fitted variance average the pooled one
    assert np.mean(raw / scale ** 2) == pytest.approx(np.mean(raw), rel=1e-9)


def test_exactly_three_positive_residuals_are_enough_for_the_line():
    fitted = np.array([1.0, 2.0, 4.0, 5.0, 7.0])
    residual = np.array([0.5, 0.0, -1.0, 0.0, 3.0])
    leverage = np.array([0.2, 0.3, 0.1, 0.0, 0.5])
    scale = local_scale(fitted, residual, leverage)
    assert not np.allclose(scale, 1.0)
    np.testing.assert_allclose(scale, _harvey(fitted, residual, leverage), rtol=1e-9)


def test_positive_residuals_all_at_one_level_give_one_even_where_zero_ones_sit_elsewhere():
    fitted = np.array([2.0, 2.0, 2.0, 5.0, 9.0])
    residual = np.array([1.0, -0.5, 2.0, 0.0, 0.0])
    assert np.array_equal(local_scale(fitted, residual, np.zeros(5)), np.ones(5))


def test_a_leverage_of_one_is_clipped_not_divided_by_zero():
    fitted = np.array([1.0, 2.0, 3.0, 4.0])
    residual = np.array([0.3, -0.2, 0.5, 1e-7])
    leverage = np.array([0.1, 0.2, 0.3, 1.0])
    scale = local_scale(fitted, residual, leverage)
    assert np.all(np.isfinite(scale))
    np.testing.assert_allclose(scale, _harvey(fitted, residual, leverage), rtol=1e-9)

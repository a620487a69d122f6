"""The loop benchmark's bootstrap interval of loop/LHS (benchmarks/loop_vs_lhs.py: how far ten seeds pin a ratio)."""

import sys
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from loop_vs_lhs import ratio_interval  # noqa: E402


@pytest.mark.parametrize("scale", [0.5, 1.0, 2.0])
def test_a_loop_that_is_a_fixed_multiple_of_the_baseline_has_that_ratio_as_its_whole_interval(scale):
    baseline = np.random.default_rng(3).uniform(0.1, 2.0, 10)
    lo, hi = ratio_interval(scale * baseline, baseline)
    assert lo == pytest.approx(scale) and hi == pytest.approx(scale)


def test_the_interval_is_the_percentiles_of_resampled_ratios_of_medians():
    rng = np.random.default_rng(7)
    loop, baseline = rng.uniform(0.1, 1.0, 10), rng.uniform(0.2, 1.5, 10)
    # the same resampling written out: pairs drawn together, the ratio of the medians, its 5th and 95th percentile
    picks = np.random.default_rng(0).integers(0, 10, size=(2000, 10))
    ratios = [np.median(loop[p]) / np.median(baseline[p]) for p in picks]
    lo, hi = ratio_interval(loop, baseline)
    assert (lo, hi) == pytest.approx(tuple(np.quantile(ratios, [0.05, 0.95])))
    assert lo < np.median(loop) / np.median(baseline) < hi
    wider = ratio_interval(loop, baseline, level=0.99)
    assert wider[0] < lo and wider[1] > hi
    assert ratio_interval(loop, baseline) == (lo, hi)  # a fixed seed: the printout repeats

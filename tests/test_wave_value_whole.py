"""What a next wave can still buy, every field against a count written here: the plausible share of the search
range now and after the planned runs on the documented evaluation points (a 201-point grid per factor up to two
factors, 41 for three, 2^14 scrambled Sobol points above; log scales, ranges away from the origin), the
contraction 1 - after / now, the stop flag below a tenth (none for an empty set) and the runs counted."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.wave_value import expected_contraction

from .generators import random_domain


class _Field:
    """A stand-in surrogate with its own update (as kriging's): the error after n new runs is the error now over
    1 + shrink n."""

    def __init__(self, domain, shrink):
        self.domain, self.shrink = domain, shrink

    def unit(self, points):
        lo, hi = self.domain.search_bounds()
        return (self.domain.to_search(points) - lo) / (hi - lo)

    def se_mean(self, points):
        return 0.05 + 0.1 * np.sum(self.unit(points) ** 2, axis=1)

    def se_mean_after(self, points, new_runs):
        return self.se_mean(points) / (1.0 + self.shrink * len(new_runs))


def _judged(domain, shrink, radius):
    field = _Field(domain, shrink)

    def contains(points, se=None):
        error = field.se_mean(points) if se is None else se["y"]
        return np.abs(np.sum(field.unit(points), axis=1) - 0.5 * domain.dim) <= radius + 2.0 * error

    return SimpleNamespace(name="sc", spec=SimpleNamespace(domain=domain), fields={"y": SimpleNamespace(surrogate=field)},
                           contains=contains), field


def _points(domain):
    lo, hi = domain.search_bounds()
    k = domain.dim
    if k <= 3:
        n = 201 if k <= 2 else 41
        axes = [np.linspace(a, b, n) for a, b in zip(lo, hi)]
        search = np.array(np.meshgrid(*axes, indexing="ij")).reshape(k, -1).T
    else:
        from scipy.stats import qmc

        search = lo + qmc.Sobol(k, scramble=True, seed=0).random(2 ** 14) * (hi - lo)
    return np.where(np.array(domain.log), 10.0 ** search, search)


@given(k=st.integers(1, 4), log_mask=st.integers(0, 15), seed=st.integers(0, 10_000), runs=st.integers(0, 12),
       shrink=st.sampled_from([0.0, 0.01, 0.5]), radius=st.sampled_from([-1.0, 0.05, 0.3]))
@settings(max_examples=8, deadline=None, derandomize=True)
def test_every_field_of_a_waves_value_is_the_count_on_the_evaluation_points(k, log_mask, seed, runs, shrink, radius):
    rng = np.random.default_rng(seed)
    domain, _, _ = random_domain(rng, k, log_mask, lower=(-2.0, 1.0), width=(0.5, 3.0))
    judged, field = _judged(domain, shrink, radius)
    new_runs = rng.uniform(0.0, 1.0, (runs, k))
    points = _points(domain)
    now = judged.contains(points).mean()
    after = judged.contains(points, se={"y": field.se_mean(points) / (1.0 + shrink * runs)}).mean()
    value = expected_contraction(judged, new_runs)
    assert set(value) == {"scenario", "count", "plausible_fraction_pct", "expected_fraction_pct",
                          "expected_contraction", "stop"}
    assert value["scenario"] == "sc" and value["count"] == runs and type(value["count"]) is int
    assert value["plausible_fraction_pct"] == pytest.approx(100.0 * now, rel=1e-12, abs=1e-12)
    assert value["expected_fraction_pct"] == pytest.approx(100.0 * after, rel=1e-12, abs=1e-12)
    if now > 0:
        contraction = 1.0 - after / now
        assert value["expected_contraction"] == pytest.approx(contraction, rel=1e-12, abs=1e-12)
        assert value["stop"] is bool(contraction < 0.1)
    else:
        assert np.isnan(value["expected_contraction"]) and value["stop"] is False

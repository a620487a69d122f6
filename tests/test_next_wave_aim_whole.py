"""The value of a next wave too small to hold a support run (one or two design runs, a quarter of which rounds to none)
is still judged on runs aimed at the plausible set itself: the wave's own band runs lie on the set at twice
robust_z, wider than the set the value is about, so counting them would undervalue the wave.  The value is
recomputed here from the aimed runs (D-optimal on the plausible points of the box at robust_z, no support share,
given the earlier runs inside the box) and differs from the value of the planned runs themselves."""

from __future__ import annotations

import numpy as np
import pytest

from demid.next_wave import PURPOSE_SUPPORT, plan_next_wave, plausible_points, propose_runs
from demid.scenario import JudgedScenario
from demid.wave_value import expected_contraction

from .helpers import one_response_study


@pytest.mark.parametrize("count", [1, 2])
def test_a_wave_without_support_runs_is_valued_on_runs_aimed_at_the_set(count):
    lower, upper = np.array([2.0, 10.0]), np.array([4.0, 14.0])
    centre = np.array([3.0, 12.0])
    z = 2.0

    noise = np.random.default_rng(5).normal(0.0, 0.3, 64)  # a residual SD, so a run can shrink the set

    def responses(x):
        return {"y": 4.0 + (((x - centre) / (upper - lower)) ** 2).sum(axis=1) * 8.0 + noise[:len(x)]}

    table, spec, surrogates, plausible = one_response_study(responses, lower, upper, 5.0, count, 0.3, z)
    wave = plan_next_wave("m", table, surrogates, spec, plausible, z=z)
    assert len(wave.runs) == count and PURPOSE_SUPPORT not in set(wave.runs["purpose"])

    domain = spec.domain
    lo = domain.to_search(wave.domain["lower"].to_numpy(dtype=float))[0]
    hi = domain.to_search(wave.domain["upper"].to_numpy(dtype=float))[0]
    earlier = domain.to_search(table[["a", "b"]].to_numpy(dtype=float))
    earlier = earlier[np.all((earlier >= lo - 1e-9) & (earlier <= hi + 1e-9), axis=1)]
    judged = JudgedScenario(spec, spec.scenarios[0], surrogates, z)
    aimed_points = plausible_points(judged, lo, hi)
    assert len(aimed_points) > 0
    aimed = domain.to_actual(propose_runs(lo, hi, earlier, count, (), aimed_points, share=0.0)[0])
    want = expected_contraction(judged, aimed)
    for key in ("scenario", "count", "plausible_fraction_pct", "expected_fraction_pct", "stop"):
        assert wave.value[key] == want[key]
    np.testing.assert_allclose(wave.value["expected_contraction"], want["expected_contraction"], rtol=1e-12)

    # the wave's own runs (on the band at twice z) would give another value
    own = expected_contraction(judged, wave.runs[["a", "b"]].to_numpy(dtype=float))
    assert abs(own["expected_contraction"] - want["expected_contraction"]) > 1e-3 * abs(want["expected_contraction"])

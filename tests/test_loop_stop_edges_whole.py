"""The loop's stop rule and run numbering at their edges: a wave's evidence without any surrogate statistics (the
band's share is then unknown, never a number) and the next wave's run numbers against the count of its proposals."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from demid.waves import WaveEvidence, next_wave_runs, stop_decision


def _evidence(surrogates: dict, previous: float = 2.0, now: float = 2.0, wave: int = 2, max_waves: int = 4):
    return WaveEvidence(wave=wave, max_waves=max_waves, plausible_pct=now, previous_pct=previous,
                        surrogates=surrogates, model_limit=False, proposed=9, criticism_runs=0)


@pytest.mark.parametrize("surrogates", [{}, {"y1": {"q2": 0.9, "lof_p": 0.5, "loo_band": None}},
                                        {"y1": {"q2": 0.9, "lof_p": 0.5, "loo_band": float("nan")},
                                         "y2": {"q2": 0.9, "lof_p": 0.5, "loo_band": 0.1}}])
def test_a_settled_share_with_the_band_share_unknown_goes_on_and_says_the_share_is_not_known(surrogates):
    decision = stop_decision(None, _evidence(surrogates))
    assert decision["stop"] is False and decision["action"] == "next_runs"
    assert decision["reason"] == (
        "the waves go on: the plausible share of the search range went 2 % → 2 % from wave 1 to wave 2 (+0.0 %), "
        "but the surrogates' leave-one-out error against the tolerance band is not known; the next wave simulates "
        "the 9 proposed runs")


@pytest.mark.parametrize("count, first", [(1, 1), (3, 12), (7, 100)])
def test_the_next_waves_runs_are_numbered_on_from_the_first_one(count, first):
    rng = np.random.default_rng(count)
    proposals = pd.DataFrame({"b": rng.uniform(-5, 5, count), "a": rng.uniform(1, 2, count), "kind": "design"})
    runs = next_wave_runs(proposals, ["a", "b"], first)
    assert list(runs.columns) == ["run", "a", "b"]
    assert runs["run"].tolist() == list(range(first, first + count))
    np.testing.assert_array_equal(runs[["a", "b"]].to_numpy(), proposals[["a", "b"]].to_numpy())

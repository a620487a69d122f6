"""An observable no factor moves (criticism.level2), judged on the scale of its error: a response that varies over
the search range only at round-off (a part in 1e14 of its value) but misses a far target by a factor of a
million has an error spread of about 1e-8 -- above a billionth absolutely, far below a billionth of the error --
and is named as unmoved like a response exactly constant; one that changes by a part in 1e7 is moved."""

from __future__ import annotations

import numpy as np
import pytest

from demid.criticism.level2 import calibration_check
from demid.design import quadratic_terms
from demid.sampling.domain import Domain
from demid.surrogate import Surrogate

NAMES = ["p", "q"]
TERMS = quadratic_terms(2)


def _surrogate(name: str, coefficients: dict) -> Surrogate:
    beta = np.zeros(len(TERMS))
    for j, v in coefficients.items():
        beta[j] = v
    return Surrogate(name, NAMES, TERMS, beta, np.zeros((6, 6)), 0.0, 20)


@pytest.mark.parametrize("slope,unmoved", [(0.0, True), (1e-11, True), (1e-4, False)])
@pytest.mark.parametrize("target", [1e-3, 2e-3])
def test_an_observable_constant_to_round_off_with_a_far_target_is_unmoved(slope, unmoved, target):
    surrogates = {"z1": _surrogate("z1", {0: 10.0, 1: 5.0, 2: 3.0}),
                  "z2": _surrogate("z2", {0: 1000.0, 1: slope})}
    result = calibration_check(surrogates, Domain(tuple(NAMES), (0.0, 0.0), (1.0, 1.0)), {"z1": 13.0, "z2": target},
                               0.05, 21)
    spread = slope / target  # of z2's relative error over the range (p from 0 to 1)
    assert (spread > 1e-9) == (slope > 0)
    assert result.unmoved == (["z2"] if unmoved else [])
    if unmoved:
        assert abs(result.best_errors["z1"]) <= 1e-6  # the best point is sought on the observable that moves


@pytest.mark.parametrize("step,unmoved", [(1.0, True), (2.0, False)])
def test_an_error_spread_of_exactly_a_billionth_is_unmoved_and_twice_that_is_moved(step, unmoved):
    # z2 = 1e9 + step * p against the target 1e9: its relative error runs from 0 to step / 1e9 over p in [0, 1]
    assert (1e9 + 1.0 - 1e9) / 1e9 == 1e-9  # the premise: a spread of exactly 1e-9 * max(1, largest |error|)
    surrogates = {"z1": _surrogate("z1", {0: 10.0, 1: 5.0, 2: 3.0}), "z2": _surrogate("z2", {0: 1e9, 1: step})}
    result = calibration_check(surrogates, Domain(tuple(NAMES), (0.0, 0.0), (1.0, 1.0)), {"z1": 13.0, "z2": 1e9},
                               0.05, 21)
    assert result.unmoved == (["z2"] if unmoved else [])
    stuck = "z2 is predicted the same everywhere in the search range"
    assert (stuck in result.message) is unmoved

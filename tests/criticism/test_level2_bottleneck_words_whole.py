"""Level 2's bottleneck (criticism.level2.calibration_check) where every two of three linear observables can be met
exactly inside the domain and the three together cannot: dropping any one leaves no error, so the bottleneck is the
observable whose target needs the smallest bias, and the sentence says by how much and whether the simulation reads
it high or low.  Each implied bias is the relative error of the dropped observable at the point where the other two
meet their targets (a 2 x 2 linear system solved here); targets of either sign, generated tables."""
from __future__ import annotations

import re

import numpy as np
import pytest

from demid.criticism.level2 import calibration_check
from demid.design import quadratic_terms
from demid.sampling import Domain
from demid.surrogate import Surrogate

NAMES = ["y1", "y2", "y3"]
LOWER, UPPER = np.array([-1.0, 0.0]), np.array([1.0, 2.0])


def _case(seed: int):
    """Offsets, gradients and targets whose three pairwise solutions lie well inside the domain."""
    rng = np.random.default_rng(seed)
    while True:
        offsets, grads = rng.uniform(-5, 5, 3), rng.uniform(-3, 3, (3, 2))
        targets = offsets + grads @ rng.uniform(LOWER, UPPER) + rng.uniform(-1.5, 1.5, 3)
        if np.min(np.abs(targets)) < 1.0:
            continue
        points = [np.linalg.solve(grads[[j for j in range(3) if j != i]],
                                  (targets - offsets)[[j for j in range(3) if j != i]]) for i in range(3)]
        inside = all(np.all(p > LOWER + 0.1) and np.all(p < UPPER - 0.1) for p in points)
        implied = [(offsets[i] + grads[i] @ points[i] - targets[i]) / abs(targets[i]) for i in range(3)]
        if inside and min(abs(v) for v in implied) > 0.05:  # infeasible at a 1 % tolerance
            return offsets, grads, targets, np.array(implied)


def _linear(name, offset, grad) -> Surrogate:
    coef = np.array([offset, grad[0], grad[1], 0.0, 0.0, 0.0])  # Intercept, a, b, a:b, a^2, b^2
    return Surrogate(name, ["a", "b"], quadratic_terms(2), coef, np.zeros((6, 6)), 0.0, 7)


@pytest.mark.parametrize("seed", [3, 4])  # read high, low; each with a larger negative bias elsewhere
def test_the_bottleneck_needs_the_smallest_bias_and_reads_high_or_low_by_its_sign(seed):
    offsets, grads, targets, implied = _case(seed)
    surrogates = {o: _linear(o, offsets[i], grads[i]) for i, o in enumerate(NAMES)}
    domain = Domain(("a", "b"), tuple(LOWER), tuple(UPPER), (False, False))
    result = calibration_check(surrogates, domain, dict(zip(NAMES, targets.tolist())), 0.01, 9)
    assert not result.feasible
    for i, o in enumerate(NAMES):
        assert result.without[o] == pytest.approx(0.0, abs=1e-6)
        assert result.implied_bias[o] == pytest.approx(implied[i], abs=1e-6)
    b = NAMES[int(np.argmin(np.abs(implied)))]
    assert result.bottleneck == b
    said = re.search(r"(\w+) is the bottleneck: without it the others can be met within .*?, and the simulation "
                     r"would then read \1 ([\d.]+) % (high|low)\.", result.message)
    assert said, result.message
    assert said.group(1) == b
    assert float(said.group(2)) == pytest.approx(100 * abs(implied[NAMES.index(b)]), abs=0.051)
    assert said.group(3) == ("high" if implied[NAMES.index(b)] > 0 else "low")

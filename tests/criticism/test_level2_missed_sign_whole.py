"""Level 2's sentence when no point meets every target (criticism.level2._level2_message): the observable it
names as missed worst is the one with the largest error relative to its own tolerance, and "over-" or
"under-predicted" is that observable's sign -- with own tolerances under which the largest plain error is
another observable's, of the other sign, and with one tolerance for all.  Quoted percentages and multiples
parsed back against the errors and tolerances written here."""

from __future__ import annotations

import re

import pytest

from demid.criticism.level2 import Level2Result, _level2_message


def _result(errors, tolerance, tolerances):
    obs = list(errors)
    return Level2Result(
        factors=["a", "b"], observables=obs, targets={o: 1.0 for o in obs}, tolerance=tolerance,
        best_point={"a": 0.25, "b": 3.0}, best_values={o: 1.0 + e for o, e in errors.items()},
        best_errors=dict(errors), best_max_error=max(abs(e) / tolerances.get(o, tolerance) * tolerance
                                                     for o, e in errors.items()),
        feasible=False, reference_point=None, reference_values=None, reference_errors=None, bottleneck=None,
        without={}, implied_bias={}, bias_candidates=[], biased_observable=None,
        shared_bias={"delta": 0.01, "max_error": 0.02}, extensions=[],
        message="", tolerances=dict(tolerances))


CASES = [
    ({"rho": 0.08, "phi": -0.06}, 0.2, {"rho": 0.2, "phi": 0.05}),            # phi: 1.2 tolerances, rho 0.4
    ({"rho": -0.30, "phi": 0.02, "h": 0.1}, 0.1, {"rho": 1.0, "phi": 0.01, "h": 0.2}),   # phi 2, rho 0.3, h 0.5
    ({"y1": -0.5, "y2": 0.45}, 0.1, {"y1": 0.5, "y2": 0.1}),                   # y2 4.5, y1 1
]


@pytest.mark.parametrize("errors,tolerance,tolerances", CASES)
def test_the_worst_relative_to_its_own_tolerance_is_named_with_its_sign(errors, tolerance, tolerances):
    own = {o: tolerances.get(o, tolerance) for o in errors}
    worst = max(errors, key=lambda o: abs(errors[o]) / own[o])
    plain = max(errors, key=lambda o: abs(errors[o]))
    assert plain != worst and (errors[plain] > 0) != (errors[worst] > 0)  # the cases tell the two apart
    text = _level2_message(_result(errors, tolerance, tolerances))
    found = re.search(r"still misses (\S+) by ([\d.]+) % \(([\d.]+) times its tolerance of ([\d.]+) %; "
                      r"(over|under)-predicted\)\.", text)
    assert found, text
    assert found.group(1) == worst
    assert float(found.group(2)) == pytest.approx(100 * abs(errors[worst]), abs=0.006)
    assert float(found.group(3)) == pytest.approx(abs(errors[worst]) / own[worst], rel=0.05)
    assert float(found.group(4)) == pytest.approx(100 * own[worst], abs=0.006)
    assert found.group(5) == ("over" if errors[worst] > 0 else "under")


@pytest.mark.parametrize("errors", [{"rho": 0.08, "phi": -0.12}, {"rho": -0.3, "phi": 0.2, "h": 0.1}])
def test_with_one_tolerance_the_largest_error_is_named_with_its_sign(errors):
    worst = max(errors, key=lambda o: abs(errors[o]))
    text = _level2_message(_result(errors, 0.05, {}))
    found = re.search(r"still misses by ([\d.]+) % \((\S+) (over|under)-predicted\)\.", text)
    assert found, text
    assert float(found.group(1)) == pytest.approx(100 * abs(errors[worst]), abs=0.006)
    assert found.group(2) == worst and found.group(3) == ("over" if errors[worst] > 0 else "under")

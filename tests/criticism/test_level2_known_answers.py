"""Level 2's reported numbers on a case solved by hand.

Two factors a, b on the unit square; y1 = a and y3 = a with targets 0.5 and 0.6 cannot both be met
within 5 % (a in [0.475, 0.525] against [0.57, 0.63]); y2 = b with target 0.437 is met on a whole line.
"""

import numpy as np
import pytest

from demid.criticism.level2 import calibration_check
from demid.design import quadratic_terms
from demid.sampling import Domain
from demid.surrogate import Surrogate


def _linear(name, slope_a, slope_b):
    coef = np.array([0.0, slope_a, slope_b, 0.0, 0.0, 0.0])  # Intercept, a, b, a:b, a^2, b^2
    return Surrogate(name, ["a", "b"], quadratic_terms(2), coef, np.zeros((6, 6)), 0.0, 7)


@pytest.fixture(scope="module")
def result():
    surrogates = {"y1": _linear("y1", 1, 0), "y2": _linear("y2", 0, 1), "y3": _linear("y3", 1, 0)}
    domain = Domain(("a", "b"), (0.0, 0.0), (1.0, 1.0), (False, False))
    return calibration_check(surrogates, domain, {"y1": 0.5, "y2": 0.437, "y3": 0.6}, 0.05, 11)


def test_best_point_balances_the_two_conflicting_targets(result):
    """max(|a - 0.5| / 0.5, |a - 0.6| / 0.6) is smallest where both are equal: a = 6/11, error 1/11."""
    assert not result.feasible
    assert result.best_max_error == pytest.approx(1 / 11, abs=1e-7)
    assert result.best_point["a"] == pytest.approx(6 / 11, abs=1e-6)
    assert result.best_errors["y1"] == pytest.approx(1 / 11, abs=1e-7)
    assert result.best_errors["y3"] == pytest.approx(-1 / 11, abs=1e-7)


def test_implied_biases_are_the_errors_closest_to_zero_where_the_others_are_met(result):
    """Without y2 its target is met anywhere on a = 6/11 (bias 0, b = 0.437 lies between grid nodes);
    without y1 the others pin a = 0.6 (y1's error 0.2); without y3, a = 0.5 (error -1/6)."""
    assert result.implied_bias["y2"] == pytest.approx(0.0, abs=1e-6)
    assert result.implied_bias["y1"] == pytest.approx(0.2, abs=1e-7)
    assert result.implied_bias["y3"] == pytest.approx(-1 / 6, abs=1e-7)
    assert result.without["y1"] == pytest.approx(0.0, abs=1e-7)
    assert result.without["y3"] == pytest.approx(0.0, abs=1e-7)
    assert result.without["y2"] == pytest.approx(1 / 11, abs=1e-7)
    # y1 and y3 tie on the error left without them; the smaller bias names the bottleneck
    assert result.bottleneck == "y3"
    assert result.bias_candidates == ["y1", "y3"] and result.biased_observable is None


def test_shared_bias_and_the_extensions_count_parameters_and_spare_measurements(result):
    """Every prediction is 0 at a = b = 0, so every relative error is -1 there: one shared relative bias of -1
    explains all three targets.  Two factors and three measurements: the calibrated simulation has one spare
    measurement, one added bias none, a bias on every observable two unknowns too many."""
    shared = result.shared_bias
    assert shared["delta"] == pytest.approx(-1.0, abs=1e-7) and shared["max_error"] == pytest.approx(0.0, abs=1e-7)
    assert shared["n_params"] == 3
    rows = {row["model"]: row for row in result.extensions}
    calibrated = rows["simulation as calibrated (no discrepancy)"]
    assert (calibrated["n_params"], calibrated["spare_measurements"]) == (2, 1)
    assert calibrated["note"].startswith("testable: 1 spare")
    assert calibrated["max_error"] == pytest.approx(1 / 11, abs=1e-7)
    one = rows["bias on y3"]
    assert (one["n_params"], one["spare_measurements"]) == (3, 0) and one["note"].startswith("saturated")
    assert one["max_error"] == pytest.approx(0.0, abs=1e-7)
    every = rows["bias on every observable"]
    assert (every["n_params"], every["spare_measurements"]) == (5, -2)
    assert every["note"].startswith("not identifiable")


def test_implied_bias_is_the_deeper_well_when_the_grid_prefers_the_shallower():
    """y2 = 16 (b - 1/4)^2 (b - 7/10)^2 + b/100 cannot reach its target -1; where y1 = a meets 0.5 (any b), the
    bias y2 needs is smallest at the well near b = 1/4 (brute force on a fine grid), although the grid node
    b = 0.7 sits at the bottom of the shallower well and is the grid's best."""
    from numpy.polynomial import polynomial as P

    well = 16 * P.polymul(P.polyfromroots([0.25, 0.25]), P.polyfromroots([0.7, 0.7])) + np.array([0, 0.01, 0, 0, 0])
    terms = [(0, 0), (1, 0)] + [(0, e) for e in range(1, 5)]
    y1 = Surrogate("y1", ["a", "b"], terms, np.array([0.0, 1.0, 0.0, 0.0, 0.0, 0.0]), np.zeros((6, 6)), 0.0, 5)
    y2 = Surrogate("y2", ["a", "b"], terms, np.array([well[0], 0.0, *well[1:]]), np.zeros((6, 6)), 0.0, 5)
    domain = Domain(("a", "b"), (0.0, 0.0), (1.0, 1.0), (False, False))
    result = calibration_check({"y1": y1, "y2": y2}, domain, {"y1": 0.5, "y2": -1.0}, 0.05, 11)
    b = np.linspace(0.0, 1.0, 400_001)
    assert not result.feasible
    assert result.implied_bias["y2"] == pytest.approx(float(np.min(P.polyval(b, well))) + 1.0, abs=1e-8)
    assert result.implied_bias["y1"] == pytest.approx(0.0, abs=1e-8)

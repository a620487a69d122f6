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


def test_an_observable_no_factor_moves_counts_at_its_own_tolerance_in_the_largest_error():
    """y1 = 1.1 everywhere (target 1, its own tolerance 25 %) and y2 = a (target 0.5, the scenario's 5 %): the best
    point meets y2 at a = 0.5; the largest weighted error is y1's 10 % weighted by 5/25, i.e. 0.02, within 5 %.
    The calibration table says y1 is met within its own tolerance, with its plain relative error 0.1."""
    y1 = Surrogate("y1", ["a", "b"], quadratic_terms(2), np.array([1.1, 0, 0, 0, 0, 0.0]), np.zeros((6, 6)), 0.0, 7)
    surrogates = {"y1": y1, "y2": _linear("y2", 1, 0)}
    domain = Domain(("a", "b"), (0.0, 0.0), (1.0, 1.0), (False, False))
    result = calibration_check(surrogates, domain, {"y1": 1.0, "y2": 0.5}, 0.05, 11, tolerances={"y1": 0.25},
                               reference_point={"a": 0.52, "b": 0.3})
    assert result.unmoved == ["y1"]
    assert result.best_point["a"] == pytest.approx(0.5, abs=1e-6)
    assert result.best_max_error == pytest.approx(0.05 / 0.25 * 0.1, abs=1e-9)
    assert result.feasible
    assert result.without["y2"] == pytest.approx(0.02, abs=1e-9)  # y1 alone, weighted
    assert result.without["y1"] == pytest.approx(0.0, abs=1e-7)
    frame = result.to_frame().set_index("observable")
    assert frame.loc["y1", "rel_error_best"] == pytest.approx(0.1, abs=1e-12)
    assert frame.loc["y1", "tolerance"] == 0.25 and frame.loc["y2", "tolerance"] == 0.05
    assert frame["within_tolerance"].to_dict() == {"y1": True, "y2": True}
    # at the reference point a = 0.52: y2 misses 0.5 by 4 % (within 5 %), y1 by its 10 % (within 25 %)
    assert frame["rel_error_reference"].to_dict() == pytest.approx({"y1": 0.1, "y2": 0.04}, abs=1e-12)
    assert frame["within_tolerance_reference"].to_dict() == {"y1": True, "y2": True}
    assert result.reference_max_error == pytest.approx(0.1, abs=1e-12) and result.reference_within
    # y1's 10 % misses a tolerance of 8 %: not within, and the weighted error exceeds the scenario's 5 %
    tighter = calibration_check(surrogates, domain, {"y1": 1.0, "y2": 0.5}, 0.05, 11, tolerances={"y1": 0.08})
    assert tighter.best_max_error == pytest.approx(0.05 / 0.08 * 0.1, abs=1e-9) and not tighter.feasible
    assert tighter.to_frame().set_index("observable")["within_tolerance"].to_dict() == {"y1": False, "y2": True}
    assert tighter.to_frame()["within_tolerance_reference"].isna().all()  # no reference point given


def _well_in_a():
    """y(a) on a in [2, 6] (b in [10, 20] does not enter): u = (a - 2)/4, y = 1 + q(u)/10 with q' ∝ -(u - 0.45)
    (u - 0.55)(u - 0.8)(u - 0.95), q(0.8) = 0, q(0.45) = 1: a narrow well at u = 0.8 reaching the target 1,
    a wide shallow one at the lower end and a local minimum at the upper end, where the grid's start nodes
    lead the local search."""
    from numpy.polynomial import Polynomial
    from numpy.polynomial import polynomial as P

    q = Polynomial(P.polyint(-P.polyfromroots([0.45, 0.55, 0.8, 0.95])))
    q = (q - q(0.8)) / (q(0.45) - q(0.8))
    y_of_a = 1 + 0.1 * q(Polynomial([-0.5, 0.25]))
    terms = [(e, 0) for e in range(len(y_of_a.coef))] + [(0, 1)]
    surrogate = Surrogate("y", ["a", "b"], terms, np.append(y_of_a.coef, 0.0), np.zeros((len(terms),) * 2), 0.0, 5)
    return surrogate, y_of_a


def test_a_thin_set_the_local_search_misses_gives_its_point_nearest_the_searchs_best():
    """The strict set (own tolerance 1 %) is a ∈ [a1, a2] around the narrow well, roots of y = 1.01; the grid of 3
    nodes per axis and SLSQP end at the corner (6, 10).  The exact set says feasible, so the best point is the set's
    point nearest that corner, (a2, 10), where the weighted error is the scenario's 2 % (1 % weighted by 2/1)."""
    from demid.sampling.evaluate import evaluate_set

    surrogate, y_of_a = _well_in_a()
    domain = Domain(("a", "b"), (2.0, 10.0), (6.0, 20.0), (False, False))
    strict = evaluate_set({"y": surrogate}, domain, ("y",), {"y": 1.0}, 0.01, 21)
    roots = (y_of_a - 1.01).roots()
    a1, a2 = sorted(r.real for r in roots if abs(r.imag) < 1e-12 and 2 <= r.real <= 6)[:2]
    np.testing.assert_allclose([strict.lower[0], strict.upper[0]], [a1, a2], atol=1e-7)
    missed = calibration_check({"y": surrogate}, domain, {"y": 1.0}, 0.02, 3, tolerances={"y": 0.01})
    assert not missed.feasible and missed.best_point["a"] == pytest.approx(6.0)  # the search alone misses it
    result = calibration_check({"y": surrogate}, domain, {"y": 1.0}, 0.02, 3, tolerances={"y": 0.01},
                               strict_set=strict)
    assert result.feasible
    assert result.best_point["a"] == pytest.approx(a2, abs=1e-7)
    assert result.best_point["b"] == pytest.approx(10.0, abs=1e-7)
    assert result.best_max_error == pytest.approx(0.02, abs=1e-8)
    assert result.best_errors["y"] == pytest.approx(0.01, abs=1e-8)


def test_a_thin_set_the_local_search_misses_reports_the_largest_error_of_every_observable_there():
    """The thin set of y beside a second observable z, met everywhere (its error at most 0.5 %, weighted 1 %): the
    best point is still y's set's point nearest the search's best, and its largest weighted error is y's 2 %."""
    from demid.sampling.evaluate import evaluate_set

    surrogate, y_of_a = _well_in_a()
    z = Surrogate("z", ["a", "b"], [(0, 0), (0, 1)], np.array([1.0 - 0.005, 0.0005]), np.zeros((2, 2)), 0.0, 5)
    domain = Domain(("a", "b"), (2.0, 10.0), (6.0, 20.0), (False, False))
    surrogates, targets = {"y": surrogate, "z": z}, {"y": 1.0, "z": 1.0}
    strict = evaluate_set(surrogates, domain, ("y", "z"), targets, 0.01, 21)
    roots = (y_of_a - 1.01).roots()
    a2 = sorted(r.real for r in roots if abs(r.imag) < 1e-12 and 2 <= r.real <= 6)[1]
    result = calibration_check(surrogates, domain, targets, 0.02, 3, tolerances={"y": 0.01, "z": 0.01},
                               strict_set=strict)
    assert result.feasible and result.best_point["a"] == pytest.approx(a2, abs=1e-7)
    b = result.best_point["b"]
    assert result.best_errors["z"] == pytest.approx(0.0005 * (b - 10.0), abs=1e-12)
    assert result.best_errors["y"] == pytest.approx(0.01, abs=1e-8)
    assert result.best_max_error == pytest.approx(0.02, abs=1e-8)


def test_implied_bias_is_the_narrow_well_at_the_grids_best_node():
    """y2 = (b - 1/4)^2 (b - 7/10)^2 (1 + 2000 b^6) - b/50 cannot reach its target -1; where y1 = a meets 0.5, the
    smallest bias y2 needs is at the narrow well near b = 0.7 (brute force on a fine grid).  Only the grid node
    b = 0.7 lies in that well; the next best nodes all lie in the wide shallow well near b = 1/4."""
    from numpy.polynomial import polynomial as P

    well = P.polysub(P.polymul(P.polyfromroots([0.25, 0.25, 0.7, 0.7]), [1.0, 0, 0, 0, 0, 0, 2000.0]), [0.0, 0.02])
    degree = len(well) - 1
    terms = [(0, 0), (1, 0)] + [(0, e) for e in range(1, degree + 1)]
    zero = np.zeros((degree + 2, degree + 2))
    y1 = Surrogate("y1", ["a", "b"], terms, np.array([0.0, 1.0] + [0.0] * degree), zero, 0.0, 5)
    y2 = Surrogate("y2", ["a", "b"], terms, np.array([well[0], 0.0, *well[1:]]), zero, 0.0, 5)
    domain = Domain(("a", "b"), (0.0, 0.0), (1.0, 1.0), (False, False))
    nodes = np.linspace(0.0, 1.0, 21)
    by_value = nodes[np.argsort(P.polyval(nodes, well))]
    assert by_value[0] == pytest.approx(0.7) and np.all(np.abs(by_value[1:6] - 0.25) <= 0.1 + 1e-9)  # premise
    result = calibration_check({"y1": y1, "y2": y2}, domain, {"y1": 0.5, "y2": -1.0}, 0.05, 21)
    b = np.linspace(0.0, 1.0, 400_001)
    assert not result.feasible
    assert result.implied_bias["y2"] == pytest.approx(float(np.min(P.polyval(b, well))) + 1.0, abs=1e-8)

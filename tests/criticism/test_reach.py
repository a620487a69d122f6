"""Reachability beyond a bound: level 2 and the advice say "widen" only where the surrogate's extrapolation
reaches the target band soon after the bound; a surrogate that levels off, or needs a far extension, is said to
saturate and gets recalibrate advice instead.  Closed-form quadratics in x on [0, 1] (w does nothing)."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from demid.criticism import calibration_check
from demid.criticism.reach import WIDEN_LIMIT, Reach, smallest_positive_root, reach_beyond_bound, saturation_advice
from demid.design import quadratic_terms
from demid.sampling.domain import Domain
from demid.spec import MaterialSpec
from demid.story import material_advice
from demid.surrogate import Surrogate

DOMAIN = Domain(("x", "w"), (0.0, 0.0), (1.0, 1.0))
TOL = 0.02


def _quadratic(b0: float, b1: float, b11: float) -> Surrogate:
    """y = b0 + b1 x + b11 x²."""
    terms = quadratic_terms(2)
    coef = np.zeros(len(terms))
    coef[0], coef[1], coef[4] = b0, b1, b11
    return Surrogate("y", ["x", "w"], terms, coef, np.zeros((len(terms), len(terms))), 0.0, 7)


def _target(edge: float) -> float:
    """The target whose lower tolerance-band edge is ``edge`` (the response is under-predicted)."""
    return edge / (1 - TOL)


def _check(surrogate, target):
    return calibration_check({"y": surrogate}, DOMAIN, {"y": target}, TOL, 21)


def _advice(level2: dict):
    spec = MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "custom"},
        "factors": {"x": {"lower": 0.0, "upper": 1.0}, "w": {"lower": 0.0, "upper": 1.0}},
        "responses": {"y": {"target": level2["targets"]["y"], "unit": "mm"}},
        "scenarios": {"s": {"observables": ["y"], "tolerance": TOL}}}, grid_points=21)
    return material_advice(spec, pd.DataFrame(columns=["scenario", "factor", "verdict"]), criticism={"level2": level2})


def test_a_surrogate_that_levels_off_below_the_target_is_said_to_saturate_and_not_widened():
    # y = 10 + 12x - 4x²: 18 at the bound, slope 4, stationary at x = 1.5 where y = 19 < 24.5
    result = _check(_quadratic(10, 12, -4), _target(24.5))
    assert result.best_point["x"] == pytest.approx(1.0) and result.best_at_bound["x"] == "upper"
    (reach,) = result.reach
    assert reach.slope == pytest.approx(4.0, rel=1e-6) and reach.curvature == pytest.approx(-8.0, rel=1e-4)
    assert reach.levels_off and not reach.widen
    assert reach.levels_off_factor_value == pytest.approx(1.5, rel=1e-6)
    assert reach.levels_off_value == pytest.approx(19.0, rel=1e-6)
    assert reach.straight_extension == pytest.approx(6.5 / 4, rel=1e-6)  # the straight line would (at x = 2.625)
    assert result.widen == {} and "Widen" not in result.message
    assert "levels off at 19 (x ≈ 1.5)" in result.message and "saturates along x" in result.message
    assert "saturates along x" in result.finding
    advice = _advice(result.to_json())
    assert not [i for i in advice if i.kind == "widen"]
    (item,) = [i for i in advice if i.factor == "x"]
    assert item.kind == "recalibrate" and item.bound == "upper" and item.observable == "y"
    assert "another mechanism in the model" in item.text and "The missing 7 mm of y" in item.text
    assert "Do not widen x for y = 25 mm: at the bound y gains only 4 mm per unit x" in item.text
    assert "a straight line would reach the target band at x ≈ 2.625" in item.text  # target 25, 18 at the bound


def test_a_small_extension_keeps_the_widen_advice():
    # y = 10 + 8x + 2x²: at the bound 20, slope 12; 21 is reached at 2t² + 12t - 1 = 0 beyond it
    result = _check(_quadratic(10, 8, 2), _target(21.0))
    (reach,) = result.reach
    assert reach.widen and not reach.levels_off
    assert reach.quadratic_extension == pytest.approx((-12 + np.sqrt(152)) / 4, rel=1e-6)
    assert reach.straight_extension == pytest.approx(1 / 12, rel=1e-6)
    assert result.widen == {"x": ["upper"]} and "Widen the range of x" in result.message
    assert [(i.kind, i.factor, i.bound) for i in _advice(result.to_json()) if i.factor == "x"] == [
        ("widen", "x", "upper")]


def test_a_straight_response_reaches_the_band_where_its_line_does():
    # y = 10 + 8x: 18 at the bound, slope 8; the band edge 19 is 1/8 of the range beyond it (x = 1.125)
    result = _check(_quadratic(10, 8, 0), _target(19.0))
    (reach,) = result.reach
    assert reach.widen and not reach.levels_off
    assert reach.quadratic_extension == pytest.approx(0.125, rel=1e-6)
    assert reach.quadratic_factor_value == pytest.approx(1.125, rel=1e-6)
    # the root of b t + c = 0 (no t^2 term) when it is positive, none otherwise
    assert smallest_positive_root(0.0, 8.0, -1.0) == pytest.approx(0.125)
    assert smallest_positive_root(0.0, 8.0, -12.0) == pytest.approx(1.5)
    assert smallest_positive_root(0.0, 8.0, 1.0) == np.inf and smallest_positive_root(0.0, 0.0, -1.0) == np.inf


def test_a_band_edge_just_below_where_the_response_levels_off_is_reached():
    # y = 10 + 12x - 4x²: 18 at the bound, levels off at 19 (x = 1.5); the band edge 18.95 is reached where
    # -4t² + 4t - 0.95 = 0, t = (4 - sqrt(0.8)) / 8 (a discriminant below one, not below zero)
    result = _check(_quadratic(10, 12, -4), _target(18.95))
    (reach,) = result.reach
    t = (4 - np.sqrt(0.8)) / 8
    assert reach.quadratic_extension == pytest.approx(t, rel=1e-6) and reach.widen and not reach.levels_off
    assert reach.quadratic_factor_value == pytest.approx(1 + t, rel=1e-6)
    assert smallest_positive_root(-1.0, 1.0, -0.2) == pytest.approx((1 - np.sqrt(0.2)) / 2)
    assert smallest_positive_root(-1.0, 1.0, -0.3) == np.inf  # discriminant -0.2: never


def test_a_huge_extension_is_not_advised_as_widen():
    # y = 10 + x: at the bound 11, slope 1; the band edge 13 needs x = 3, twice the range beyond the bound
    result = _check(_quadratic(10, 1, 0), _target(13.0))
    (reach,) = result.reach
    assert not reach.widen and not reach.levels_off
    assert reach.quadratic_extension == pytest.approx(2.0, rel=1e-6) and reach.quadratic_extension > WIDEN_LIMIT
    assert reach.quadratic_factor_value == pytest.approx(3.0, rel=1e-6)
    assert result.widen == {} and "Widen" not in result.message
    assert "only at x ≈ 3, 200 % of the range beyond the bound" in result.message
    kinds = [(i.kind, i.factor) for i in _advice(result.to_json())]
    assert ("widen", "x") not in kinds and ("recalibrate", "x") in kinds


def test_the_lower_bound_and_a_falling_response_mirror_the_upper_one():
    # y = 18 - 4x - 4x²: 18 at the lower bound x = 0, rising as x falls, stationary at x = -0.5 (y = 19 < 24.5)
    result = _check(_quadratic(18, -4, -4), _target(24.5))
    (reach,) = result.reach
    assert reach.side == "lower" and reach.levels_off and not reach.widen
    assert reach.levels_off_factor_value == pytest.approx(-0.5, rel=1e-6)
    assert reach.slope == pytest.approx(-4.0, rel=1e-6)  # d y / d x at the bound: y rises as x falls
    # over-predicted: y = 20 - x on [0, 1] is 19 at best (x = 1); the band's upper edge 17 needs x = 3
    high = _check(_quadratic(20, -1, 0), 17.0 / (1 + TOL))
    (reach,) = high.reach
    assert reach.side == "upper" and reach.quadratic_factor_value == pytest.approx(3.0, rel=1e-6) and not reach.widen


def test_reach_round_trips_through_json():
    r = reach_beyond_bound(_quadratic(10, 12, -4), DOMAIN, "x", "upper", {"x": 1.0, "w": 0.3}, "y", 25.0, TOL)
    again = Reach.from_json(r.to_json())
    assert again.levels_off == r.levels_off and again.quadratic_extension == np.inf
    assert again.levels_off_value == pytest.approx(r.levels_off_value)


def test_a_log_factor_is_followed_in_decades():
    # y = 10 + 4 log10(x) on x in [0.01, 1] (log scale): 10 at the upper bound, 4 per decade; the band edge
    # 11 needs a quarter of a decade, i.e. 12.5 % of the two-decade range: widen, at x = 10^0.25
    domain = Domain(("x", "w"), (0.01, 0.0), (1.0, 1.0), log=(True, False))
    terms = quadratic_terms(2)
    coef = np.zeros(len(terms))
    coef[0], coef[1] = 10.0, 4.0
    sur = Surrogate("y", ["x", "w"], terms, coef, np.zeros((len(terms), len(terms))), 0.0, 7, log_factors=("x",))
    r = reach_beyond_bound(sur, domain, "x", "upper", {"x": 1.0, "w": 0.5}, "y", _target(11.0), TOL)
    assert r.log and r.slope == pytest.approx(4.0, rel=1e-6) and r.widen
    assert r.quadratic_extension == pytest.approx(0.125, rel=1e-6)
    assert r.quadratic_factor_value == pytest.approx(10 ** 0.25, rel=1e-6)
    # the band edge 20 needs 2.5 decades beyond the bound: not widened, said per decade
    far = reach_beyond_bound(sur, domain, "x", "upper", {"x": 1.0, "w": 0.5}, "y", _target(20.0), TOL)
    assert not far.widen and "gains only 4 per decade of x" in saturation_advice(far, "x", "y")


def test_the_heap_without_rolling_friction_is_not_advised_to_widen_sliding_friction():
    """The Kratos heap without rolling friction (examples/dem_heap): the best point sits on μ_s's upper bound, 18.3°
    against 24°; the runs at μ_s = 1.2 and 1.5 (17.5°, 17.6°) show that widening would not help, and the fitted
    quadratic needs μ_s ≈ 1.58, 85 % of the range beyond the bound: no widening."""
    from pathlib import Path

    from demid.surrogate import fit_response

    table = pd.read_csv(Path(__file__).resolve().parents[2] / "examples" / "dem_heap" / "data" / "no_rolling.csv")
    sur = fit_response(table, ["mu_s", "e"], "angle_of_repose", alpha=1.41421).surrogate()
    domain = Domain(("mu_s", "e"), (0.1, 0.2), (0.9, 0.8))
    result = calibration_check({"angle_of_repose": sur}, domain, {"angle_of_repose": 24.0}, 0.04, 41)
    assert not result.feasible and result.best_at_bound["mu_s"] == "upper"
    (reach,) = [r for r in result.reach if r.factor == "mu_s"]
    assert not reach.widen and reach.quadratic_extension > WIDEN_LIMIT
    assert "mu_s" not in result.widen and "Widen the range of mu_s" not in result.message


@pytest.mark.parametrize("value", [-3e6, -1.0, 0.2, 5e4])
def test_an_observable_is_flat_along_a_factor_when_it_changes_by_a_billionth_of_its_size(value):
    """Flat: |slope| + |curvature| at most 1e-9 of |value| (or of 1 for values below 1): relative for large values,
    absolute for small ones."""
    import dataclasses

    size = max(1.0, abs(value))
    base = Reach("a", "upper", "y", value, 2.0 * value, 1.9 * value, 0.0, 0.0, np.inf, np.inf, np.inf, np.nan,
                 np.nan, np.nan, np.nan, False)
    for slope, curvature, flat in ((0.4e-9 * size, 0.5e-9 * size, True), (0.7e-9 * size, -0.7e-9 * size, False),
                                   (0.0, 0.0, True), (-2e-9 * size, 0.0, False)):
        assert dataclasses.replace(base, slope=slope, curvature=curvature).flat is flat

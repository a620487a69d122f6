"""Per-observable tolerances: the rescaled surrogate holds exactly the points of the observable's own band.

Known answers: the band |y - y*| <= a is checked point by point on the original surrogate (numpy, no
demid set code), and the rescaled polynomial's coefficients, covariance and residual variance against
c = eps |y*| / a written out by hand.
"""

from types import SimpleNamespace

import numpy as np
import pandas as pd
import pytest

from demid.design import quadratic_terms
from demid.surrogate import Surrogate
from demid.scenario import scenario_bands
from demid.tolerance import band_scale, observable_band, rescaled_surrogate, scenario_grid, scenario_surrogates


def _response(name, target, tolerance=None, tolerance_abs=None, sigma=None, sigma_rel=None, discrepancy=None):
    return SimpleNamespace(name=name, target=target, tolerance=tolerance, tolerance_abs=tolerance_abs,
                           sigma=sigma, sigma_rel=sigma_rel, discrepancy=discrepancy,
                           sigma_config={"sigma": sigma, "sigma_rel": sigma_rel})


def _spec(*responses):
    return SimpleNamespace(responses=list(responses), targets={r.name: r.target for r in responses},
                           response=lambda name: next(r for r in responses if r.name == name))


def _surrogate(name="y"):
    # y = 1 + 2a - b + 0.5ab + 3a^2 - b^2 on two factors, with a non-trivial covariance
    coef = np.array([1.0, 2.0, -1.0, 0.5, 3.0, -1.0])
    cov = np.diag([0.1, 0.2, 0.3, 0.05, 0.4, 0.25]) + 0.01
    return Surrogate(name, ["a", "b"], quadratic_terms(2), coef, cov, 0.7, 5)


@pytest.mark.parametrize("target", [4.0, -4.0])
def test_band_half_widths_in_response_units(target):
    assert observable_band(_response("y", target, tolerance_abs=0.5), target, 0.1) == 0.5
    assert observable_band(_response("y", target, tolerance=0.2), target, 0.1) == pytest.approx(0.8)
    assert observable_band(_response("y", target), target, 0.1) == pytest.approx(0.4)
    assert band_scale(_response("y", target, tolerance_abs=0.5), target, 0.1) == pytest.approx(0.1 * 4 / 0.5)
    assert band_scale(_response("y", target, tolerance=0.05), target, 0.1) == pytest.approx(2.0)
    assert band_scale(_response("y", target), target, 0.1) == 1.0


@pytest.mark.parametrize("target, own", [(4.0, 0.5), (-3.0, 1.2)])
def test_rescaled_surrogate_meets_the_scenario_band_exactly_where_the_own_band_holds(target, own):
    eps = 0.1
    surrogate = _surrogate()
    c = eps * abs(target) / own
    scaled = rescaled_surrogate(surrogate, target, c)
    x = np.random.default_rng(3).uniform(-2.0, 2.0, size=(4000, 2))
    y = surrogate.predict(x)
    np.testing.assert_allclose(scaled.predict(x), target + c * (y - target), rtol=1e-12, atol=1e-12)
    inside_own = np.abs(y - target) <= own
    inside_scaled = np.abs(scaled.predict(x) - target) <= eps * abs(target)
    margin = np.abs(np.abs(y - target) - own) > 1e-9  # away from the band's edge, where round-off decides
    assert inside_own.any() and (~inside_own).any()
    assert np.array_equal(inside_own[margin], inside_scaled[margin])
    np.testing.assert_allclose(scaled.covariance, c ** 2 * surrogate.covariance)
    assert scaled.resid_var == pytest.approx(c ** 2 * 0.7)
    np.testing.assert_allclose(scaled.se_mean(x[:5]), c * surrogate.se_mean(x[:5]), rtol=1e-12)
    assert rescaled_surrogate(surrogate, target, 1.0) is surrogate


def test_scenario_surrogates_and_grid_rescale_only_the_observables_with_their_own_band():
    eps = 0.1
    spec = _spec(_response("y", 4.0, tolerance_abs=0.5), _response("z", 2.0))
    surrogates = {"y": _surrogate("y"), "z": _surrogate("z")}
    out = scenario_surrogates(surrogates, spec, eps)
    assert out["z"] is surrogates["z"]
    x = np.array([[0.3, -0.2], [1.0, 1.0]])
    c = eps * 4.0 / 0.5
    np.testing.assert_allclose(out["y"].predict(x), 4.0 + c * (surrogates["y"].predict(x) - 4.0))
    grid = pd.DataFrame({"y": surrogates["y"].predict(x), "z": surrogates["z"].predict(x)})
    moved = scenario_grid(grid, spec, eps)
    np.testing.assert_allclose(moved["y"], 4.0 + c * (grid["y"] - 4.0))
    np.testing.assert_allclose(moved["z"], grid["z"])
    np.testing.assert_allclose(grid["y"], surrogates["y"].predict(x))  # the caller's frame is not modified
    # a grid of other responses only (one observable set's columns) is left as it is
    only_z = grid[["z"]]
    np.testing.assert_allclose(scenario_grid(only_z, spec, eps)["z"], grid["z"])
    plain = _spec(_response("y", 4.0), _response("z", 2.0))
    assert scenario_surrogates(surrogates, plain, eps) is surrogates
    assert scenario_grid(grid, plain, eps) is grid


def test_measurement_bands_scale_with_the_own_band():
    eps = 0.1
    spec = _spec(_response("y", 4.0, tolerance_abs=0.5, sigma=0.2, discrepancy=0.3),
                 _response("z", -2.0, sigma_rel=0.05), _response("w", 1.0))
    bands = scenario_bands(spec, ["y", "z", "w"], eps)
    c = eps * 4.0 / 0.5
    assert bands["y"].sigma == pytest.approx(c * 0.2) and bands["y"].discrepancy == pytest.approx(c * 0.3)
    assert bands["z"].sigma == pytest.approx(0.05 * 2.0) and bands["z"].discrepancy == 0.0
    assert "w" not in bands


def test_a_discrepancy_without_a_sigma_still_gets_its_band():
    spec = _spec(_response("y", 4.0, tolerance_abs=0.5, discrepancy=0.3))
    band = scenario_bands(spec, ["y"], 0.1)["y"]
    assert band.sigma is None and band.discrepancy == pytest.approx(0.1 * 4.0 / 0.5 * 0.3)


def test_plausible_basis_names_each_source_of_the_band():
    from demid.scenario import plausible_basis

    plain = _spec(_response("y", 4.0))
    assert plausible_basis(plain, "y").startswith("no sigma configured")
    rich = _spec(SimpleNamespace(**vars(_response("y", 4.0, tolerance_abs=0.5, sigma=0.2, discrepancy=0.3)),
                                 unit="mm"))
    text = plausible_basis(rich, "y")
    assert text == "config sigma = 0.2; own tolerance ±0.5 mm; discrepancy δ = 0.3"
    relative = _spec(SimpleNamespace(**vars(_response("y", 4.0, tolerance=0.05)), unit="-"))
    assert plausible_basis(relative, "y").endswith("; own tolerance 0.05")


def test_own_tolerances_equal_to_the_scenarios_to_round_off_are_the_same_tolerance():
    from demid.tolerance import same_tolerances

    assert same_tolerances(0.05, {"a": 0.05, "b": 0.05 * (1 + 1e-13)}) and same_tolerances(0.05, {})
    assert same_tolerances(0.05, None)
    assert not same_tolerances(0.05, {"a": 0.05, "b": 0.02})
    assert not same_tolerances(0.05, {"a": 0.05 * (1 + 1e-9)})

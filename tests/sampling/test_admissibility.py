"""Admissible sets against closed forms: circular level sets give annuli and disks."""

import numpy as np
import pytest

from demid.admissibility import Domain, admissible_set, predict_grid
from demid.design import quadratic_terms
from demid.surrogate import Surrogate

TERMS = quadratic_terms(2)  # Intercept, a, b, a:b, a^2, b^2


def radius_squared(center=(0.0, 0.0)):
    """y = (a - a0)^2 + (b - b0)^2 as a quadratic surrogate: level sets are circles."""
    a0, b0 = center
    coef = np.array([a0**2 + b0**2, -2 * a0, -2 * b0, 0.0, 1.0, 1.0])
    return Surrogate("r2", ["a", "b"], TERMS, coef, np.zeros((6, 6)), 0.0, 7)


DOMAIN = Domain(("a", "b"), (-1.0, -1.0), (1.0, 1.0))


@pytest.mark.parametrize("fraction", [1e-2, 1e-3, 1e-4])
def test_annulus_fraction_exact_within_2_percent(fraction):
    # Target T = r0^2, tolerance eps: annulus r^2 in [T(1-eps), T(1+eps)], area = 2*pi*T*eps.
    target = 0.3
    eps = fraction * DOMAIN_AREA / (2 * np.pi * target)
    result = admissible_set({"r2": radius_squared()}, DOMAIN, ["r2"], {"r2": target}, eps, 1001)
    assert result.fraction == pytest.approx(fraction, rel=0.02)
    outer = np.sqrt(target * (1 + eps))
    assert result.lower == pytest.approx([-outer, -outer], abs=2e-3)
    assert result.width == pytest.approx([2 * outer, 2 * outer], abs=4e-3)


DOMAIN_AREA = 4.0


def test_disk_fraction_and_span_off_centre():
    # A disk of radius 0.2 around (0.3, -0.4): r^2 <= 0.04, i.e. |r^2 - 0.02| <= 0.02 * 1.0 (eps = 1).
    sur = radius_squared((0.3, -0.4))
    result = admissible_set({"r2": sur}, DOMAIN, ["r2"], {"r2": 0.02}, 0.999999, 401)
    assert result.fraction == pytest.approx(np.pi * 0.04 / 4, rel=0.01)
    assert result.lower == pytest.approx([0.1, -0.6], abs=0.006)
    assert result.upper == pytest.approx([0.5, -0.2], abs=0.006)


def test_empty_set_gives_zero_fraction_and_nan_bounds():
    result = admissible_set({"r2": radius_squared()}, DOMAIN, ["r2"], {"r2": 5.0}, 0.01, 101)
    assert result.fraction == 0.0 and result.empty
    assert np.isnan(result.lower).all() and np.isnan(result.width).all()
    assert result.best_error == pytest.approx((5.0 - 2.0) / 5.0)


def test_intersection_of_two_observables_is_smaller():
    a = radius_squared((0.0, 0.0))
    b = radius_squared((0.5, 0.0))
    sur = {"p": a, "q": b}
    one = admissible_set(sur, DOMAIN, ["p"], {"p": 0.25, "q": 0.25}, 0.05, 501)
    two = admissible_set(sur, DOMAIN, ["p", "q"], {"p": 0.25, "q": 0.25}, 0.05, 501)
    assert 0 < two.fraction < one.fraction
    assert np.all(two.mask <= one.mask)


def test_log_scale_factor_grid_is_log_spaced():
    dom = Domain(("a", "g"), (0.0, 0.001), (1.0, 0.1), (False, True))
    axes = dom.axes(3)
    assert axes[1] == pytest.approx([0.001, 0.01, 0.1])
    sur = Surrogate("y", ["a", "g"], TERMS, np.array([0, 0, 1.0, 0, 0, 0]), np.zeros((6, 6)), 0.0, 7,
                    log_factors=("g",))
    grid = predict_grid({"y": sur}, dom, 3)
    assert grid["y"].to_numpy()[:3] == pytest.approx([-3, -2, -1])
    # y = log10(g) in [-2.2, -1.8]: fraction of the log axis (-3..-1) = 0.4 / 2 = 0.2
    result = admissible_set({"y": sur}, dom, ["y"], {"y": -2.0}, 0.1, 201)
    assert result.fraction == pytest.approx(0.2, rel=0.01)
    assert result.lower[1] == pytest.approx(10 ** -2.2, rel=0.01)


def test_unit_cube_coordinates_of_a_linear_and_a_log_factor():
    """a in [2, 4] (linear), b in [10, 1000] (log): a = 3, b = 100 is the cube's centre; a = 2.5, b = 10^1.5 a
    quarter of each range; from_unit goes back."""
    domain = Domain(("a", "b"), (2.0, 10.0), (4.0, 1000.0), log=(False, True))
    points = np.array([[3.0, 100.0], [2.5, 10 ** 1.5], [4.0, 10.0]])
    unit = domain.to_unit(points)
    np.testing.assert_allclose(unit, [[0.5, 0.5], [0.25, 0.25], [1.0, 0.0]], atol=1e-12)
    np.testing.assert_allclose(domain.from_unit(unit), points, rtol=1e-12)

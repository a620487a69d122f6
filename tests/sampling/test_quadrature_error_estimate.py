"""The exact set's quadrature and its error estimate, against independent computations.

``fraction_error`` is reported next to every exact fraction; it is built from QUADPACK's
Gauss-Kronrod 7-15 estimate of each piece.  Here one piece is integrated in one round and its
integral, its Gauss companion and its estimate are recomputed from Gauss-Legendre nodes
(numpy) and scipy's adaptive quadrature, with the same change of variable.
"""

import numpy as np
import pytest
from scipy import integrate

from demid.sampling import quadrature


def _substituted(f, v):
    """f(s(v)) s'(v) for s = (1 - cos(pi v)) / 2 on [0, 1]."""
    s = (1 - np.cos(np.pi * v)) / 2
    return f(s) * np.pi / 2 * np.sin(np.pi * v)


@pytest.mark.parametrize("name, f, exact", [
    ("exp", lambda s: np.exp(4 * s), (np.exp(4) - 1) / 4),
    ("runge", lambda s: 1 / (1 + 25 * (2 * s - 1) ** 2), np.arctan(5) / 5),
    ("oscillating", lambda s: np.cos(30 * s), np.sin(30) / 30),
])
def test_one_piece_estimate_is_quadpacks_formula(name, f, exact):
    """With a loose tolerance one round is accepted: the integral is the 15-point Kronrod value and the
    estimate is v * min(1, (200 |K - G| / v) ** 1.5), v = the integral of |f - mean f| over the piece."""
    total, error = quadrature.integrate(lambda owner, s: f(s)[:, None], [0], [0.0], [1.0], 1, rtol=10.0)
    kronrod = float(total[0, 0])
    # the 7-point Gauss rule on the substituted integrand, from numpy's Legendre nodes
    x, w = np.polynomial.legendre.leggauss(7)
    gauss = float(np.sum(w / 2 * _substituted(f, (x + 1) / 2)))
    # Kronrod 15 integrates what Gauss 7 gets wrong more closely: both near the exact value
    assert abs(kronrod - exact) <= abs(gauss - exact) + 1e-12
    variation = integrate.quad(lambda s: abs(f(s) - kronrod), 0.0, 1.0, limit=200, points=None)[0]
    expected = variation * min(1.0, (200 * abs(kronrod - gauss) / variation) ** 1.5)
    assert error[0] == pytest.approx(expected, rel=0.05)


def test_error_estimate_bounds_the_true_error_on_each_owner():
    """Several owners at once, tight tolerance: each integral within its reported error of the exact value,
    and each error small."""
    funcs = [lambda s: np.exp(4 * s), lambda s: np.sqrt(s), lambda s: np.abs(s - 0.3)]
    exact = np.array([(np.exp(4) - 1) / 4, 2 / 3, 0.5 * (0.09 + 0.49)])

    def func(owner, s):
        return np.select([owner == 0, owner == 1, owner == 2], [f(s) for f in funcs])[:, None]

    total, error = quadrature.integrate(func, [0, 1, 2], [0.0] * 3, [1.0] * 3, 3, rtol=1e-9)
    assert np.all(np.abs(total[:, 0] - exact) <= error + 1e-15)
    assert np.all(error <= 1e-8 * exact)


@pytest.mark.parametrize("target, tolerance", [(0.04, 0.5), (0.09, 0.2)])
def test_a_two_factor_fraction_error_adds_both_integrations_estimates_and_their_difference(target, tolerance):
    """In two factors the set is integrated twice, along each axis (each with its Gauss-Kronrod estimate, checked
    above): the fraction is the first integral, its error the sum of both estimates and of the difference between
    the two integrals.  The annulus y = (a - 1/2)^2 + (b - 1/2)^2 within a tolerance of t has the area
    pi t 2 tolerance: both integrals lie within their own estimates of it."""
    from demid.design import quadratic_terms
    from demid.sampling import Domain
    from demid.sampling.evaluate import evaluate_set
    from demid.surrogate import Surrogate

    coef = np.array([0.5, -1.0, -1.0, 0.0, 1.0, 1.0])  # Intercept, a, b, a:b, a^2, b^2
    sur = Surrogate("y", ["a", "b"], quadratic_terms(2), coef, np.zeros((6, 6)), 0.0, 7)
    domain = Domain(("a", "b"), (0.0, 0.0), (1.0, 1.0), (False, False))
    exact = evaluate_set({"y": sur}, domain, ("y",), {"y": target}, tolerance, 101).exact
    (along0,), (err0,) = exact._shape.integral(0)
    (along1,), (err1,) = exact._shape.integral(1)
    area = np.pi * target * 2 * tolerance
    assert abs(along0 - area) <= err0 + 1e-15 and abs(along1 - area) <= err1 + 1e-15
    assert err0 > 0 and err1 > 0 and along0 != along1  # premise: every part of the sum counts
    assert exact.fraction == along0
    assert exact.fraction_error == pytest.approx(err0 + err1 + abs(along0 - along1), rel=1e-12, abs=0.0)


@pytest.mark.parametrize("eps", [1e-2, 1e-3])
def test_one_piece_estimate_is_quadpacks_formula_to_a_thousandth(eps):
    """An integrand whose spread about its mean is smooth: f = 2 + (s - 1/2) |s - 1/2| + eps cos(10 s), so that
    |f - mean| is (s - 1/2)^2 but for a kink of order eps^1.5, and the 15-point sum of it is its integral to a few
    1e-5; with 200 |K - G| / v well below 1 the estimate v (200 |K - G| / v) ** 1.5 is then checked to 1e-3."""
    def f(s):
        return 2.0 + (s - 0.5) * np.abs(s - 0.5) + eps * np.cos(10.0 * s)

    total, error = quadrature.integrate(lambda owner, s: f(s)[:, None], [0], [0.0], [1.0], 1, rtol=10.0)
    kronrod = float(total[0, 0])
    x, w = np.polynomial.legendre.leggauss(7)
    gauss = float(np.sum(w / 2 * _substituted(f, (x + 1) / 2)))
    variation = integrate.quad(lambda s: abs(f(s) - kronrod), 0.0, 1.0, limit=400, epsabs=1e-14, epsrel=1e-12)[0]
    ratio = 200 * abs(kronrod - gauss) / variation
    assert 1e-3 < ratio < 0.5
    assert error[0] == pytest.approx(variation * ratio ** 1.5, rel=1e-3)

"""The exact evaluator's reported fraction error, over generated integrands and sets: QUADPACK's estimate where
the Gauss and Kronrod rules nearly agree (the regime of every converged piece), that it bounds the true error of
a set whose area or volume is known, and that it is no larger than the accuracy the quadrature was asked for."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import integrate

from demid.design import quadratic_terms
from demid.sampling import Domain
from demid.sampling.evaluate import evaluate_set
from demid.sampling.planes import OUTER_RTOL, QUADRATURE_RTOL
from demid.sampling.quadrature import integrate as integrate_pieces
from demid.surrogate import Surrogate


def _substituted(f, v):
    s = (1 - np.cos(np.pi * v)) / 2
    return f(s) * np.pi / 2 * np.sin(np.pi * v)


@given(kind=st.sampled_from(["exp", "inverse", "root"]), k=st.floats(0.5, 3.0))
@settings(max_examples=20, deadline=None, derandomize=True)
def test_a_smooth_pieces_estimate_is_quadpacks_scaled_difference(kind, k):
    """One piece, accepted in one round: the estimate is v·(200|K − G|/v)^1.5 with v the integrand's variation
    about its mean, here with 200|K − G|/v below 1 (the power matters; above 1 the estimate is v itself)."""
    f = {"exp": lambda s: np.exp(k * s), "inverse": lambda s: 1 / (k + s), "root": lambda s: np.sqrt(s + k / 10)}[kind]
    total, error = integrate_pieces(lambda owner, s: f(s)[:, None], [0], [0.0], [1.0], 1, rtol=10.0)
    kronrod = float(total[0, 0])
    x, w = np.polynomial.legendre.leggauss(7)
    gauss = float(np.sum(w / 2 * _substituted(f, (x + 1) / 2)))
    variation = integrate.quad(lambda s: abs(f(s) - kronrod), 0.0, 1.0, limit=200)[0]
    ratio = 200 * abs(kronrod - gauss) / variation
    assert ratio < 1  # premise
    floor = 50 * np.finfo(float).eps * abs(kronrod)
    assert error[0] == pytest.approx(max(variation * ratio ** 1.5, floor), rel=0.05)


def _ball_surrogate(d: int, centre) -> Surrogate:
    """y = Σ (x_i − c_i)²: its set |y − t| ≤ ε t is a shell of radii √(t(1 ∓ ε))."""
    terms = quadratic_terms(d)
    coef = np.zeros(len(terms))
    for i, term in enumerate(terms):
        powers = [int(p) for p in term]
        if sum(powers) == 0:
            coef[i] = float(np.sum(np.square(centre)))
        elif sum(powers) == 1:
            coef[i] = -2.0 * centre[powers.index(1)]
        elif max(powers) == 2:
            coef[i] = 1.0
    names = list("abc"[:d])
    return Surrogate("y", names, terms, coef, np.zeros((len(terms), len(terms))), 0.0, 20)


@given(d=st.sampled_from([2, 2, 3]), target=st.floats(0.01, 0.1), tolerance=st.floats(0.05, 0.5),
       shift=st.floats(-0.05, 0.05))
@settings(max_examples=8, deadline=None, derandomize=True)
def test_the_reported_fraction_error_bounds_the_true_error_and_no_more_than_asked(d, target, tolerance, shift):
    centre = np.full(d, 0.5 + shift)
    domain = Domain(tuple("abc"[:d]), (0.0,) * d, (1.0,) * d, (False,) * d)
    exact = evaluate_set({"y": _ball_surrogate(d, centre)}, domain, ("y",), {"y": target}, tolerance, 41).exact
    inner, outer = np.sqrt(target * (1 - tolerance)), np.sqrt(target * (1 + tolerance))
    assert outer < 0.5 - abs(shift)  # premise: the shell lies inside the box
    known = np.pi * (outer ** 2 - inner ** 2) if d == 2 else 4 / 3 * np.pi * (outer ** 3 - inner ** 3)
    assert abs(exact.fraction - known) <= exact.fraction_error + 1e-15
    if d == 2:
        # each of the two integrations meets its relative tolerance; the error adds both and their difference
        (along0,), _ = exact._shape.integral(0)
        (along1,), _ = exact._shape.integral(1)
        asked = 2 * QUADRATURE_RTOL * exact.fraction + abs(along0 - along1)
    else:
        # the outer quadrature meets its tolerance over slices whose areas meet theirs
        asked = (OUTER_RTOL + QUADRATURE_RTOL) * exact.fraction
    assert exact.fraction_error <= asked * (1 + 1e-9) + 1e-15


def test_a_volumes_error_is_the_outer_estimate_plus_the_slices_errors_integrated():
    """In three factors the volume is integrated over slices: its error is the outer quadrature's estimate plus
    the slices' own error estimates integrated over the slices (scipy's quad here, as a function of the slice)."""
    domain = Domain(("a", "b", "c"), (0.0,) * 3, (1.0,) * 3, (False,) * 3)
    exact = evaluate_set({"y": _ball_surrogate(3, np.full(3, 0.5))}, domain, ("y",), {"y": 0.05}, 0.3, 41).exact
    solid, axis = exact._shape, exact._outer_axis
    lo, hi = exact._unit_spans[axis]
    edges = np.linspace(lo, hi, 9)
    _, outer = integrate_pieces(lambda owners, s: solid.planes(axis, s).integral(0)[0][:, None], np.zeros(8, dtype=int),
                          edges[:-1], edges[1:], 1, OUTER_RTOL)
    slices = integrate.quad(lambda s: float(solid.planes(axis, np.array([s])).integral(0)[1][0]), lo, hi,
                            points=edges[1:-1], limit=200)[0]
    assert slices > outer[0] / 100  # premise: the slices' errors are a visible part of the sum
    assert exact.fraction_error == pytest.approx(outer[0] + slices, rel=0.1)

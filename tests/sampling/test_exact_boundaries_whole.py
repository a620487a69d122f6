"""Exact sets at their boundaries, against rules written out here: every refusal of a polynomial and of an exact set
(a negative exponent, one coefficient too few, four factors, an empty box, a zero or infinite target, a tolerance of
zero, a reference of the wrong size), a polynomial's values and unit tensor against its terms summed one by one
(one to three factors), a constant response exactly on the tolerance (the whole box, in one to three factors; just
past it, nothing) and a linear response in one factor, whose set, fraction, frame and reference distance are
intervals in closed form (targets of either sign, log factors)."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
from hypothesis import Phase, given, settings
from hypothesis import strategies as st

from demid.sampling.exact import Polynomial, exact_set

SETTINGS = settings(max_examples=10, deadline=None, derandomize=True, phases=[Phase.explicit, Phase.generate])


@pytest.mark.parametrize("exponents, coefficients", [
    ([[0], [-1]], [1.0, 2.0]),           # a negative exponent
    ([[0, 1], [1, 0]], [1.0]),           # one coefficient too few
    ([[0, 1]], [1.0, 2.0]),              # one too many
    ([0, 1], [1.0, 2.0]),                # not a matrix
])
def test_a_polynomial_without_one_coefficient_per_term_of_non_negative_exponents_is_refused(exponents, coefficients):
    with pytest.raises(ValueError, match="non-negative exponents"):
        Polynomial(np.array(exponents), np.array(coefficients))


def _random_polynomial(rng, dim):
    exps = sorted({tuple(int(e) for e in rng.integers(0, 3, dim)) for _ in range(5)})
    return Polynomial(np.array(exps), rng.normal(size=len(exps)))


@given(seed=st.integers(0, 10_000), dim=st.integers(1, 3))
@SETTINGS
def test_a_polynomial_s_values_degree_and_unit_tensor_against_its_terms(seed, dim):
    rng = np.random.default_rng(seed)
    poly = _random_polynomial(rng, dim)
    z = rng.normal(size=(4, dim))
    want = [sum(c * np.prod(zz ** e) for e, c in zip(poly.exponents, poly.coefficients)) for zz in z]
    assert poly(z) == pytest.approx(want, rel=1e-12, abs=1e-12)
    assert poly.dim == dim and poly.degree == max(sum(e) for e in poly.exponents)
    lower, upper = rng.normal(size=dim), None
    upper = lower + rng.uniform(0.5, 3, dim)
    tensor = poly.unit_tensor(lower, upper, poly.degree + 1)
    assert tensor.shape == (poly.degree + 2,) * dim
    u = rng.random((4, dim))
    in_unit = [sum(tensor[idx] * np.prod(uu ** np.array(idx)) for idx in itertools.product(range(poly.degree + 2),
                                                                                             repeat=dim))
               for uu in u]
    assert in_unit == pytest.approx(poly(lower + u * (upper - lower)), rel=1e-10, abs=1e-10)
    assert Polynomial(np.zeros((0, dim), dtype=int), np.zeros(0)).degree == 0


def _line(a=1.0):
    return Polynomial(np.array([[1]]), np.array([a]))


@pytest.mark.parametrize("polys, targets, tolerance, lower, upper, reference, words", [
    ([], [], 0.1, [0.0], [1.0], None, "one target per polynomial"),
    ([_line()], [1.0, 2.0], 0.1, [0.0], [1.0], None, "one target per polynomial"),
    ([Polynomial(np.zeros((1, 4), dtype=int), np.ones(1))], [1.0], 0.1, [0.0] * 4, [1.0] * 4, None, "1 to 3 factors"),
    ([_line()], [1.0], 0.1, [1.0], [1.0], None, "lower < upper"),
    ([_line()], [1.0], 0.1, [2.0], [1.0], None, "lower < upper"),
    ([Polynomial(np.zeros((1, 2), dtype=int), np.ones(1))], [1.0], 0.1, [0.0], [1.0], None, "one exponent per factor"),
    ([_line()], [0.0], 0.1, [0.0], [1.0], None, "non-zero"),
    ([_line()], [math.inf], 0.1, [0.0], [1.0], None, "non-zero"),
    ([_line()], [1.0], 0.0, [0.0], [1.0], None, "tolerance must be positive"),
    ([_line()], [1.0], -0.1, [0.0], [1.0], None, "tolerance must be positive"),
    ([_line()], [1.0], 0.1, [0.0], [1.0], [0.5, 0.5], "one finite value per factor"),
    ([_line()], [1.0], 0.1, [0.0], [1.0], [math.nan], "one finite value per factor"),
])
def test_every_refusal_of_an_exact_set(polys, targets, tolerance, lower, upper, reference, words):
    with pytest.raises(ValueError, match=words):
        exact_set(polys, targets, tolerance, lower, upper, reference=reference)


def test_three_factors_are_accepted():
    poly = Polynomial(np.array([[1, 0, 0]]), np.array([1.0]))
    assert exact_set([poly], [0.5], 0.2, [0.0] * 3, [1.0] * 3).fraction == pytest.approx(0.2, abs=1e-9)


@pytest.mark.parametrize("dim", [1, 2, 3])
@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_a_constant_response_exactly_on_the_tolerance_is_admissible_everywhere(dim, sign):
    # (0.75 - 0.5) / 0.5 is exactly 0.5, the tolerance: the whole box; a hair more and none of it
    on_edge = Polynomial(np.zeros((1, dim), dtype=int), np.array([sign * 0.75]))
    es = exact_set([on_edge], [sign * 0.5], 0.5, [-1.0] * dim, [2.0] * dim)
    assert es.fraction == 1.0
    np.testing.assert_array_equal(es.spans["lower"], [-1.0] * dim)
    np.testing.assert_array_equal(es.spans["upper"], [2.0] * dim)
    past = Polynomial(np.zeros((1, dim), dtype=int), np.array([sign * 0.7500001]))
    es = exact_set([past], [sign * 0.5], 0.5, [-1.0] * dim, [2.0] * dim)
    assert es.fraction == 0.0
    assert np.isnan(es.spans["lower"]).all() and np.isnan(es.spans["upper"]).all()


@given(slope=st.floats(0.2, 5.0), sign=st.sampled_from([-1.0, 1.0]), slope_sign=st.sampled_from([-1.0, 1.0]),
       eps=st.floats(0.02, 0.6), ref=st.floats(-3.0, 3.0), log=st.booleans())
@SETTINGS
def test_a_linear_response_in_one_factor_is_an_interval_in_closed_form(slope, sign, slope_sign, eps, ref, log):
    a, t, lo, hi = slope * slope_sign, sign * 1.0, -1.0, 1.5
    es = exact_set([_line(a)], [t], eps, [lo], [hi], reference=[ref], factors=["k"], log=[log])
    # |a z - t| <= eps |t|: z between (t -+ eps) / a, cut to the box
    ends = sorted([(t - eps) / a, (t + eps) / a])
    first, last = max(ends[0], lo), min(ends[1], hi)
    length = max(last - first, 0.0)
    assert es.fraction == pytest.approx(length / (hi - lo), abs=1e-12)
    assert es.fraction_error == 0.0
    frame = es.to_frame()
    assert list(frame.columns) == ["tolerance", "factor", "lower", "upper", "width", "feasible_fraction",
                                   "fraction_error", "reference_distance", "nearest_point"]
    actual = (lambda z: 10.0 ** z) if log else (lambda z: z)
    if length > 0:
        assert frame["lower"][0] == pytest.approx(actual(first), rel=1e-10)
        assert frame["upper"][0] == pytest.approx(actual(last), rel=1e-10)
        assert frame["width"][0] == pytest.approx(actual(last) - actual(first), rel=1e-9, abs=1e-12)
        # the reference's distance to the box's part of the set (also from outside the box)
        nearest = min(max(ref, first), last)
        assert es.reference_distance == pytest.approx(abs(nearest - ref) / (hi - lo), abs=1e-10)
        assert frame["nearest_point"][0] == pytest.approx(actual(nearest), rel=1e-9, abs=1e-12)
    else:
        assert es.reference_distance == math.inf
    assert (frame["tolerance"] == eps).all() and frame["factor"].tolist() == ["k"]

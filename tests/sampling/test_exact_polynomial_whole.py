"""The exact sets' polynomial against sums written out term by term, over generated polynomials of one to three
factors and degrees up to four: its value at points, its degree and dimension, its dense tensor in unit
coordinates of any box (evaluated back at mapped points), the surrogate's polynomial, and every malformed input
refused (a single negative exponent among others, a coefficient count that does not match, exponents not a
matrix)."""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.design import quadratic_terms
from demid.sampling.exact import Polynomial, polynomial_from_surrogate
from demid.surrogate import Surrogate


@given(seed=st.integers(0, 10_000), dim=st.integers(1, 3), n_terms=st.integers(1, 6), top=st.integers(0, 4))
@settings(max_examples=25, deadline=None, derandomize=True)
def test_a_polynomial_s_values_degree_and_unit_tensor(seed, dim, n_terms, top):
    rng = np.random.default_rng(seed)
    exps = rng.integers(0, top + 1, size=(n_terms, dim))
    coef = rng.normal(size=n_terms)
    poly = Polynomial(exps, coef)
    assert poly.dim == dim and poly.degree == int(exps.sum(axis=1).max())
    z = rng.uniform(-2, 2, size=(5, dim))
    want = [sum(c * np.prod([zi ** e for zi, e in zip(point, row)]) for c, row in zip(coef, exps)) for point in z]
    np.testing.assert_allclose(poly(z), want, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(poly(z[0]), want[:1], rtol=1e-12, atol=1e-12)

    lower = rng.uniform(-3, 1, dim)
    upper = lower + rng.uniform(0.5, 4, dim)
    extra = int(rng.integers(0, 2))
    tensor = poly.unit_tensor(lower, upper, poly.degree + extra if extra else None)
    assert tensor.shape == (poly.degree + extra + 1,) * dim
    u = rng.uniform(0, 1, size=(4, dim))
    from_tensor = [sum(tensor[idx] * np.prod(point ** np.array(idx)) for idx in
                       itertools.product(range(tensor.shape[0]), repeat=dim)) for point in u]
    np.testing.assert_allclose(from_tensor, poly(lower + (upper - lower) * u), rtol=1e-9, atol=1e-9)


def test_an_empty_polynomial_has_degree_zero():
    assert Polynomial(np.zeros((0, 2), dtype=int), np.zeros(0)).degree == 0


@pytest.mark.parametrize("exps, coef", [
    ([[1, 0], [0, -1], [2, 0]], [1.0, 2.0, 3.0]),   # one negative exponent among others
    ([[-1, 0]], [1.0]),
    ([[1, 0], [0, 1]], [1.0, 2.0, 3.0]),             # a coefficient without a term
    ([1, 0, 2], [1.0, 2.0, 3.0]),                   # not a matrix
])
def test_a_malformed_polynomial_is_refused(exps, coef):
    with pytest.raises(ValueError, match="non-negative exponents"):
        Polynomial(np.array(exps), np.array(coef))


def test_a_surrogate_s_polynomial_has_its_terms_and_coefficients():
    terms = quadratic_terms(2)
    coef = np.arange(1.0, len(terms) + 1)
    sur = Surrogate("y", ["a", "b"], terms, coef, np.zeros((6, 6)), 0.0, 3)
    poly = polynomial_from_surrogate(sur)
    np.testing.assert_array_equal(poly.exponents, np.array(terms))
    np.testing.assert_array_equal(poly.coefficients, coef)
    z = np.array([[0.3, -1.2], [2.0, 0.5]])
    np.testing.assert_allclose(poly(z), sur.predict(z), rtol=1e-12)

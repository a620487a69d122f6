"""The exact sets' building blocks over generated polynomials, each against an independent computation: real
roots in [0, 1] (numpy.polynomial), Horner values (polyval), resultants (the product of g over the roots of f),
Chebyshev roots (chebroots), lines cut at the roots (dense sampling), the ragged breakpoint table (plain
Python), the adaptive quadrature (closed-form integrals) and the per-owner minima (dense sampling)."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.polynomial import chebyshev as C
from numpy.polynomial import polynomial as P

from demid.sampling.quadrature import argmin_by_owner, integrate, zoom_min
from demid.sampling.roots import Lines, chebyshev_roots, horner, line_coefficients, ragged, real_roots_unit, sylvester_det

SETTINGS = settings(max_examples=40, deadline=None, derandomize=True)


def _separated(values, gap):
    values = sorted(values)
    return all(b - a > gap for a, b in zip(values, values[1:]))


# roots in and around [0, 1], well apart (a double root is a grazing line, tested by the exact sets' tests)
real_roots = st.lists(st.floats(-0.6, 1.6), min_size=1, max_size=5).filter(lambda r: _separated(r, 0.05))
leads = st.sampled_from([-1000.0, -3.0, -1.0, -0.01, 0.02, 1.0, 7.0, 500.0])


def _ascending(roots, lead, complex_pair):
    """Ascending coefficients of lead * prod (t - r), times (t^2 + 0.5) when ``complex_pair`` (no real root)."""
    coef = lead * P.polyfromroots(roots)
    return P.polymul(coef, [0.5, 0.0, 1.0]) if complex_pair else coef


def _unit_roots(roots):
    """The roots in [0, 1], away from the ends by more than round-off."""
    return sorted(r for r in roots if 1e-6 < r < 1 - 1e-6)


@given(roots=real_roots, lead=leads, complex_pair=st.booleans())
@SETTINGS
def test_real_roots_in_the_unit_interval_are_the_polynomials_roots(roots, lead, complex_pair):
    roots = [r for r in roots if abs(r) > 1e-3 and abs(r - 1) > 1e-3]
    if not roots:
        roots = [0.5]
    coef = _ascending(roots, lead, complex_pair)
    found = real_roots_unit(coef[None, None, :])
    assert found.shape == (1, 1, len(coef) - 1)
    got = np.sort(found[np.isfinite(found)])
    np.testing.assert_allclose(got, _unit_roots(roots), atol=1e-7)


@given(n_lines=st.integers(1, 4), degree=st.integers(1, 2), seed=st.integers(0, 10_000))
@SETTINGS
def test_linear_and_quadratic_roots_batched_over_lines_are_numpys(n_lines, degree, seed):
    """Degrees 1 and 2 take the closed-form branch; a batch of lines gives each line its own roots."""
    rng = np.random.default_rng(seed)
    coef = rng.normal(size=(n_lines, 3, degree + 1))
    found = real_roots_unit(coef)
    assert found.shape == (n_lines, 3, degree)
    for i in range(n_lines):
        for k in range(3):
            expected = [r.real for r in P.polyroots(coef[i, k]) if abs(r.imag) < 1e-12 and 0 <= r.real <= 1]
            got = found[i, k][np.isfinite(found[i, k])]
            np.testing.assert_allclose(np.sort(got), np.sort(expected), atol=1e-9)


@given(seed=st.integers(0, 10_000), degree=st.integers(0, 5), n_points=st.integers(1, 6))
@SETTINGS
def test_horner_values_are_polyval(seed, degree, n_points):
    rng = np.random.default_rng(seed)
    coef = rng.normal(size=(3, 2, degree + 1)) * 10.0 ** rng.integers(-2, 3)
    t = rng.uniform(-1.5, 1.5, size=(3, n_points))
    values = horner(coef, t)
    expected = np.array([[P.polyval(t[n], coef[n, k]) for k in range(2)] for n in range(3)])
    np.testing.assert_allclose(values, expected, rtol=1e-12, atol=1e-12)


@given(f_roots=st.lists(st.floats(-2.0, 2.0), min_size=1, max_size=3), g_degree=st.integers(1, 3),
       lead=leads, seed=st.integers(0, 10_000))
@SETTINGS
def test_a_resultant_is_the_product_of_g_over_the_roots_of_f(f_roots, g_degree, lead, seed):
    """Res(f, g) = a_p^q prod g(alpha_i), with a_p f's leading coefficient and q g's degree."""
    g = np.random.default_rng(seed).normal(size=g_degree + 1)
    f = lead * P.polyfromroots(f_roots)
    expected = lead ** g_degree * np.prod(P.polyval(np.array(f_roots), g))
    got = sylvester_det(np.stack([f, 2 * f]), np.stack([g, g]))
    assert got.shape == (2,)
    scale = abs(lead) ** g_degree * np.prod(np.maximum(1.0, np.abs(P.polyval(np.array(f_roots), np.abs(g)))))
    assert got[0] == pytest.approx(expected, abs=1e-9 * scale)
    # f scaled by 2 scales the resultant by 2^q
    assert got[1] == pytest.approx(2.0 ** g_degree * expected, abs=1e-9 * scale * 2.0 ** g_degree)


@given(roots=st.lists(st.floats(-1.3, 1.3), min_size=1, max_size=5).filter(lambda r: _separated(r, 0.05)),
       lead=leads, pad=st.integers(0, 2))
@SETTINGS
def test_chebyshev_roots_are_numpys_within_the_unit_interval(roots, lead, pad):
    """Rows of different degrees in one batch (trailing zeros pad the shorter series)."""
    coef = lead * C.chebfromroots(roots)
    width = len(coef) + pad
    rows = np.zeros((2, width))
    rows[0, :len(coef)] = coef
    rows[1, :2] = [0.25, 1.0]  # T1 + 0.25: the root -0.25
    found = chebyshev_roots(rows)
    assert found.shape == (2, width - 1)
    expected = sorted(r for r in roots if abs(r) <= 1 - 1e-6)
    got = np.sort(found[0][np.isfinite(found[0])])
    got = got[np.abs(got) <= 1 - 1e-6]
    np.testing.assert_allclose(got, expected, atol=1e-7)
    np.testing.assert_allclose(found[1][np.isfinite(found[1])], [-0.25], atol=1e-12)


@given(seed=st.integers(0, 10_000), n_owners=st.integers(1, 5))
@SETTINGS
def test_ragged_rows_are_each_owners_sorted_distinct_values(seed, n_owners):
    rng = np.random.default_rng(seed)
    owners = rng.integers(0, n_owners, size=12)
    values = np.round(rng.uniform(0, 1, size=12), 1)  # repeats on purpose
    values[rng.uniform(size=12) < 0.2] = np.nan
    table = ragged(owners, values, n_owners)
    expected = [sorted({v for o, v in zip(owners, values) if o == i and np.isfinite(v)}) for i in range(n_owners)]
    assert table.shape == (n_owners, max(1, max(len(e) for e in expected)))
    for row, want in zip(table, expected):
        np.testing.assert_array_equal(row[:len(want)], want)
        assert np.all(np.isnan(row[len(want):]))


def _dense_intervals(coef, eps, n=200_001):
    """Admissible length, first and last admissible t of one line, by sampling."""
    t = np.linspace(0.0, 1.0, n)
    ok = np.all(np.abs(np.array([P.polyval(t, c) for c in coef])) <= eps, axis=0)
    if not ok.any():
        return 0.0, np.inf, -np.inf
    return ok.mean(), t[ok][0], t[ok][-1]


@given(seed=st.integers(0, 10_000), k=st.integers(1, 3), degree=st.integers(1, 4), eps=st.floats(0.05, 0.6))
@settings(max_examples=25, deadline=None, derandomize=True)
def test_a_line_cut_at_its_roots_has_the_admissible_length_and_ends_of_dense_sampling(seed, k, degree, eps):
    rng = np.random.default_rng(seed)
    coef = rng.normal(scale=0.6, size=(1, k, degree + 1))
    lines = Lines.cut(coef, eps)
    length, first, last = _dense_intervals(coef[0], eps)
    assert lines.length[0] == pytest.approx(length, abs=2e-5)
    assert bool(lines.feasible[0]) == (length > 0) or length < 2e-5
    if length > 1e-4:
        assert lines.first[0] == pytest.approx(first, abs=2e-5)
        assert lines.last[0] == pytest.approx(last, abs=2e-5)
        # the nearest admissible point to a coordinate: distance zero inside, the closest end outside
        t0 = float(rng.uniform())
        gap, point = lines.nearest(t0)
        t = np.linspace(0.0, 1.0, 200_001)
        ok = np.all(np.abs(np.array([P.polyval(t, c) for c in coef[0]])) <= eps, axis=0)
        assert gap[0] == pytest.approx(np.min(np.abs(t[ok] - t0)), abs=2e-5)
        assert abs(point[0] - t0) == pytest.approx(gap[0], abs=1e-12)


@given(seed=st.integers(0, 10_000), axis=st.integers(0, 2))
@SETTINGS
def test_line_coefficients_restrict_the_tensor_polynomial_to_the_line(seed, axis):
    """coef[n, k, e] of the line through points[n] along ``axis``: the tensor polynomial evaluated there."""
    rng = np.random.default_rng(seed)
    tensor = rng.normal(size=(2, 3, 3, 3))
    points = rng.uniform(size=(4, 3))
    coef = line_coefficients(tensor, axis, points)
    t = rng.uniform(size=5)
    for n in range(4):
        for j, tj in enumerate(t):
            x = points[n].copy()
            x[axis] = tj
            direct = np.einsum("kabc,a,b,c->k", tensor, *(x[i] ** np.arange(3) for i in range(3)))
            np.testing.assert_allclose([P.polyval(tj, coef[n, kk]) for kk in range(2)], direct, rtol=1e-10)


@given(seed=st.integers(0, 10_000), n_owners=st.integers(1, 4), columns=st.integers(1, 2),
       rtol=st.sampled_from([1e-4, 1e-7, 1e-10]))
@settings(max_examples=25, deadline=None, derandomize=True)
def test_integrals_over_each_owners_pieces_are_the_closed_form_ones(seed, n_owners, columns, rtol):
    """Owners with several pieces (one owner may have none); each column its own polynomial times a square-root
    end; the error estimate within the asked accuracy and at least the true error's order."""
    rng = np.random.default_rng(seed)
    owners = np.repeat(np.arange(n_owners), rng.integers(0, 3, size=n_owners))
    cuts = np.sort(rng.uniform(size=(len(owners), 2)), axis=1)
    coef = rng.normal(size=(n_owners, columns, 4))
    coef[rng.uniform(size=n_owners) < 0.3] = 0.0  # an owner whose integrand vanishes: no variation at all

    def func(owner, s):
        powers = s[:, None] ** np.arange(4)
        return np.einsum("mce,me->mc", coef[owner], powers) * np.sqrt(s)[:, None]

    total, error = integrate(func, owners, cuts[:, 0], cuts[:, 1], n_owners, rtol=rtol, columns=columns)
    assert total.shape == (n_owners, columns) and error.shape == (n_owners,)
    expected = np.zeros((n_owners, columns))
    for m, o in enumerate(owners):
        for c in range(columns):
            antiderivative = lambda s: sum(coef[o, c, e] * s ** (e + 1.5) / (e + 1.5) for e in range(4))  # noqa: E731
            expected[o, c] += antiderivative(cuts[m, 1]) - antiderivative(cuts[m, 0])
    np.testing.assert_allclose(total, expected, rtol=max(10 * rtol, 1e-12), atol=1e-14)
    assert np.all(error <= np.maximum(rtol * np.abs(expected[:, 0]), 1e-15) * 1.0001)
    assert np.all(error >= 0.0)
    np.testing.assert_array_equal(error[~coef[:, 0].any(axis=1)], 0.0)


@given(seed=st.integers(0, 10_000), n_owners=st.integers(1, 6))
@SETTINGS
def test_argmin_by_owner_is_each_owners_smallest_entry(seed, n_owners):
    rng = np.random.default_rng(seed)
    owners = rng.integers(0, n_owners, size=10)
    values = rng.permutation(10).astype(float)
    index = argmin_by_owner(owners, values, n_owners)
    for o in range(n_owners):
        mine = np.flatnonzero(owners == o)
        assert index[o] == (mine[np.argmin(values[mine])] if len(mine) else -1)


@given(seed=st.integers(0, 10_000))
@SETTINGS
def test_zoom_min_finds_each_owners_minimum_of_a_smooth_function(seed):
    rng = np.random.default_rng(seed)
    centres = rng.uniform(0.1, 0.9, size=3)
    depth = rng.uniform(-2, 2, size=3)

    def func(owner, x):
        return (x - centres[owner]) ** 2 + depth[owner]

    owners = np.arange(3)
    x, value = zoom_min(func, owners, np.zeros(3), np.ones(3), np.full(3, 0.5), func(owners, np.full(3, 0.5)))
    np.testing.assert_allclose(x, centres, atol=1e-6)
    np.testing.assert_allclose(value, depth, atol=1e-10)
    # a start better than anything on the bracket is kept
    x, value = zoom_min(func, owners, np.zeros(3), np.ones(3), np.full(3, 2.0), depth - 1.0)
    np.testing.assert_array_equal(x, np.full(3, 2.0))
    np.testing.assert_array_equal(value, depth - 1.0)

"""The adaptive quadrature's work and answer over pieces anywhere on the line (negative, straddling zero, far from
it), against closed forms: pieces moved along the line (and the integrand with them) take the same rounds and give
the same integrals, a polynomial's closed-form one; a sharp peak is refined until each owner's estimate meets its
tolerance, with the integral within it; empty pieces and owners without pieces add nothing."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.sampling.quadrature import integrate


def _integrate_shifted(coef, owners, cuts, offset, rtol):
    """The integrals of p(s - offset) over the pieces shifted by offset, and the sizes of the calls made."""
    calls = []

    def func(owner, s):
        calls.append(len(s))
        return (coef[owner] * (s[:, None] - offset) ** np.arange(coef.shape[1])).sum(axis=1)[:, None]

    total, error = integrate(func, owners, cuts[:, 0] + offset, cuts[:, 1] + offset, coef.shape[0], rtol=rtol)
    return total[:, 0], error, calls


@given(seed=st.integers(0, 10_000), n_owners=st.integers(1, 4), offset=st.sampled_from([-64.0, -3.0, -0.5, 8.0,
                                                                                         1024.0]),
       rtol=st.sampled_from([1e-6, 1e-10]), degree=st.integers(1, 9))
@settings(max_examples=20, deadline=None, derandomize=True)
def test_pieces_moved_along_the_line_take_the_same_work_and_give_the_same_integrals(seed, n_owners, offset, rtol,
                                                                                    degree):
    """The tolerance an owner shares among its pieces is by their lengths: moving every piece (and the integrand
    with it) changes neither the refinement nor the answer, which is the polynomial's closed-form integral."""
    rng = np.random.default_rng(seed)
    owners = np.repeat(np.arange(n_owners), rng.integers(1, 4, size=n_owners))
    cuts = np.sort(rng.integers(0, 64, size=(len(owners), 2)), axis=1) / 32.0
    cuts[:, 1] += 1 / 32.0
    coef = rng.normal(size=(n_owners, degree + 1)) * 3.0 ** -np.arange(degree + 1)
    total, error, calls = _integrate_shifted(coef, owners, cuts, 0.0, rtol)
    moved, moved_error, moved_calls = _integrate_shifted(coef, owners, cuts, offset, rtol)
    assert moved_calls == calls
    expected = np.zeros(n_owners)
    for m, o in enumerate(owners):
        a, b = cuts[m]
        expected[o] += sum(coef[o, e] * (b ** (e + 1) - a ** (e + 1)) / (e + 1) for e in range(degree + 1))
    np.testing.assert_allclose(total, expected, rtol=10 * rtol, atol=1e-13)
    np.testing.assert_allclose(moved, expected, rtol=10 * rtol, atol=1e-13)
    assert np.all(error <= np.maximum(rtol * np.abs(expected), 1e-15) * 1.0001)
    np.testing.assert_allclose(moved_error, error, rtol=1e-3, atol=1e-15)


@pytest.mark.parametrize("offset", [-40.0, -1.0, 0.0, 250.0])
@pytest.mark.parametrize("rtol", [1e-5, 1e-9])
def test_a_sharp_peak_is_refined_until_each_owner_meets_its_tolerance(offset, rtol):
    width = np.array([0.01, 0.05])
    centre = offset + np.array([0.3, 0.71])

    def func(owner, s):
        return (1.0 / (1.0 + ((s - centre[owner]) / width[owner]) ** 2))[:, None]

    owners = np.array([0, 0, 1])
    lower = offset + np.array([0.0, 0.5, 0.0])
    upper = offset + np.array([0.5, 1.0, 1.0])
    total, error = integrate(func, owners, lower, upper, 2, rtol=rtol)
    expected = np.array([width[0] * (np.arctan((offset + 1.0 - centre[0]) / width[0])
                                     - np.arctan((offset - centre[0]) / width[0])),
                         width[1] * (np.arctan((offset + 1.0 - centre[1]) / width[1])
                                     - np.arctan((offset - centre[1]) / width[1]))])
    np.testing.assert_allclose(total[:, 0], expected, rtol=10 * rtol)
    assert np.all(error <= rtol * np.abs(expected) * 1.0001) and np.all(error > 0)


def test_empty_pieces_and_owners_without_pieces_add_nothing():
    total, error = integrate(lambda owner, s: np.ones((len(s), 1)), np.array([0, 2]), np.array([1.0, -2.0]),
                             np.array([1.0, -1.0]), 3, rtol=1e-8)
    np.testing.assert_allclose(total[:, 0], [0.0, 0.0, 1.0], atol=1e-14)
    assert error[0] == error[1] == 0.0

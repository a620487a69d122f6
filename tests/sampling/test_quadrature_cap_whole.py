"""The quadrature's limits met exactly: a batch of pieces is bisected while the bisection leaves at most
_MAX_PIECES pieces (10,000 owners of one piece are bisected once, 10,001 are not), a piece no longer than 1e-15 is
left out, a jump is refined for all 40 rounds, and a straight line's estimate is QUADPACK's floor.  Each answer is
compared with the same rule applied by hand: the 15-point Kronrod sums of the pieces the rule ends on, computed by a
call that stops at once."""

from __future__ import annotations

import numpy as np
import pytest

from demid.sampling import quadrature
from demid.sampling.quadrature import integrate

FREQUENCY = 6.0  # cos(6 s) on [0, 1]: one 15-point piece is 4e-9 off, two halves 1e-12


def _cosine(owner, s):
    return np.cos(FREQUENCY * s)[:, None] * (1.0 + 0.0 * owner[:, None])


def _one_round(lower, upper):
    """The Kronrod integral and error estimate of [0, 1] cut at the given pieces, without any bisection."""
    total, error = integrate(_cosine, np.zeros(len(lower), dtype=int), lower, upper, 1, rtol=1e9)
    return total[0, 0], error[0]


def test_the_piece_cap_is_twice_the_owners_a_bisection_makes():
    assert quadrature._MAX_PIECES == 20_000  # the owner counts below sit on either side of half of it


@pytest.mark.parametrize("n_owners, bisected", [(10_000, True), (10_001, False), (9_999, True)])
def test_a_batch_is_bisected_only_while_it_stays_within_the_piece_cap(n_owners, bisected):
    owners = np.arange(n_owners)
    total, error = integrate(_cosine, owners, np.zeros(n_owners), np.ones(n_owners), n_owners, rtol=1e-6)
    expected_total, expected_error = _one_round(np.array([0.0, 0.5]), np.array([0.5, 1.0])) if bisected else \
        _one_round(np.array([0.0]), np.array([1.0]))
    np.testing.assert_allclose(total[:, 0], expected_total, rtol=1e-13, atol=0)
    np.testing.assert_allclose(error, expected_error, rtol=1e-9, atol=0)
    exact = np.sin(FREQUENCY) / FREQUENCY
    assert np.abs(total[:, 0] - exact).max() < (1e-11 if bisected else 1.0)
    if not bisected:
        assert np.abs(total[:, 0] - exact).min() > 1e-9  # the single piece's own error, not refined away


def test_a_few_owners_are_refined_until_each_estimate_meets_its_tolerance():
    n_owners, rtol = 3, 1e-6
    total, error = integrate(_cosine, np.arange(n_owners), np.zeros(n_owners), np.ones(n_owners), n_owners, rtol=rtol)
    exact = np.sin(FREQUENCY) / FREQUENCY
    np.testing.assert_allclose(total[:, 0], exact, rtol=1e-12)
    assert (error <= rtol * abs(exact)).all() and (error > 0).all()


@pytest.mark.parametrize("length, kept", [(1e-15, False), (2e-15, True)])
def test_a_piece_no_longer_than_1e_15_is_left_out(length, kept):
    """A constant 1e6 over a piece [0, length] (length a power-of-two-exact float difference here)."""
    lower, upper = np.array([0.0]), np.array([length])
    assert upper[0] - lower[0] == length
    total, error = integrate(lambda o, s: np.full((len(s), 1), 1e6), [0], lower, upper, 1, rtol=1e-8)
    if kept:
        assert total[0, 0] == pytest.approx(1e6 * length, rel=1e-12)
    else:
        assert total[0, 0] == 0.0 and error[0] == 0.0


@pytest.mark.parametrize("value", [1e-9, -1e-6, 1.0, -3e3, 1e6])
@pytest.mark.parametrize("length", [1.0, 0.25])
def test_a_constant_s_error_estimate_is_round_off_whatever_its_scale(value, length):
    """A constant is integrated exactly by both rules: the estimate is round-off, at least 50 machine epsilons of
    the integral (QUADPACK's floor) and far below any tolerance, relative to the integral at every scale."""
    total, error = integrate(lambda o, s: np.full((len(s), 1), value), [0], [0.0], [length], 1, rtol=1e-8)
    assert total[0, 0] == pytest.approx(value * length, rel=1e-14)
    floor = 50 * np.finfo(float).eps * abs(total[0, 0])
    assert floor * (1 - 1e-12) <= error[0] < 1e-11 * abs(total[0, 0])


@pytest.mark.parametrize("at", [0.3, 1 / 3, 0.7])
def test_a_jump_is_refined_for_the_full_forty_rounds_and_its_last_piece_counted(at):
    """A step from 0 to 1 at s = ``at``: the piece holding the jump never meets its share of the tolerance (its
    error shrinks only with its length, as its share does), and after r bisections it is 2^-r long, above the 1e-13
    floor for every r < 40; so every one of the 40 rounds is made, one call each, and the last round's pieces are
    counted: the error estimate covers the actual error, and is at most what the last piece's variation can be
    (its length 2^-39 times the jump) beside the other pieces' round-off floors."""
    assert quadrature._MAX_ROUNDS == 40
    calls = []

    def step(owner, s):
        calls.append(len(s))
        return (s > at).astype(float)[:, None] + 0.0 * owner[:, None]

    total, error = integrate(step, [0], [0.0], [1.0], 1, rtol=1e-6)
    assert len(calls) == 40
    assert abs(total[0, 0] - (1 - at)) <= error[0] <= 2.0 ** -39 + 1e-13


@pytest.mark.parametrize("value", [1e-9, -1e-6, 1.0, -3e3, 1e6])
@pytest.mark.parametrize("length", [1.0, 0.25])
def test_a_straight_lines_error_estimate_is_exactly_quadpacks_floor(value, length):
    """value (1 + s) on [0, length]: both rules integrate a straight line exactly, so |K - G| is round-off while
    the spread about the mean, value length^2 / 4, is not; QUADPACK's scaled difference is then some 1e-19 of the
    integral, and the estimate is its floor, 50 machine epsilons of the integral."""
    total, error = integrate(lambda o, s: value * (1.0 + s)[:, None], [0], [0.0], [length], 1, rtol=1e-8)
    assert total[0, 0] == pytest.approx(value * (length + length ** 2 / 2), rel=1e-14, abs=0.0)
    assert error[0] == pytest.approx(50 * np.finfo(float).eps * abs(total[0, 0]), rel=1e-12, abs=0.0)

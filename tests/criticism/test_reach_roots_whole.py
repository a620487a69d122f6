"""The smallest positive root that places a band edge beyond a bound (criticism.reach.smallest_positive_root), whole,
against exact arithmetic over small integer coefficients (so a double root, a root at 0, a line and no real root all
occur): a double root is a root, a root at 0 is not positive, a quadratic coefficient below 1e-12 of the others'
(and of 1) is round-off and the line's root is taken, one exactly 1e-12 of them is a quadratic."""

from __future__ import annotations

import math
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.criticism.reach import smallest_positive_root


def _exact(a: int, b: int, c: int) -> float:
    if a == 0:
        return Fraction(-c, b) if b and Fraction(-c, b) > 0 else math.inf
    disc = b * b - 4 * a * c
    if disc < 0:
        return math.inf
    roots = [(-b - s * math.sqrt(disc)) / (2 * a) for s in (1, -1)]
    # the sign of each root exactly: a root is 0 only when c is, and then the other is -b / a
    positive = [r for r in roots if r > 0 and not (c == 0 and abs(r) < 1e-9)]
    return min(positive) if positive else math.inf


@settings(max_examples=150, deadline=None, derandomize=True)
@given(a=st.integers(-4, 4), b=st.integers(-6, 6), c=st.integers(-4, 4), scale=st.sampled_from([1e-3, 1.0, 1e5]))
def test_the_smallest_positive_root_of_integer_quadratics(a, b, c, scale):
    got = smallest_positive_root(a * scale, b * scale, c * scale)
    want = float(_exact(a, b, c))
    if math.isinf(want):
        assert got == math.inf
    else:
        assert got == pytest.approx(want, rel=1e-12)


def test_a_double_root_is_a_root_and_a_root_at_zero_is_not_positive():
    assert smallest_positive_root(1.0, -4.0, 4.0) == 2.0  # (t - 2)^2: the discriminant exactly 0
    assert smallest_positive_root(-1.0, 4.0, -4.0) == 2.0
    assert smallest_positive_root(1.0, -3.0, 0.0) == 3.0  # t (t - 3): 0 is no extension beyond the bound
    assert smallest_positive_root(1.0, 3.0, 0.0) == math.inf
    assert smallest_positive_root(0.0, 2.0, 0.0) == math.inf


@pytest.mark.parametrize("others", [1.0, 0.5, 40.0])
def test_a_quadratic_coefficient_below_a_trillionth_of_the_others_is_round_off(others):
    """a t^2 - others = 0 with no linear term: below 1e-12 max(others, 1) the curve is round-off and the line (flat)
    never reaches; at exactly that much it is a quadratic with the root sqrt(others / a)."""
    at = 1e-12 * max(others, 1.0)
    assert smallest_positive_root(math.nextafter(at, 0.0), 0.0, -others) == math.inf
    assert smallest_positive_root(at, 0.0, -others) == pytest.approx(math.sqrt(others / at), rel=1e-12)
    # with a slope the line's root is taken below the threshold
    assert smallest_positive_root(math.nextafter(at, 0.0), others, -others) == 1.0

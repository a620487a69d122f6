"""Orthogonal blocking at its threshold: blocking counts as orthogonal only when every block column correlates with
every model term by less than ORTHOGONAL_CORRELATION, so a correlation of exactly that size (either sign) is not
orthogonal and is quoted, and one a hair below it is.  The term is built so that its correlation with the two-block
column is exactly 1/100 in floating point: integers with mean 0, norm 50 and a product 2 with the +-1 block column
of norm 4."""

from __future__ import annotations

import numpy as np
import pytest

from demid.blocks import ORTHOGONAL_CORRELATION, check_blocks

#: first eight runs sum to 1, last eight to -1, squares to 2500: (t . b) / (|t| |b|) = 2 / (50 * 4)
TERM = np.array([-15, 3, 15, 18, -8, -16, 14, -10, -2, 13, -19, 13, -9, -12, 13, 2], dtype=float)
LABELS = ["A"] * 8 + ["B"] * 8


def _check(term):
    return check_blocks(term[:, None], LABELS, np.column_stack([np.ones(len(term)), term]))


def test_the_term_is_correlated_exactly_at_the_threshold():
    b = np.where(np.array(LABELS) == "A", 1.0, -1.0)
    assert TERM.sum() == 0 and TERM @ TERM == 2500 and TERM @ b == 2
    assert 2 / (50 * 4) == ORTHOGONAL_CORRELATION == 0.01


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_a_correlation_of_exactly_the_threshold_is_not_orthogonal(sign):
    check = _check(sign * TERM)
    assert check.max_correlation == ORTHOGONAL_CORRELATION and not check.orthogonal
    assert check.notes[-1] == ("blocking is not orthogonal (largest correlation of a block with a model term "
                               "0.010): the quadratic's coefficients are estimated adjusted for the blocks")
    assert check.problems == ()


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_a_correlation_just_below_the_threshold_is_orthogonal(sign):
    term = TERM.copy()
    term[0] -= 1.0
    term[8] -= 1.0  # the same product with the block column (which sums to 0), a larger norm
    term -= term.mean()
    check = _check(sign * term)
    expected = abs(term @ np.where(np.array(LABELS) == "A", 1.0, -1.0)) / (np.linalg.norm(term) * 4)
    assert check.max_correlation == pytest.approx(expected, rel=1e-12) and expected < ORTHOGONAL_CORRELATION
    assert check.orthogonal and check.notes[-1].startswith("blocking is orthogonal")

"""demid.criticism.models.orthonormal_basis on its edge cases: the basis of a matrix's column space has as many
columns as the matrix has rank, each of unit length and orthogonal to the others (q'q = I), so a matrix without
columns, or with only zero columns, has an empty basis (rank 0), the leverages it gives are zero and residualising
on it leaves a column as it was."""

from __future__ import annotations

import numpy as np
import pytest

from demid.criticism.models import leverages, orthonormal_basis, residualize


@pytest.mark.parametrize("x", [np.zeros((6, 0)), np.zeros((6, 2))], ids=["no columns", "zero columns"])
def test_a_matrix_of_rank_zero_has_an_empty_basis(x):
    q = orthonormal_basis(x)
    assert q.shape == (6, 0)  # rank 0: no direction
    np.testing.assert_array_equal(q.T @ q, np.eye(0))
    np.testing.assert_array_equal(leverages(x), np.zeros(6))
    y = np.arange(6.0)[:, None]
    np.testing.assert_array_equal(residualize(q, y), y)


def test_the_basis_has_the_rank_of_the_matrix_with_unit_orthogonal_columns():
    rng = np.random.default_rng(3)
    a = rng.normal(size=(7, 2))
    x = np.column_stack([a, a @ [2.0, -1.0], np.zeros(7)])  # four columns, rank 2
    q = orthonormal_basis(x)
    assert q.shape == (7, np.linalg.matrix_rank(x)) == (7, 2)
    np.testing.assert_allclose(q.T @ q, np.eye(2), atol=1e-12)
    # the same column space: x is its own projection on q
    np.testing.assert_allclose(q @ (q.T @ x), x, atol=1e-12)

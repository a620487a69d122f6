"""What makes the material job linear in the runs gives the numbers the direct computations give: each
replacement against the computation it replaced, written out here, over generated inputs (ties, -0.0, -inf,
string group labels, column blocks that split the null draws); to the bit where the order of the sums is kept."""

from __future__ import annotations

import numpy as np
import pytest

from demid.criticism import catalogue
from demid.criticism import outliers
from demid.criticism.catalogue import added_variable_stats
from demid.criticism.outliers import outlier_null_max, outlier_stats
from demid.criticism.run_order import _ranks
from demid.fit_statistics import pure_error_ss


def _ranks_by_unique(key, run_rank):
    _, inverse = np.unique(np.column_stack([key, run_rank]), axis=0, return_inverse=True)
    return inverse.ravel().astype(float)


def _pure_error_by_group(y, groups):
    y, groups = np.asarray(y, dtype=float), np.asarray(groups)
    return float(sum(np.sum((y[groups == g] - y[groups == g].mean()) ** 2) for g in np.unique(groups)))


@pytest.mark.parametrize("seed", range(6))
def test_lexicographic_ranks_are_uniques(seed):
    rng = np.random.default_rng(seed)
    for _ in range(200):
        n, c = int(rng.integers(1, 40)), int(rng.integers(1, 6))
        key = rng.integers(-2, 3, (n, c)).astype(float)
        key[rng.random((n, c)) < 0.1] = -0.0
        key[rng.random((n, c)) < 0.05] = -np.inf
        run_rank = (rng.integers(0, max(1, n // 2), n) if seed % 2 else rng.permutation(n)).astype(float)
        np.testing.assert_array_equal(_ranks(key, run_rank), _ranks_by_unique(key, run_rank))


@pytest.mark.parametrize("seed", range(6))
def test_pure_error_is_the_sum_over_groups_to_the_bit(seed):
    rng = np.random.default_rng(seed)
    for _ in range(200):
        n = int(rng.integers(1, 60))
        y = rng.normal(size=n) * 10.0 ** int(rng.integers(-3, 4)) + rng.normal() * 100
        groups = rng.integers(0, max(1, n // 3), n)
        if seed % 2:
            groups = np.array([f"g{g}" for g in groups])
        assert pure_error_ss(y, groups) == _pure_error_by_group(y, groups)


@pytest.mark.parametrize("cells", [1, 37, 10 ** 6])
def test_outlier_null_maximum_by_column_blocks_is_the_whole_arrays(cells, monkeypatch):
    rng = np.random.default_rng(cells)
    e = rng.standard_normal((30, 23))
    hat = rng.uniform(0.05, 0.6, 30)
    hat[4] = 0.9999  # a run the others cannot predict: left out of the maximum
    monkeypatch.setattr(outliers, "OUTLIER_CELLS", cells)
    expected = np.max(np.abs(outlier_stats(e, hat, 20)), axis=0)
    # a block of one column sums its squares in another order than numpy sums a wider block: the last bit
    np.testing.assert_allclose(outlier_null_max(e, hat, 20), expected, rtol=1e-13)
    assert np.all(expected > 0) and np.argmax(outlier_null_max(e, hat, 20)) == np.argmax(expected)


def test_added_variable_f_with_the_callers_sums_of_squares_is_the_same():
    rng = np.random.default_rng(3)
    e = rng.standard_normal((25, 9))
    u = rng.standard_normal(25)
    u /= np.linalg.norm(u)
    direct = added_variable_stats(e, u, 18)
    np.testing.assert_array_equal(added_variable_stats(e, u, 18, np.sum(e * e, axis=0)), direct)
    proj = e.T @ u
    np.testing.assert_allclose(direct, proj ** 2 * 18 / (np.sum(e * e, axis=0) - proj ** 2), rtol=1e-12)


@pytest.mark.parametrize("seed,n,p,aliased", [(0, 300, 6, False), (1, 1200, 15, True), (2, 4000, 28, False)])
def test_weighted_sums_of_squares_from_normal_equations_are_the_decompositions(seed, n, p, aliased):
    """Above ASYMPTOTIC_RUNS the unequal-scatter test fits each weighting from p x p normal equations: the
    residual sums of squares and the likelihood ratio are those of the orthonormal basis (SVD), for
    responses fitted to R^2 ~ 0.9999 and residual columns, with an aliased column too."""
    from demid.criticism.catalogue import heteroscedasticity_lr, weighted_sse
    from demid.criticism.models import orthonormal_basis, residualize

    rng = np.random.default_rng(seed)
    x = np.column_stack([np.ones(n), rng.uniform(-1, 1, (n, p - 1))])
    if aliased:
        x[:, -1] = x[:, 1] - x[:, 2]  # a column the others make: rank p - 1
    y = x @ rng.uniform(-5, 5, p) + 0.01 * rng.standard_normal(n)
    e = residualize(orthonormal_basis(x), rng.standard_normal((n, 3)))
    covariate = rng.uniform(-1, 1, n)
    sw = np.exp(-0.5 * 1.3 * covariate)
    for cols in (y[:, None], e):
        r = residualize(orthonormal_basis(x * sw[:, None]), cols * sw[:, None])
        np.testing.assert_allclose(weighted_sse(x * sw[:, None], cols * sw[:, None]), np.sum(r * r, axis=0),
                                   rtol=1e-8)
    lr = heteroscedasticity_lr(e, x, covariate)
    monkey = catalogue.ASYMPTOTIC_RUNS
    try:
        catalogue.ASYMPTOTIC_RUNS = 10 ** 9  # the decomposition for every size
        np.testing.assert_allclose(lr, heteroscedasticity_lr(e, x, covariate), rtol=1e-7, atol=1e-9)
    finally:
        catalogue.ASYMPTOTIC_RUNS = monkey


def test_pure_error_of_a_table_with_a_missing_or_infinite_response_is_undefined():
    rng = np.random.default_rng(0)
    y, groups = rng.normal(size=20), np.array([0, 0] + list(range(1, 19)))
    for bad in (np.nan, np.inf):
        for at in (0, 7):  # in a replicated group and in a run without replicates
            z = y.copy()
            z[at] = bad
            with np.errstate(invalid="ignore"):
                assert np.isnan(pure_error_ss(z, groups)) and np.isnan(_pure_error_by_group(z, groups))

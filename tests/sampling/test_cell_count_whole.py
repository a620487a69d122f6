"""The grid's cell count on curved fields, cell by cell, against each cell's admissible share counted on a dense
sample of the cell: generated quadratic residual fields of one or two factors and one or two observables, on
coarse grids where a band edge often passes between a cell's corners (the corners inside the band, the field
leaving it in mid-cell) — the case the curvature margin exists for.  And the known cell: corners at 0.9 of the
band, a bump to 1.1 between them, about 29 % of the cell admissible (not all of it)."""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.sampling import Domain
from demid.sampling.grid import cell_count


def _field(coef):
    a, b, c = coef

    def r(u):  # u (N, d) -> (N,)
        return a + u @ b + np.einsum("ni,ij,nj->n", u, c, u)
    return r


def _dense_share(fields, eps, lo, hi, m):
    axes = [np.linspace(a, b, m) for a, b in zip(lo, hi)]
    pts = np.array(list(itertools.product(*axes)))
    ok = np.all([np.abs(f(pts)) <= eps for f in fields], axis=0)
    return ok.mean()


@given(seed=st.integers(0, 10_000), d=st.integers(1, 2), k=st.integers(1, 2), n=st.sampled_from([3, 4, 6]))
@settings(max_examples=15, deadline=None, derandomize=True)
def test_each_cell_s_share_against_a_dense_count(seed, d, k, n):
    rng = np.random.default_rng(seed)
    domain = Domain(tuple(f"f{i}" for i in range(d)), (0.0,) * d, (1.0,) * d)
    fields = []
    for _ in range(k):
        c = rng.normal(size=(d, d)) * 1.5
        fields.append(_field((rng.uniform(-0.5, 1.0), rng.normal(size=d), (c + c.T) / 2)))
    eps = 1.0
    axis = np.linspace(0, 1, n)
    nodes = np.array(list(itertools.product(*[axis] * d)))
    resid = np.stack([f(nodes) for f in fields]).reshape((k,) + (n,) * d)
    step = np.full(d, 1.0 / (n - 1))

    def evaluate(x):
        return np.stack([f(np.atleast_2d(x)) for f in fields])

    count = cell_count(resid, eps, domain, step, evaluate, 16)
    dense = 120 if d == 1 else 40
    for cell in itertools.product(range(n - 1), repeat=d):
        lo = np.array(cell) * step
        want = _dense_share(fields, eps, lo, lo + step, dense)
        assert count.cells[cell] == pytest.approx(want, abs=0.12), cell
    assert count.fraction == pytest.approx(count.cells.mean(), abs=1e-15)
    assert count.analytic_cells + count.sampled_cells <= (n - 1) ** d


def test_a_cell_whose_corners_are_inside_and_whose_middle_is_not_is_measured_not_counted_whole():
    domain = Domain(("a",), (0.0,), (2.0,))
    field = _field((0.9, np.array([0.8]), np.array([[-0.8]])))  # 1.1 - 0.8 (u - 0.5)^2
    nodes = np.array([[0.0], [1.0], [2.0]])
    resid = field(nodes)[None, :]
    np.testing.assert_allclose(resid[0], [0.9, 0.9, -0.7])
    count = cell_count(resid, 1.0, domain, np.array([1.0]), lambda x: field(np.atleast_2d(x))[None, :], 16)
    share = 2 * (0.5 - np.sqrt(0.125))  # |u - 0.5| >= sqrt(0.1 / 0.8)
    assert count.cells[0] == pytest.approx(share, abs=1 / 16)
    assert count.sampled_cells >= 1


@pytest.mark.parametrize("moving", range(5))
def test_more_observables_than_grid_nodes_each_cell_is_measured_by_the_observable_that_crosses_the_band(moving):
    """Five observables on a three-node axis: four are constant inside the band, the fifth (any of them) rises
    through it, r = 2u - 1.5 on [0, 2]; |r| <= 1 holds for u in [0.25, 1.25], so 3/4 of the first cell and 1/4
    of the second, measured by the plane through the corners, which is exact for a straight field."""
    domain = Domain(("a",), (0.0,), (2.0,))
    nodes = np.array([0.0, 1.0, 2.0])

    def fields(u):
        out = np.full((5, len(u)), 0.25)
        out[moving] = 2.0 * u - 1.5
        return out

    count = cell_count(fields(nodes), 1.0, domain, np.array([1.0]), lambda x: fields(np.atleast_2d(x)[:, 0]), 16)
    np.testing.assert_allclose(count.cells, [0.75, 0.25], rtol=0, atol=1e-12)
    assert count.fraction == pytest.approx(0.5, abs=1e-12)
    assert (count.analytic_cells, count.sampled_cells, count.evaluations) == (2, 0, 0)

"""Where a set has no admissible grid node, span polishing starts from the least-violating nodes of a grid of at
most a million nodes: for six factors sampled at 2^20 points (about 10 per axis), a grid of about 10 nodes per
axis (the sixth root of a million, to its round-off), from its nodes nearest to where the residual vanishes."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np

from demid.sampling import Domain
from demid.sampling.polish import start_points

D = 6
CENTRE = np.array([0.3012, 0.5523, 0.7781, 0.1297, 0.8843, 0.4161])


def _distance(nodes: np.ndarray) -> np.ndarray:
    return np.linalg.norm(nodes - CENTRE, axis=1)[None, :]


def _nearest_nodes(m: int, count: int) -> np.ndarray:
    """The ``count`` (<= 64) nodes of the m^D grid on the unit cube nearest CENTRE, sorted.  The 2^D nodes on each
    axis's two nearest values lie within sqrt(D) steps of it, a node on an axis's sixth nearest value or farther
    at least 2.5 steps away: the nearest nodes are among the five nearest values of every axis."""
    axis = np.linspace(0.0, 1.0, m)
    near = [axis[np.argsort(np.abs(axis - c))[:5]] for c in CENTRE]
    block = np.array(np.meshgrid(*near, indexing="ij")).reshape(D, -1).T
    dist = np.linalg.norm(block - CENTRE, axis=1)
    return np.array(sorted(map(tuple, block[np.argsort(dist)[:count]])))


def test_an_empty_set_of_many_points_starts_from_the_nodes_of_a_grid_of_a_million_nearest_the_zero():
    domain = Domain(tuple("abcdef"), (0.0,) * D, (1.0,) * D)
    aset = SimpleNamespace(n_nodes=2 ** 20, mask=np.zeros(2 ** 20, dtype=bool))
    starts = start_points(_distance, domain, aset)
    assert starts.shape == (16, D)  # at least 16 starts, two per factor above that
    got = np.array(sorted(map(tuple, starts)))
    m = next(m for m in (10, 9) if np.allclose(starts * (m - 1), np.round(starts * (m - 1))))
    assert m ** D <= 1_000_000
    assert np.array_equal(got, _nearest_nodes(m, 16))

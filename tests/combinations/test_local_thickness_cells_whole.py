"""A curved set's local thickness (three factors), cell by cell, against a computation written here: each cell's
points (those whose coordinates on the wide principal axes fall in it, taken in the order given), their centre,
the narrowest axis of their covariance, the width sqrt(12) sd along it and that width over the box's extent along
it; the set's thickness the cells' median weighted by their points.  Every cell holds many points with one key, so
the order they are taken in is fixed (the order given): the thickness the story prints and compares with the
identified width is then the same to the last digit wherever the study is run, not the order an unstable sort
leaves tied keys in.  And on a slab of known thickness the width is that thickness."""

from __future__ import annotations

import numpy as np
import pytest

from demid.combinations.axes import (LOCAL_CELLS, LOCAL_MIN_POINTS, UNIFORM_WIDTH_PER_SD, local_thickness,
                                     principal_axes)
from demid.combinations.material import set_combinations

LOWER, UPPER = [-1.0] * 3, [1.0] * 3


def _cells_here(points: np.ndarray, axes) -> list[tuple]:
    """(centre, normal, width, fraction, count) per cell of at least LOCAL_MIN_POINTS points, by cell number."""
    coords = (points - axes.centre) @ axes.directions[:, 1:]
    lo, hi = coords.min(axis=0), coords.max(axis=0)
    index = np.clip(np.floor((coords - lo) / (hi - lo) * LOCAL_CELLS).astype(int), 0, LOCAL_CELLS - 1)
    number = index[:, 0] * LOCAL_CELLS + index[:, 1]
    out = []
    for cell in range(LOCAL_CELLS ** 2):
        mask = number == cell
        if mask.sum() < LOCAL_MIN_POINTS:
            continue
        pts = points[mask]  # in the order given
        centre = pts.mean(axis=0)
        values, vectors = np.linalg.eigh(np.cov((pts - centre).T, bias=True))
        width = UNIFORM_WIDTH_PER_SD * np.sqrt(max(values[0], 0.0))
        out.append((centre, vectors[:, 0], width, width / float(np.abs(vectors[:, 0]) @ np.full(3, 2.0)),
                    int(mask.sum())))
    return out


def _weighted_median(fractions: np.ndarray, counts: np.ndarray) -> float:
    """The smallest fraction whose cells with no larger fraction hold at least half the points."""
    order = np.argsort(fractions, kind="stable")
    cum = np.cumsum(counts[order])
    return float(fractions[order][np.flatnonzero(cum >= cum[-1] / 2)[0]])


@pytest.mark.parametrize("seed, n, bend", [(0, 6000, 0.6), (1, 9000, 0.3), (2, 4000, 0.8)])
def test_each_cells_thickness_and_the_sets_are_the_cells_points_in_the_order_given(seed, n, bend):
    rng = np.random.default_rng(seed)
    ab = rng.uniform(-1, 1, (n, 2))
    c = bend * ab[:, 0] ** 2 - 0.3 + rng.uniform(-0.03, 0.03, n)
    points = np.column_stack([ab, c])
    axes = principal_axes(points, LOWER, UPPER)
    got = local_thickness(points, axes, LOWER, UPPER)
    here = _cells_here(points, axes)
    assert got is not None and len(got.counts) == len(here) > 10
    for i, (centre, normal, width, fraction, count) in enumerate(here):
        assert got.counts[i] == count
        assert np.array_equal(got.centres[i], centre)
        assert np.array_equal(got.normals[i], normal)
        assert got.widths[i] == width and got.fractions[i] == fraction
    fractions = np.array([h[3] for h in here])
    counts = np.array([h[4] for h in here])
    assert got.fraction == _weighted_median(fractions, counts)
    # the number the story reads: the set's band fraction
    res = set_combinations(points, LOWER, UPPER, ["a", "b", "c"], scenario="s", set_name="plausible")
    assert res.band_fraction == got.fraction


def test_a_flat_slab_is_as_thick_as_it_is():
    """A slab 0.1 thick across c (uniform across): every cell of 200 points or more has the normal c and the width
    0.1 to sampling error (a corner of the wide axes' cells cuts a sliver off the slab, narrower across it in the
    slab's plane), and the set's weighted median is 0.1 over the box's extent of 2."""
    rng = np.random.default_rng(5)
    n = 20_000
    points = np.column_stack([rng.uniform(-1, 1, (n, 2)), rng.uniform(-0.05, 0.05, n)])
    axes = principal_axes(points, LOWER, UPPER)
    got = local_thickness(points, axes, LOWER, UPPER)
    full = got.counts >= 200
    assert full.sum() > 20
    assert got.widths[full] == pytest.approx(np.full(full.sum(), 0.1), rel=0.08)
    assert np.abs(got.normals[full, 2]) == pytest.approx(np.ones(full.sum()), abs=2e-3)
    assert got.fraction == pytest.approx(0.1 / 2, rel=0.05)  # the sampled normals tilt a little: a longer extent

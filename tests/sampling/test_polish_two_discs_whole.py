"""Span ends polished on a set of two separate discs, one towards each corner of a box whose ranges lie away from
zero (above it, below it, across it): each end is the extreme of the disc that reaches it, written out from the
centres and the radius.  SLSQP only finds the disc it starts in, so the ends are right only when every search
starts from the grid's own extreme admissible nodes, wherever the box lies."""

from __future__ import annotations

import numpy as np
import pytest

from demid.sampling import Domain
from demid.sampling.grid import admissible_set
from demid.sampling.polish import polish_spans


class TwoDiscs:
    """y = 1 + eps * min(|x - c1|, |x - c2|)^2 / radius^2: with target 1 and tolerance eps the set is two discs."""

    def __init__(self, centres, radius, eps):
        self.centres, self.radius, self.eps = np.asarray(centres, dtype=float), float(radius), float(eps)

    def predict(self, x):
        x = np.atleast_2d(np.asarray(x, dtype=float))
        d2 = np.min(np.sum((x[:, None, :] - self.centres[None]) ** 2, axis=2), axis=1)
        return 1.0 + self.eps * d2 / self.radius ** 2


@pytest.mark.parametrize("lower, width", [((10.0, 30.0), (10.0, 5.0)), ((-20.0, -7.0), (10.0, 4.0)),
                                          ((-3.0, 2.0), (5.0, 8.0)), ((0.0, 0.0), (2.0, 2.0))])
def test_each_polished_end_is_the_extreme_of_its_disc(lower, width):
    lower, width = np.array(lower), np.array(width)
    upper = lower + width
    domain = Domain(("a", "b"), tuple(lower), tuple(upper))
    # discs as fractions of the box; the radius is a fraction of the narrower range
    radius = 0.12 * width.min()
    centres = lower + np.array([[0.25, 0.3], [0.72, 0.75]]) * width
    eps = 0.05
    sur = {"y": TwoDiscs(centres, radius, eps)}
    aset = admissible_set(sur, domain, ["y"], {"y": 1.0}, eps, 21)
    assert not aset.empty
    lower_p, upper_p = polish_spans(sur, domain, ["y"], {"y": 1.0}, eps, aset)
    want_lower = centres.min(axis=0) - radius
    want_upper = centres.max(axis=0) + radius
    np.testing.assert_allclose(lower_p, want_lower, atol=1e-5 * width.max())
    np.testing.assert_allclose(upper_p, want_upper, atol=1e-5 * width.max())
    # the grid's ends lie inside the discs' extremes, by up to a grid step
    assert np.all(aset.lower >= want_lower - 1e-12) and np.all(aset.upper <= want_upper + 1e-12)
    assert np.any(aset.lower > want_lower + 1e-4 * width) or np.any(aset.upper < want_upper - 1e-4 * width)

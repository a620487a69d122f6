"""Roots on [0, 1] at the interval's ends and of every formal degree, against rules written out here: a constant has
no root (an empty last axis), a root exactly at 0 or 1 is kept and one a hair outside is not (lines, quadratics and
cubics), and a line cut at a band whose edge passes exactly through an end of the unit interval keeps its length."""

from __future__ import annotations

import numpy as np
import pytest

from demid.sampling.roots import Lines, real_roots_unit


def test_a_constant_has_no_root():
    assert real_roots_unit(np.array([[2.0], [-1.0], [0.5]])).shape == (3, 0)
    assert real_roots_unit(np.ones((2, 4, 1))).shape == (2, 4, 0)


@pytest.mark.parametrize("coef, roots", [
    ([0.0, 1.0], [0.0]),                       # t: a root at 0
    ([-1.0, 1.0], [1.0]),                      # t - 1: at 1
    ([-1.0 - 1e-9, 1.0], []),                  # a hair past 1
    ([1e-9, 1.0], []),                         # a hair below 0
    ([0.0, -1.0, 1.0], [0.0, 1.0]),            # t (t - 1)
    ([-0.25, 0.0, 1.0], [0.5]),                # (t - 1/2)(t + 1/2)
    ([0.0, 2.0, -3.0, 1.0], [0.0, 1.0]),       # t (t - 1)(t - 2)
    ([-2.0, 3.0, 0.0, 0.0], [2.0 / 3.0]),      # a line written as a cubic
])
def test_roots_at_the_ends_of_the_unit_interval_are_kept(coef, roots):
    got = real_roots_unit(np.array([coef]))[0]
    assert got.shape == (len(coef) - 1,)
    found = np.sort(got[np.isfinite(got)])
    assert found == pytest.approx(roots, abs=1e-12)


@pytest.mark.parametrize("shift, length", [(0.0, 0.5), (0.5, 1.0), (-0.2, 0.3)])
def test_a_band_edge_through_an_end_of_the_interval(shift, length):
    # |t - shift| <= 0.5 on [0, 1]: the band [shift - 0.5, shift + 0.5] cut to the interval
    lines = Lines.cut(np.array([[[-shift, 1.0]]]), 0.5)
    assert lines.length[0] == pytest.approx(length, abs=1e-15)
    assert lines.first[0] == pytest.approx(max(shift - 0.5, 0.0), abs=1e-15)
    assert lines.last[0] == pytest.approx(min(shift + 0.5, 1.0), abs=1e-15)
    gap, point = lines.nearest(0.9)
    assert gap[0] == pytest.approx(max(0.9 - min(shift + 0.5, 1.0), 0.0), abs=1e-15)

"""How many design runs a refocused wave keeps when the earlier runs lie far outside its box: runs on a circle as a
run sheet prints them (8 significant digits) determine the circle's quadratic by round-off alone, wherever the new
box is, so they count as one coefficient short and the wave keeps one design run for it; moved off the circle by a
thousandth they determine it.  Boxes a quarter to a twentieth of the circle's size put the runs 4-17 box
half-widths out, where the quadratic's columns reach 300: the rank's round-off allowance grows with them."""

from __future__ import annotations

import numpy as np
import pytest

from demid.wave_runs import design_count, full_rank


def _printed_circle(n: int, seed: int) -> tuple[np.ndarray, np.ndarray]:
    rng = np.random.default_rng(seed)
    t = rng.uniform(0.0, 2 * np.pi, n)
    circle = np.column_stack([0.2 + 0.6 * np.cos(t), -0.1 + 0.6 * np.sin(t)])
    printed = np.vectorize(lambda v: float(f"{v:.8g}"))(circle)
    off = circle * (1.0 + 1e-3 * rng.standard_normal((n, 1)))
    return printed, off


def _quadratic_rank(x: np.ndarray) -> int:
    """numpy's rank of the quadratic's model matrix at well-separated points (no round-off question)."""
    cols = [np.ones(len(x)), x[:, 0], x[:, 1], x[:, 0] ** 2, x[:, 0] * x[:, 1], x[:, 1] ** 2]
    return int(np.linalg.matrix_rank(np.column_stack(cols)))


@pytest.mark.parametrize("n, seed", [(20, 20), (40, 3)])
@pytest.mark.parametrize("width, corner", [(0.5, (0.3, 0.1)), (0.2, (-0.6, 0.4)), (0.1, (0.05, -0.05))])
def test_printed_runs_on_a_conic_far_outside_the_box_leave_one_coefficient(n, seed, width, corner):
    printed, off = _printed_circle(n, seed)
    lo = np.array(corner)
    hi = lo + width
    coded = (printed - (lo + hi) / 2) / ((hi - lo) / 2)
    assert np.abs(coded).max() > 3.5  # the runs lie well outside the box
    # on the circle: 5 of the 6 coefficients are determined (a conic through the runs is one relation among them)
    assert _quadratic_rank(np.column_stack([0.2 + 0.6 * np.cos([0, 1, 2, 3, 4, 5.0]),
                                            -0.1 + 0.6 * np.sin([0, 1, 2, 3, 4, 5.0])])) == 5
    assert full_rank(coded, 2) == 1
    for count, deciding in ((9, 9), (9, 4), (1, 1), (3, 3)):
        assert design_count(count, deciding, printed, lo, hi) == max(count - deciding, min(1, count))
    coded_off = (off - (lo + hi) / 2) / ((hi - lo) / 2)
    assert _quadratic_rank(coded_off) == 6
    assert full_rank(coded_off, 2) == 0
    assert design_count(9, 9, off, lo, hi) == 0

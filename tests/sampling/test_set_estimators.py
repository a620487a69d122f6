"""Known answers for the grid, Sobol and polishing estimators of an admissible set.

The pipeline computes the sets of polynomial surrogates in up to 3 factors exactly
(:mod:`demid.sampling.exact`); these estimators serve the other cases (plausible sets,
non-polynomial fields, more factors).  The fields here are closed-form functions of the
factors (not polynomial surrogates), so every test reaches the estimator itself, and
each answer (a slab's width, a box's corner, a root of a quadratic, a Student-t
quantile) is computed in the test, independently of the code under test.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy import stats

from demid.design import quadratic_terms
from demid.sampling.domain import Domain
from demid.sampling.grid import admissible_set, fraction_with_error, predict_grid
from demid.sampling.polish import polish_spans
from demid.sampling.sobol import sobol_admissible_set, sobol_fraction
from demid.surrogate import Surrogate

SQUARE = Domain(("a", "b"), (0.0, 0.0), (1.0, 1.0))
CUBE = Domain(("a", "b", "c"), (0.0, 0.0, 0.0), (1.0, 1.0, 1.0))
BOX4 = Domain(("a", "b", "c", "d"), (0.0,) * 4, (1.0,) * 4)


class Field:
    """A response given by a closed-form function of the actual factor values."""

    def __init__(self, f):
        self.f = f

    def predict(self, points):
        return self.f(np.atleast_2d(np.asarray(points, dtype=float)))


def along(i, scale=1.0, offset=0.0):
    return Field(lambda x: offset + scale * x[:, i])


# --------------------------------------------------------------------------- grid estimator
@pytest.mark.parametrize("second", [
    # touches both band edges exactly on the box's faces b = 0 and b = 1
    Field(lambda x: 0.75 + 0.5 * x[:, 1]),
    # curved, stays inside its band by 0.01 (less than the cell-to-cell change of its residual)
    Field(lambda x: 1.0 + 0.96 * (x[:, 1] - 0.5) ** 2),
])
def test_an_observable_inside_its_band_leaves_a_slab_exact(second):
    """y1 = a within 25 % of 0.52 is the slab 0.39 <= a <= 0.65 (26 % of the square).  A second
    observable that never leaves its band, even touching its edge, must not change that fraction:
    the slab's edges cut cells mid-way, where the plane rule is exact for a linear field."""
    res = admissible_set({"y1": along(0), "y2": second}, SQUARE, ["y1", "y2"], {"y1": 0.52, "y2": 1.0},
                         0.25, 11)
    assert res.fraction == pytest.approx(0.26, abs=1e-9)


def test_span_of_a_set_that_reaches_the_domain_bound_is_the_bound():
    """|a - 0.2| <= 1.5 * 0.2 is -0.1 <= a <= 0.5: in the unit square the set is [0, 0.5] x [0, 1]."""
    res = admissible_set({"y": along(0)}, SQUARE, ["y"], {"y": 0.2}, 1.5, 11)
    np.testing.assert_allclose(res.lower, [0.0, 0.0], atol=1e-12)
    np.testing.assert_allclose(res.upper, [0.5, 1.0], atol=1e-12)
    assert res.fraction == pytest.approx(0.5, abs=1e-9)


def test_three_factor_corner_of_two_slabs():
    """a within 25 % of 0.52 and b within 25 % of 0.4: (0.5 * 0.52) * (0.5 * 0.4) = 5.2 % of the
    cube.  The cells holding the slabs' crossing are sub-sampled; at 9 nodes per axis the estimate
    is within 0.1 % of the cube."""
    res = admissible_set({"y1": along(0), "y2": along(1)}, CUBE, ["y1", "y2"], {"y1": 0.52, "y2": 0.4},
                         0.25, 9)
    assert res.fraction == pytest.approx(0.26 * 0.2, abs=1e-3)


def test_fraction_with_error_on_the_corner_of_two_slabs():
    """Both the n = 11 estimate and the nested n = 6 one measure the 0.26 x 0.2 rectangle, and the
    error estimate bounds the true error."""
    exact = 0.26 * 0.2
    fields = {"y1": along(0), "y2": along(1)}
    est = fraction_with_error(fields, SQUARE, ["y1", "y2"], {"y1": 0.52, "y2": 0.4}, 0.25, 11)
    assert est.n == 11
    assert est.fraction == pytest.approx(exact, abs=1e-5)
    assert est.coarse_fraction == pytest.approx(exact, abs=1e-3)
    assert est.error >= abs(est.fraction - exact)


def test_plausible_fraction_ignores_strict_predictions():
    """y = a, target 0.5, 20 % tolerance, sigma 0.3 and no fit uncertainty: the plausible band at
    z = 0.5 is |a - 0.5| <= 0.5 * 0.3 (sigma configured: the tolerance plays no part), i.e. 30 % of the
    square, whether or not the strict grid predictions (|a - 0.5| <= 0.1: 20 %) are passed along."""
    terms = quadratic_terms(2)
    line = Surrogate("y", ["a", "b"], terms, np.array([0.0, 1.0, 0.0, 0.0, 0.0, 0.0]), np.zeros((6, 6)), 0.0, 7)
    preds = predict_grid({"y": line}, SQUARE, 21)
    for given in (None, preds):
        est = fraction_with_error({"y": line}, SQUARE, ["y"], {"y": 0.5}, 0.2, 21, z=0.5, sigma={"y": 0.3},
                                  grid_predictions=given)
        assert est.fraction == pytest.approx(0.3, abs=1e-5)  # the strict 0.2 is far off


# --------------------------------------------------------------------------- Sobol estimator
@pytest.mark.parametrize("replicates", [4, 16])
def test_sobol_interval_is_a_student_t_interval_on_the_replicates(replicates):
    """R independent scramblings give R i.i.d. means: the 95 % interval is mean +- t(0.975, R - 1) s/sqrt(R)."""
    res = sobol_fraction({"y": Field(lambda x: x[:, 0] + x[:, 1])}, BOX4, ["y"], {"y": 1.0}, 0.3, 2 ** 10, 3,
                         replicates=replicates, polish=False)
    assert 0.0 < res.ci_lower < res.ci_upper < 1.0  # not clipped
    half = (res.ci_upper - res.ci_lower) / 2
    assert half == pytest.approx(stats.t.ppf(0.975, replicates - 1) * res.std_error, rel=1e-9)
    # |a + b - 1| <= 0.3: the square minus two corner triangles of legs 0.7: 1 - 0.49 = 0.51
    assert res.ci_lower - 0.01 <= 0.51 <= res.ci_upper + 0.01


def test_sobol_set_accepts_any_iterable_of_observables():
    """As the grid estimator: names may come from a generator; the result names them as a tuple."""
    fields = {"y1": along(0), "y2": along(1, 0.5)}
    res = sobol_admissible_set(fields, BOX4, (o for o in ["y1", "y2"]), {"y1": 0.5, "y2": 0.25}, 0.5, 2 ** 10)
    assert res.observables == ("y1", "y2")
    # a in [0.25, 0.75] and b in [0.25, 0.75]
    assert res.fraction == pytest.approx(0.25, abs=0.02)


def test_sobol_spans_start_from_the_extreme_admissible_points():
    """Without polishing, the spans are the smallest and largest admissible sample coordinates: inside the
    exact spans [0.25, 0.75] of a and b, and within a few sample spacings of them."""
    fields = {"y1": along(0), "y2": along(1)}
    res = sobol_fraction(fields, BOX4, ["y1", "y2"], {"y1": 0.5, "y2": 0.5}, 0.5, 2 ** 12, 5, polish=False)
    assert np.all(res.lower[:2] >= 0.25) and np.all(res.upper[:2] <= 0.75)
    np.testing.assert_allclose(res.lower, [0.25, 0.25, 0.0, 0.0], atol=0.02)
    np.testing.assert_allclose(res.upper, [0.75, 0.75, 1.0, 1.0], atol=0.02)


# --------------------------------------------------------------------------- polishing
def test_polished_spans_of_a_set_in_two_pieces():
    """(a - 1/2)^2 within 20 % of 0.09 holds on two intervals, 0.3 sqrt(0.8) <= |a - 1/2| <= 0.3 sqrt(1.2):
    the spans run from the lower piece's lower end to the upper piece's upper end."""
    field = {"y": Field(lambda x: (x[:, 0] - 0.5) ** 2)}
    grid = admissible_set(field, SQUARE, ["y"], {"y": 0.09}, 0.2, 21)
    lower, upper = polish_spans(field, SQUARE, ["y"], {"y": 0.09}, 0.2, grid)
    reach = 0.3 * np.sqrt(1.2)
    np.testing.assert_allclose(lower, [0.5 - reach, 0.0], atol=1e-7)
    np.testing.assert_allclose(upper, [0.5 + reach, 1.0], atol=1e-7)


def test_polished_spans_of_a_set_between_the_nodes():
    """y1 = a within 0.4 % of 0.5 and y2 = max(b, 0.4) within 0.4 % of 0.5125: the rectangle
    0.498 <= a <= 0.502, 0.5125 (1 -+ 0.004) for b, which holds no node of the 21-point grid.  Below
    b = 0.4, y2 is flat, 22 % off its target (no gradient leads out): polishing starts from the nodes
    that violate the bands least, and reaches the rectangle's edges."""
    fields = {"y1": along(0), "y2": Field(lambda x: np.maximum(x[:, 1], 0.4))}
    targets = {"y1": 0.5, "y2": 0.5125}
    grid = admissible_set(fields, SQUARE, ["y1", "y2"], targets, 0.004, 21)
    assert grid.n_admissible_nodes == 0
    lower, upper = polish_spans(fields, SQUARE, ["y1", "y2"], targets, 0.004, grid)
    np.testing.assert_allclose(lower, [0.498, 0.5125 * 0.996], atol=1e-7)
    np.testing.assert_allclose(upper, [0.502, 0.5125 * 1.004], atol=1e-7)


@pytest.mark.parametrize("shape", [(7,), (5, 6), (4, 5, 3), (3, 4, 3, 2)])
def test_cell_corner_ranges_equal_the_min_and_max_over_every_corner(shape):
    """Each cell's smallest and largest corner value, taken axis by axis, against a plain loop over
    the cells and their 2**d corners."""
    from itertools import product

    from demid.sampling.grid import cell_range

    values = np.random.default_rng(len(shape)).normal(size=shape)
    lo, hi = cell_range(values)
    cells = tuple(n - 1 for n in shape)
    assert lo.shape == hi.shape == cells
    for cell in np.ndindex(*cells):
        corners = [values[tuple(c + o for c, o in zip(cell, offset))] for offset in product((0, 1), repeat=len(shape))]
        assert lo[cell] == min(corners) and hi[cell] == max(corners)

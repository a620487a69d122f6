"""The grid estimator's pieces at their boundaries, against rules written out here: a node whose relative error is
exactly the tolerance is admissible (and so is a constant field exactly on a band's edge); a cell's corner range
against every corner read one by one; the curvature margin against second differences taken by hand (an axis of
three nodes counts, one of two does not); the distribution of a sum of uniforms against closed forms (one and two) and sampling (three); the
plane rule against the slab's length in one factor; the fraction's relative error when the fraction is zero; the
empty test; every column of an admissible set's frame; predictions on the grid; the odd grid size the fraction
with error rounds to and its grid error against the reference passed."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pandas as pd
import pytest
from hypothesis import Phase, given, settings
from hypothesis import strategies as st

from demid.sampling import Domain
from demid.sampling.grid import (AdmissibleSet, FractionEstimate, _box_cdf, _curvature_margin, admissible_set,
                                 cell_range, fraction_with_error, plane_band_fraction, predict_grid)

from ..helpers import Linear

# no shrinking: a failing example is reported as drawn, in seconds
SETTINGS = settings(max_examples=10, deadline=None, derandomize=True, phases=[Phase.explicit, Phase.generate])


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_a_node_whose_error_is_exactly_the_tolerance_is_admissible(sign):
    # y = t (1 + x) on [0, 1], |t| = 1: the relative error is x, exactly 0.5 at the middle node of five
    domain = Domain(("a",), (0.0,), (1.0,))
    fields = {"y": Linear(sign, [sign])}
    aset = admissible_set(fields, domain, ["y"], {"y": sign}, 0.5, 5)
    assert list(aset.mask) == [True, True, True, False, False]
    assert (aset.n_admissible_nodes, aset.n_nodes, aset.node_fraction) == (3, 5, 0.6)
    assert aset.fraction == 0.5
    assert (aset.lower[0], aset.upper[0]) == (0.0, 0.5)
    assert (aset.best_error, aset.best_point[0]) == (0.0, 0.0)
    assert not aset.empty


def test_a_constant_field_on_the_band_s_edge_is_inside_and_just_past_it_outside():
    center = np.array([0.25, -0.25, 0.25 + 1e-12, 0.1, 0.1])
    increments = np.array([[0.0, 0.0, 0.0, 0.4, 0.0]])
    # the fourth: |0.1 + 0.4 u| <= 0.25 on u in [-1/2, 1/2] holds for u <= 0.375: 0.875 of the box
    got = plane_band_fraction(center, increments, 0.25)
    assert got == pytest.approx([1.0, 1.0, 0.0, 0.875, 1.0], abs=1e-12)
    assert got[:3].tolist() == [1.0, 1.0, 0.0]


@given(seed=st.integers(0, 10_000), eps=st.floats(0.05, 2.0), n=st.integers(1, 6))
@SETTINGS
def test_the_plane_rule_of_one_factor_is_the_slab_s_length(seed, eps, n):
    rng = np.random.default_rng(seed)
    center = rng.normal(size=n) * 2
    slope = rng.normal(size=n) * 3
    got = plane_band_fraction(center, slope[None, :], eps)
    # |c + a u| <= eps for u in [-1/2, 1/2]: an interval of u, clipped to the box
    lo = np.minimum((-eps - center) / slope, (eps - center) / slope)
    hi = np.maximum((-eps - center) / slope, (eps - center) / slope)
    want = np.clip(np.minimum(hi, 0.5) - np.maximum(lo, -0.5), 0.0, 1.0)
    assert got == pytest.approx(want, abs=1e-9)


def _sum_cdf(t, widths):
    """P(V_1 + ... + V_d <= t), V_i ~ U(0, w_i), d = 1 or 2, in closed form (a clipped ramp; a trapezoid's area)."""
    if len(widths) == 1:
        return float(np.clip(t / widths[0], 0.0, 1.0))
    a, b = sorted(widths)
    t = min(max(t, 0.0), a + b)
    if t <= a:
        return t * t / (2 * a * b)
    if t <= b:
        return (t - a / 2) / b
    return 1.0 - (a + b - t) ** 2 / (2 * a * b)


@given(seed=st.integers(0, 10_000), d=st.integers(1, 3))
@settings(max_examples=6, deadline=None, derandomize=True, phases=[Phase.explicit, Phase.generate])
def test_the_sum_of_uniforms_distribution_against_closed_forms_and_sampling(seed, d):
    rng = np.random.default_rng(seed)
    widths = rng.uniform(0.2, 2.0, d)
    total = widths.sum()
    ts = np.array([-0.1, 0.0, 0.3 * total, total / 2, 0.8 * total, total, total + 1])
    got = _box_cdf(ts, np.repeat(widths[:, None], len(ts), axis=1))
    if d < 3:
        want = [_sum_cdf(t, widths) for t in ts]
    else:
        sums = (rng.random((200_000, d)) * widths).sum(axis=1)
        want = [(sums <= t).mean() for t in ts]
    assert got == pytest.approx(want, abs=1e-12 if d < 3 else 4e-3)
    # the ends and the median of a symmetric distribution, exactly
    assert got[:2].tolist() == [0.0, 0.0] and got[-1] == pytest.approx(1.0, abs=1e-12)
    assert got[3] == pytest.approx(0.5, abs=1e-12) and got[-2] == pytest.approx(1.0, abs=1e-12)


@given(seed=st.integers(0, 10_000), shape=st.lists(st.integers(2, 5), min_size=1, max_size=3))
@SETTINGS
def test_cell_ranges_and_the_curvature_margin_against_the_corners_read_one_by_one(seed, shape):
    rng = np.random.default_rng(seed)
    values = rng.normal(size=shape)
    lo, hi = cell_range(values)
    d = len(shape)
    for cell in itertools.product(*[range(m - 1) for m in shape]):
        corners = [values[tuple(c + o for c, o in zip(cell, offs))] for offs in itertools.product((0, 1), repeat=d)]
        assert (lo[cell], hi[cell]) == (min(corners), max(corners))
    margin = 0.0
    for axis, m in enumerate(shape):
        moved = np.moveaxis(values, axis, 0)
        if m >= 3:  # a second difference needs three nodes
            margin += max(abs(moved[i] - 2 * moved[i + 1] + moved[i + 2]).max() for i in range(m - 2)) / 8
    assert _curvature_margin(values) == pytest.approx(margin, rel=1e-12, abs=1e-15)


def test_an_axis_of_three_nodes_has_a_curvature_margin():
    assert _curvature_margin(np.array([0.0, 1.0, 0.0])) == 0.25
    assert _curvature_margin(np.array([[0.0, 1.0, 0.0], [0.0, 1.0, 0.0]])) == 0.25
    assert _curvature_margin(np.array([0.0, 1.0])) == 0.0


def _set(**changes):
    base = dict(observables=("y1", "y2"), tolerance=0.05, factors=("a", "b"), fraction=0.125, node_fraction=0.25,
                n_nodes=16, n_admissible_nodes=4, n_refined_cells=3, lower=np.array([1.0, -2.0]),
                upper=np.array([1.5, 3.0]), mask=np.zeros(16, dtype=bool), best_error=0.01, fraction_error=0.002)
    base.update(changes)
    return AdmissibleSet(**base)


def test_every_column_of_an_admissible_set_s_frame():
    frame = _set().to_frame()
    want = pd.DataFrame({"observables": ["y1+y2"] * 2, "tolerance": [0.05] * 2, "feasible_fraction_pct": [12.5] * 2,
                         "factor": ["a", "b"], "lower": [1.0, -2.0], "upper": [1.5, 3.0], "width": [0.5, 5.0],
                         "node_fraction_pct": [25.0] * 2, "n_admissible_nodes": [4, 4], "best_max_rel_error": [0.01] * 2,
                         "fraction_error_pct": [0.2] * 2})
    pd.testing.assert_frame_equal(frame, want)
    bound = _set(at_bound=("lower", "none")).to_frame()
    assert list(bound.columns) == [*want.columns, "at_bound"] and list(bound["at_bound"]) == ["lower", "none"]


def test_a_set_is_empty_only_with_no_fraction_and_no_admissible_node():
    assert _set(fraction=0.0, n_admissible_nodes=0).empty
    assert not _set(fraction=0.0, n_admissible_nodes=1).empty
    assert not _set(fraction=1e-9, n_admissible_nodes=0).empty


def test_the_relative_error_of_a_fraction_and_of_no_fraction():
    def estimate(fraction, error):
        return FractionEstimate(fraction=fraction, error=error, coarse_fraction=fraction, n=9, evaluations=0,
                                analytic_cells=0, sampled_cells=0)

    assert estimate(0.25, 0.01).relative_error == 0.04
    assert estimate(0.0, 0.0).relative_error == 0.0
    assert estimate(0.0, 1e-6).relative_error == math.inf


@pytest.mark.parametrize("n, dim", [(5, 1), (6, 2), (4, 3)])
def test_predictions_on_the_grid_are_each_surrogate_at_each_node(n, dim):
    domain = Domain(tuple(f"f{i}" for i in range(dim)), tuple(-1.0 - i for i in range(dim)),
                    tuple(2.0 + i for i in range(dim)))
    fields = {"y": Linear(1.5, np.arange(1, dim + 1)), "w": Linear(-3.0, -np.ones(dim))}
    frame = predict_grid(fields, domain, n)
    nodes = np.array(list(itertools.product(*domain.axes(n))))
    assert list(frame.columns) == [*domain.factors, "y", "w"]
    np.testing.assert_array_equal(frame[list(domain.factors)].to_numpy(), nodes)
    np.testing.assert_allclose(frame["y"], 1.5 + nodes @ np.arange(1, dim + 1), rtol=1e-13)
    np.testing.assert_allclose(frame["w"], -3.0 - nodes.sum(axis=1), rtol=1e-13)


@pytest.mark.parametrize("n, odd", [(8, 9), (9, 9), (10, 11)])
def test_the_fraction_with_error_uses_the_odd_grid_and_bounds_the_reference_s_error(n, odd):
    # a slab |x - 0.3| <= 0.2 of [0, 1] x [0, 1] in a: fraction 0.4 exactly (the plane rule is exact on it)
    domain = Domain(("a", "b"), (0.0, 0.0), (1.0, 1.0))
    fields = {"y": Linear(0.7, [1.0, 0.0])}
    targets = {"y": 1.0}
    reference = admissible_set(fields, domain, ["y"], targets, 0.2, 7)
    est = fraction_with_error(fields, domain, ["y"], targets, 0.2, n, reference=reference)
    assert est.n == odd
    # 0.4 up to the plane rule's floor on a flat direction's width (1e-4 of the cell's total change)
    assert est.fraction == pytest.approx(0.4, abs=1e-4)
    assert est.coarse_fraction == pytest.approx(0.4, abs=1e-4)
    assert est.error == pytest.approx(0.0, abs=1e-4)
    assert est.grid_fraction == reference.fraction
    assert est.grid_error == pytest.approx(abs(reference.fraction - est.fraction) + est.error, abs=1e-15)
    assert est.evaluations >= odd ** 2
    without = fraction_with_error(fields, domain, ["y"], targets, 0.2, n)
    assert math.isnan(without.grid_fraction) and math.isnan(without.grid_error)


@pytest.mark.parametrize("dim, n", [(2, 9), (2, 11), (3, 7)])
def test_the_fraction_with_error_repeats_the_grid_estimator_s_fraction_on_the_same_grid(dim, n):
    # two crossing bands: cells where both edges pass are sub-sampled; both estimators count the same cells with
    # the same sub-grid (16 points per axis up to two factors, 4 in three), so the fraction is one number
    domain = Domain(tuple(f"f{i}" for i in range(dim)), (-1.0,) * dim, (1.0,) * dim)
    fields = {"y1": Linear(2.0, [1.0, 0.7] + [0.3] * (dim - 2)), "y2": Linear(2.0, [0.6, -1.0] + [0.2] * (dim - 2))}
    targets = {"y1": 2.1, "y2": 1.9}
    grid = admissible_set(fields, domain, ["y1", "y2"], targets, 0.15, n)
    est = fraction_with_error(fields, domain, ["y1", "y2"], targets, 0.15, n)
    assert est.sampled_cells > 0 and 0 < est.fraction < 1
    assert est.fraction == grid.fraction

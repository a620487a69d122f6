"""The search domain's every output against rules written out here, over generated boxes of one to five factors
(any of them on a log scale), ranges of any sign and scale, and physical limits inside, on or beyond the range:
search bounds, unit and search coordinates both ways, grid axes and nodes in 'ij' order, the Sobol points (the
count, scipy's scrambled sequence itself), the grid-or-Sobol sample, which ends a span touches (on and just past
the touch distance), and the room left before a physical limit."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.stats import qmc

from demid.sampling.domain import AT_BOUND, BOUND_TOUCH, MAX_GRID_DIM, Domain, uses_grid

SETTINGS = settings(max_examples=20, deadline=None, derandomize=True)


def _domain(seed, dim, logs, with_limits=False):
    rng = np.random.default_rng(seed)
    lower, upper = [], []
    for i in range(dim):
        if logs[i]:
            lo = 10.0 ** rng.uniform(-8, 8)
            lower.append(lo), upper.append(lo * 10.0 ** rng.uniform(0.3, 4))
        else:
            lo = rng.normal() * 10.0 ** rng.integers(-3, 5)
            lower.append(lo), upper.append(lo + abs(lo) * rng.uniform(0.1, 3) + 1e-3)
    limits = ()
    if with_limits:
        limits = tuple((None if rng.random() < 0.3 else lo - rng.uniform(-0.5, 1.0) * (hi - lo),
                        None if rng.random() < 0.3 else hi + rng.uniform(-0.5, 1.0) * (hi - lo))
                       for lo, hi in zip(lower, upper))
    return Domain(tuple(f"f{i}" for i in range(dim)), tuple(lower), tuple(upper), log=tuple(logs), limits=limits)


def _search(values, logs):
    out = np.array(values, dtype=float, copy=True)
    for i, lg in enumerate(logs):
        if lg:
            out[..., i] = np.log10(out[..., i])
    return out


def _actual(search, logs):
    out = np.array(search, dtype=float, copy=True)
    for i, lg in enumerate(logs):
        if lg:
            out[..., i] = 10.0 ** out[..., i]
    return out


@given(seed=st.integers(0, 10_000), dim=st.integers(1, 5), data=st.data())
@SETTINGS
def test_coordinates_axes_grid_and_sample_follow_the_box(seed, dim, data):
    logs = data.draw(st.lists(st.booleans(), min_size=dim, max_size=dim))
    domain = _domain(seed, dim, logs)
    lo = _search(np.array(domain.lower), logs)
    hi = _search(np.array(domain.upper), logs)
    got_lo, got_hi = domain.search_bounds()
    np.testing.assert_allclose(got_lo, lo, rtol=1e-14)
    np.testing.assert_allclose(got_hi, hi, rtol=1e-14)
    assert domain.dim == dim and uses_grid(dim) is (dim <= MAX_GRID_DIM)

    u = np.random.default_rng(seed).uniform(-0.2, 1.2, size=(7, dim))
    actual = domain.from_unit(u)
    want = _actual(lo + np.clip(u, 0, 1) * (hi - lo), logs)
    np.testing.assert_allclose(actual, want, rtol=1e-12)
    np.testing.assert_allclose(domain.to_unit(actual), np.clip(u, 0, 1), atol=1e-9)
    np.testing.assert_allclose(domain.to_search(actual), _search(actual, logs), rtol=1e-12, atol=1e-300)
    np.testing.assert_allclose(domain.to_actual(domain.to_search(actual)), actual, rtol=1e-12)

    n = 3 if dim > 3 else 4
    axes = domain.axes(n)
    for i in range(dim):
        s = np.linspace(lo[i], hi[i], n)
        np.testing.assert_allclose(domain.search_axes(n)[i], s, rtol=1e-14)
        np.testing.assert_allclose(axes[i], 10.0 ** s if logs[i] else s, rtol=1e-12)
    nodes = domain.grid(n)
    np.testing.assert_allclose(nodes, np.array(list(itertools.product(*axes))), rtol=1e-14)

    points = domain.sobol(20, seed=seed)
    m = math.ceil(math.log2(20))
    want_u = lo + qmc.Sobol(dim, scramble=True, rng=np.random.default_rng(seed)).random_base2(m) * (hi - lo)
    np.testing.assert_allclose(points, _actual(want_u, logs), rtol=1e-12)
    assert len(domain.sobol(1)) == 2 and len(domain.sobol(33)) == 64
    sample = domain.sample(n)
    np.testing.assert_array_equal(sample, domain.grid(n) if dim <= MAX_GRID_DIM else domain.sobol(n))


@given(seed=st.integers(0, 10_000), dim=st.integers(1, 4), data=st.data(),
       offsets=st.lists(st.sampled_from([-0.3, -0.9 * BOUND_TOUCH, -1.1 * BOUND_TOUCH, 0.0, 0.9 * BOUND_TOUCH,
                                         1.1 * BOUND_TOUCH, 0.25]), min_size=2, max_size=2))
@SETTINGS
def test_a_span_touches_an_end_within_the_touch_distance_in_search_units(seed, dim, data, offsets):
    logs = data.draw(st.lists(st.booleans(), min_size=dim, max_size=dim))
    domain = _domain(seed, dim, logs)
    lo, hi = domain.search_bounds()
    # offsets inward from each end, in units of the range (negative: beyond the end)
    lower_s, upper_s = lo + offsets[0] * (hi - lo), hi - offsets[1] * (hi - lo)
    got = domain.at_bound(_actual(lower_s, logs), _actual(upper_s, logs))
    low_touch, high_touch = offsets[0] <= BOUND_TOUCH, offsets[1] <= BOUND_TOUCH
    assert got == (AT_BOUND[int(low_touch) + 2 * int(high_touch)],) * dim
    assert domain.at_bound(np.full(dim, np.nan), np.full(dim, np.nan)) == ("none",) * dim


@given(seed=st.integers(0, 10_000), dim=st.integers(1, 3), data=st.data())
@SETTINGS
def test_the_room_before_a_physical_limit_in_units_of_the_search_range(seed, dim, data):
    logs = data.draw(st.lists(st.booleans(), min_size=dim, max_size=dim))
    domain = _domain(seed, dim, logs, with_limits=True)
    lo, hi = domain.search_bounds()
    for i, factor in enumerate(domain.factors):
        for side, j in (("lower", 0), ("upper", 1)):
            limit = domain.limits[i][j]
            got = domain.room_beyond(factor, side)
            if limit is None or (logs[i] and limit <= 0):
                assert got == math.inf
                continue
            at = math.log10(limit) if logs[i] else limit
            room = (lo[i] - at) if side == "lower" else (at - hi[i])
            assert got == pytest.approx(max(room / (hi[i] - lo[i]), 0.0), rel=1e-9, abs=1e-12)


def test_a_log_factor_s_limit_of_zero_is_no_limit_and_a_limit_inside_leaves_no_room():
    domain = Domain(("a", "b"), (1.0, -1.0), (100.0, 1.0), log=(True, False), limits=((0.0, 1000.0), (-0.5, 3.0)))
    assert domain.room_beyond("a", "lower") == math.inf
    assert domain.room_beyond("a", "upper") == pytest.approx(0.5)
    assert domain.room_beyond("b", "lower") == 0.0
    assert domain.room_beyond("b", "upper") == pytest.approx(1.0)

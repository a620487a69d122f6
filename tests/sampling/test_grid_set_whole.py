"""Every field of the grid estimator's admissible set (up to three factors) against computations made apart, over
generated linear responses of either sign, one to three observables, box offsets and scales and grid sizes: the
node mask, its counts and fraction, the closest node and its error against the worst relative error evaluated at
every node; the feasible fraction of one observable (a slab, where the plane rule is exact) against the slab's
area integrated in closed form along one axis, and of several against a Monte Carlo count; the spans against the
slab's extent from linear programming; and the frame the identifiability table is built from."""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import linprog

from demid.sampling import Domain
from demid.sampling.grid import admissible_set

from ..helpers import Linear

SETTINGS = settings(max_examples=8, deadline=None, derandomize=True)


def _study(seed, dim, k, sign):
    rng = np.random.default_rng(seed)
    lower = rng.normal(size=dim) * 3
    upper = lower + rng.uniform(0.5, 4, dim)
    domain = Domain(tuple(f"f{i}" for i in range(dim)), tuple(lower), tuple(upper))
    centre = (lower + upper) / 2
    fields, targets = {}, {}
    for j in range(k):
        a = rng.normal(size=dim) / (upper - lower)
        fields[f"y{j}"] = Linear(sign * 10.0, a * sign)
        targets[f"y{j}"] = float(fields[f"y{j}"].predict(centre + rng.uniform(-0.2, 0.2, dim) * (upper - lower))[0])
    return domain, fields, targets, lower, upper


def _worst(fields, targets, x):
    return np.max([np.abs(fields[o].predict(x) - targets[o]) / abs(targets[o]) for o in fields], axis=0)


def _slab_span(field, target, eps, lower, upper, i):
    """Smallest and largest x_i on the slab |a.x + c - t| <= eps |t| inside the box (linear programming)."""
    band = eps * abs(target)
    a_ub = np.vstack([field.a, -field.a])
    b_ub = np.array([target + band - field.c, band - target + field.c])
    ends = []
    for direction in (1.0, -1.0):
        cost = np.zeros(len(lower))
        cost[i] = direction
        res = linprog(cost, A_ub=a_ub, b_ub=b_ub, bounds=list(zip(lower, upper)), method="highs")
        ends.append(res.x[i] if res.success else np.nan)
    return ends


def _slab_fraction_2d(field, target, eps, lower, upper):
    """Area of the slab in a 2-factor box / the box's: the x2-interval's length integrated over x1 (midpoints)."""
    m = 200_000
    x1 = lower[0] + (np.arange(m) + 0.5) / m * (upper[0] - lower[0])
    band = eps * abs(target)
    a1, a2 = field.a
    rest = field.c + a1 * x1 - target
    ends = np.sort(np.stack([(-band - rest) / a2, (band - rest) / a2]), axis=0)
    length = np.clip(np.minimum(ends[1], upper[1]) - np.maximum(ends[0], lower[1]), 0, None)
    return float(length.mean() / (upper[1] - lower[1]))


@given(seed=st.integers(0, 10_000), dim=st.integers(1, 3), k=st.integers(1, 3), sign=st.sampled_from([-1.0, 1.0]),
       eps=st.sampled_from([0.01, 0.05, 0.2]), n=st.sampled_from([9, 14, 21]))
@SETTINGS
def test_every_field_of_a_grid_set_against_the_nodes_and_the_slabs(seed, dim, k, sign, eps, n):
    domain, fields, targets, lower, upper = _study(seed, dim, k, sign)
    names = list(fields)
    aset = admissible_set(fields, domain, names, targets, eps, n)

    nodes = np.array(list(itertools.product(*[np.linspace(lo, hi, n) for lo, hi in zip(lower, upper)])))
    worst = _worst(fields, targets, nodes)
    mask = worst <= eps
    np.testing.assert_array_equal(aset.mask, mask)
    assert aset.n_nodes == n ** dim and aset.n_admissible_nodes == int(mask.sum())
    assert aset.node_fraction == pytest.approx(mask.mean(), abs=1e-15)
    assert aset.best_error == pytest.approx(worst.min(), rel=1e-9, abs=1e-15)
    np.testing.assert_allclose(aset.best_point, nodes[np.argmin(worst)], rtol=1e-12, atol=1e-12)
    assert (aset.observables, aset.tolerance, aset.factors) == (tuple(names), eps, domain.factors)
    assert aset.evaluations >= n ** dim * k

    if k == 1 and dim == 2:
        want = _slab_fraction_2d(fields["y0"], targets["y0"], eps, lower, upper)
        assert aset.fraction == pytest.approx(want, abs=1e-6)
    else:
        sample = np.random.default_rng(seed).uniform(lower, upper, size=(200_000, dim))
        assert aset.fraction == pytest.approx(np.mean(_worst(fields, targets, sample) <= eps), abs=0.01)
    if k == 1 and aset.fraction > 0:
        step = (upper - lower) / (n - 1)
        for i in range(dim):
            lo, hi = _slab_span(fields["y0"], targets["y0"], eps, lower, upper, i)
            assert aset.lower[i] == pytest.approx(lo, abs=step[i] / 8)
            assert aset.upper[i] == pytest.approx(hi, abs=step[i] / 8)
    np.testing.assert_array_equal(aset.width, aset.upper - aset.lower)
    assert aset.empty is (aset.fraction == 0 and aset.n_admissible_nodes == 0)

    frame = aset.to_frame()
    assert list(frame["factor"]) == list(domain.factors)
    assert (frame["observables"] == "+".join(names)).all() and (frame["tolerance"] == eps).all()
    np.testing.assert_allclose(frame["feasible_fraction_pct"], 100 * aset.fraction)
    np.testing.assert_allclose(frame["node_fraction_pct"], 100 * mask.mean())
    np.testing.assert_array_equal(frame["n_admissible_nodes"], int(mask.sum()))
    np.testing.assert_array_equal(frame[["lower", "upper", "width"]].to_numpy(),
                                  np.column_stack([aset.lower, aset.upper, aset.upper - aset.lower]))
    np.testing.assert_array_equal(frame["best_max_rel_error"], aset.best_error)

"""The one evaluator of a strict set (evaluate_set) on polynomial surrogates of one to three factors (any of them on
a log scale), one observable of either sign, against computations made apart: a slab's fraction (its area
integrated in closed form along one axis, or a Monte Carlo count), its spans (linear programming in search
units), the ends of the search range they touch, the method, the node mask when asked for, and for a target the
box cannot reach the closest approach (a linear response's smallest error over the box is at a corner)."""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import linprog

from demid.design import quadratic_terms
from demid.sampling import Domain
from demid.sampling.domain import BOUND_TOUCH
from demid.sampling.evaluate import EXACT_METHOD, evaluate_set
from demid.surrogate import Surrogate


def _linear_surrogate(factors, logs, c, a) -> Surrogate:
    terms = quadratic_terms(len(factors))
    coef = np.zeros(len(terms))
    coef[0] = c
    coef[1:len(factors) + 1] = a
    return Surrogate("y", list(factors), terms, coef, np.zeros((len(terms), len(terms))), 0.0, 5,
                     log_factors=tuple(f for f, lg in zip(factors, logs) if lg))


def _study(seed, dim, logs, sign, reach):
    rng = np.random.default_rng(seed)
    factors = tuple(f"f{i}" for i in range(dim))
    lower = np.where(logs, 10.0 ** rng.uniform(-3, 1, dim), rng.normal(size=dim) * 2)
    upper = np.where(logs, lower * 10.0 ** rng.uniform(0.5, 2, dim), lower + rng.uniform(0.5, 3, dim))
    domain = Domain(factors, tuple(lower), tuple(upper), log=tuple(logs))
    lo_s, hi_s = domain.search_bounds()
    a = rng.normal(size=dim) / (hi_s - lo_s)
    c = sign * 10.0
    centre = (lo_s + hi_s) / 2
    inside = sign * 10.0 + centre @ a + rng.uniform(-0.3, 0.3) * np.abs(a) @ (hi_s - lo_s)
    target = float(inside if reach else sign * 10.0 + centre @ a + 3 * np.abs(a) @ (hi_s - lo_s) * sign)
    return domain, _linear_surrogate(factors, logs, c, a), target, a, c, lo_s, hi_s


def _span(a, c, target, eps, lo, hi, i):
    band = eps * abs(target)
    a_ub, b_ub = np.vstack([a, -a]), np.array([target + band - c, band - target + c])
    ends = []
    for direction in (1.0, -1.0):
        cost = np.zeros(len(a))
        cost[i] = direction
        res = linprog(cost, A_ub=a_ub, b_ub=b_ub, bounds=list(zip(lo, hi)), method="highs")
        ends.append(res.x[i])
    return ends


def _fraction(a, c, target, eps, lo, hi, seed):
    band = eps * abs(target)
    if len(a) == 1:
        ends = np.sort([(target - band - c) / a[0], (target + band - c) / a[0]])
        return max(min(ends[1], hi[0]) - max(ends[0], lo[0]), 0.0) / (hi[0] - lo[0]), 1e-12
    if len(a) == 2:
        m = 200_000
        x1 = lo[0] + (np.arange(m) + 0.5) / m * (hi[0] - lo[0])
        rest = c + a[0] * x1 - target
        ends = np.sort(np.stack([(-band - rest) / a[1], (band - rest) / a[1]]), axis=0)
        return float(np.clip(np.minimum(ends[1], hi[1]) - np.maximum(ends[0], lo[1]), 0, None).mean()
                     / (hi[1] - lo[1])), 1e-6
    u = np.random.default_rng(seed).uniform(lo, hi, size=(400_000, len(a)))
    return float(np.mean(np.abs(c + u @ a - target) <= band)), 0.005


@given(seed=st.integers(0, 10_000), dim=st.integers(1, 3), data=st.data(), sign=st.sampled_from([-1.0, 1.0]),
       eps=st.sampled_from([0.02, 0.1]), reach=st.sampled_from([True, True, False]))
@settings(max_examples=10, deadline=None, derandomize=True)
def test_an_exact_set_s_numbers_against_the_slab(seed, dim, data, sign, eps, reach):
    logs = data.draw(st.lists(st.booleans(), min_size=dim, max_size=dim))
    domain, surrogate, target, a, c, lo, hi = _study(seed, dim, logs, sign, reach)
    aset = evaluate_set({"y": surrogate}, domain, ["y"], {"y": target}, eps, 11, grid=True)
    assert aset.method == EXACT_METHOD and aset.exact is not None
    want, tol = _fraction(a, c, target, eps, lo, hi, seed)
    assert aset.fraction == pytest.approx(want, abs=tol)
    nodes = np.array(list(itertools.product(*domain.axes(11))))
    worst = np.abs(surrogate.predict(nodes) - target) / abs(target)
    np.testing.assert_array_equal(aset.mask, worst <= eps)
    if aset.fraction > 0:
        touch = []
        for i in range(dim):
            s_lo, s_hi = _span(a, c, target, eps, lo, hi, i)
            got_lo, got_hi = domain.to_search(np.array([aset.lower, aset.upper]))[:, i]
            assert got_lo == pytest.approx(s_lo, abs=1e-7 * (hi[i] - lo[i]))
            assert got_hi == pytest.approx(s_hi, abs=1e-7 * (hi[i] - lo[i]))
            low = s_lo <= lo[i] + BOUND_TOUCH * (hi[i] - lo[i])
            high = s_hi >= hi[i] - BOUND_TOUCH * (hi[i] - lo[i])
            touch.append(("none", "lower", "upper", "both")[int(low) + 2 * int(high)])
        assert aset.at_bound == tuple(touch)
        assert aset.best_error == pytest.approx(worst.min(), rel=1e-12)
    else:
        corners = np.array(list(itertools.product(*zip(lo, hi))))
        closest = np.min(np.abs(c + corners @ a - target)) / abs(target)
        assert aset.best_error == pytest.approx(closest, rel=1e-6)
        assert aset.best_error > eps and np.all(np.isnan(aset.lower)) and aset.at_bound == ("none",) * dim

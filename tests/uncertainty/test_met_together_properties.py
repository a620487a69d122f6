"""Whether the targets of a set of observables can be met together, over generated linear responses of 1-3
factors (one or two observables more than factors, so no point meets every target exactly) with targets of
either sign: the answer follows the minimax linear programme written out here (scipy's linprog), the smallest
tolerance at which one point meets every target: met at that tolerance (a set of one point), at 5 % more, and
not at 5 % less."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import optimize

from demid.design import quadratic_terms
from demid.sampling.domain import Domain
from demid.surrogate import Surrogate
from demid.uncertainty.ranking import _met_together


def _linear(name: str, factors, intercept: float, slopes) -> Surrogate:
    terms = quadratic_terms(len(factors))
    coef = np.zeros(len(terms))
    coef[0], coef[1:1 + len(slopes)] = intercept, slopes
    return Surrogate(name, list(factors), terms, coef, np.zeros((len(terms), len(terms))), 0.0, 1, ())


def _smallest_tolerance(lower, upper, intercepts, slopes, targets) -> float:
    """min over the box of max_k |y_k(x) - T_k| / |T_k|: minimise t subject to +-(y_k(x) - T_k) <= t |T_k|."""
    k = len(lower)
    rows, rhs = [], []
    for b, a, t in zip(intercepts, slopes, targets):
        for sign in (1.0, -1.0):
            rows.append(np.concatenate([sign * np.asarray(a), [-abs(t)]]))
            rhs.append(sign * (t - b))
    res = optimize.linprog(np.r_[np.zeros(k), 1.0], A_ub=np.array(rows), b_ub=np.array(rhs),
                           bounds=[*zip(lower, upper), (0.0, None)], method="highs")
    assert res.status == 0
    return float(res.x[-1])


@given(k=st.integers(1, 3), more=st.integers(1, 2), seed=st.integers(0, 10_000), signs=st.integers(0, 31))
@settings(max_examples=8, deadline=None, derandomize=True)
def test_targets_are_met_together_exactly_down_to_the_minimax_tolerance(k, more, seed, signs):
    count = k + more  # more observables than factors: their targets conflict, no point meets them all exactly
    rng = np.random.default_rng(seed)
    factors = [f"f{i}" for i in range(k)]
    lower = rng.uniform(-2.0, 2.0, k)
    upper = lower + rng.uniform(0.5, 3.0, k)
    domain = Domain(tuple(factors), tuple(lower), tuple(upper))
    names = [f"y{i}" for i in range(count)]
    intercepts = [(-1.0 if signs >> i & 1 else 1.0) * rng.uniform(5.0, 10.0) for i in range(count)]
    slopes = [rng.uniform(-1.0, 1.0, k) for _ in range(count)]
    # targets: each response's value at its own random point
    targets = [b + a @ (lower + rng.uniform(0, 1, k) * (upper - lower)) for b, a in zip(intercepts, slopes)]
    surrogates = {n: _linear(n, factors, b, a) for n, b, a in zip(names, intercepts, slopes)}
    target_of = dict(zip(names, targets))
    best = _smallest_tolerance(lower, upper, intercepts, slopes, targets)
    assert best > 0.0
    assert _met_together(surrogates, domain, names, target_of, best)
    assert _met_together(surrogates, domain, names, target_of, best * 1.05)
    assert not _met_together(surrogates, domain, names, target_of, best * 0.95)


def _study(seed):
    """Two or three factors, one or two observables more than factors, linear responses with targets of either
    sign, each target the response's value at its own random point: their minimax tolerance by linprog."""
    rng = np.random.default_rng(seed)
    k = int(rng.integers(2, 4))
    count = k + int(rng.integers(1, 3))
    factors = [f"f{i}" for i in range(k)]
    lower = rng.uniform(-2.0, 2.0, k)
    upper = lower + rng.uniform(0.5, 3.0, k)
    names = [f"y{i}" for i in range(count)]
    intercepts = [float(rng.choice([-1.0, 1.0])) * rng.uniform(5.0, 10.0) for _ in range(count)]
    slopes = [rng.uniform(-1.0, 1.0, k) for _ in range(count)]
    targets = [b + a @ (lower + rng.uniform(0, 1, k) * (upper - lower)) for b, a in zip(intercepts, slopes)]
    surrogates = {n: _linear(n, factors, b, a) for n, b, a in zip(names, intercepts, slopes)}
    best = _smallest_tolerance(lower, upper, intercepts, slopes, targets)
    return surrogates, Domain(tuple(factors), tuple(lower), tuple(upper)), names, dict(zip(names, targets)), best


@pytest.mark.parametrize("seed", [12, 13, 16, 23, 45, 59, 70])
def test_a_set_a_thousandth_wider_than_a_point_is_found(seed):
    """0.1 % above the minimax tolerance the set of points meeting every target is a sliver around the minimax
    point, far thinner than any grid cell: the search still finds it (and, as above, nothing below the minimax
    tolerance)."""
    surrogates, domain, names, targets, best = _study(seed)
    assert best > 0.0
    assert _met_together(surrogates, domain, names, targets, best * 1.001)

"""The closest approach of a strict set the box cannot hold, against closed forms: bowls
``y_k = c_k + sum_i q_ki (x_i - m_i)^2`` (search units, any factor on a log scale) whose targets lie beyond
their lowest values (or, for a negative c_k, beyond their highest: q_ki < 0), all lowest at one point m inside
the box but off every grid node.  The smallest largest relative error over the box is then
max_k |c_k - t_k| / |t_k|, reached at m, whether the search starts from a grid node (``grid=True``: the
figure's node mask) or from the small start grid; a grid node's larger error must not replace it."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.design import quadratic_terms
from demid.sampling import Domain
from demid.sampling.evaluate import EXACT_METHOD, closest_approach, evaluate_set
from demid.surrogate import Surrogate


def _bowl(name, factors, logs, c, q, m) -> Surrogate:
    """c + sum_i q_i (x_i - m_i)^2 written in the quadratic terms' own coefficients."""
    terms = quadratic_terms(len(factors))
    coef = np.zeros(len(terms))
    for j, term in enumerate(terms):  # a term is its exponent of each factor
        powers = np.asarray(term, dtype=int)
        i = int(np.argmax(powers))
        if powers.sum() == 0:
            coef[j] = c + float(np.sum(q * m ** 2))
        elif powers.sum() == 1:
            coef[j] = -2 * q[i] * m[i]
        elif powers.max() == 2:
            coef[j] = q[i]
    return Surrogate(name, list(factors), terms, coef, np.zeros((len(terms), len(terms))), 0.0, 5,
                     log_factors=tuple(f for f, lg in zip(factors, logs) if lg))


def _study(seed, dim, logs, k_obs):
    rng = np.random.default_rng(seed)
    factors = tuple(f"f{i}" for i in range(dim))
    lower = np.where(logs, 10.0 ** rng.uniform(-3, 1, dim), rng.normal(size=dim) * 3)
    upper = np.where(logs, lower * 10.0 ** rng.uniform(0.5, 2, dim), lower + rng.uniform(0.5, 5, dim))
    domain = Domain(factors, tuple(lower), tuple(upper), log=tuple(logs))
    lo, hi = domain.search_bounds()
    # the lowest point: inside the box, a third of a grid step (or more) from every node of 11 or 21 per axis
    m = lo + (hi - lo) * (rng.integers(2, 8, dim) / 10 + rng.uniform(0.017, 0.033, dim))
    surrogates, targets, errors = {}, {}, []
    for k in range(k_obs):
        sign = rng.choice([-1.0, 1.0])
        c = sign * 10.0 ** rng.uniform(-2, 3)
        q = sign * abs(c) * rng.uniform(0.5, 4, dim) / (hi - lo) ** 2  # curved away from the target
        target = c * (1 - rng.uniform(0.05, 0.6))  # same sign, nearer zero: the bowl never comes down to it
        surrogates[f"y{k}"] = _bowl(f"y{k}", factors, logs, c, q, m)
        targets[f"y{k}"] = float(target)
        errors.append(abs(c - target) / abs(target))
    return domain, surrogates, targets, m, max(errors)


@given(seed=st.integers(0, 10_000), dim=st.integers(1, 3), k_obs=st.integers(1, 3), data=st.data(),
       grid=st.booleans(), n=st.sampled_from([11, 21]))
@settings(max_examples=12, deadline=None, derandomize=True)
def test_the_closest_approach_of_an_unreachable_bowl_is_its_lowest_point(seed, dim, k_obs, data, grid, n):
    logs = data.draw(st.lists(st.booleans(), min_size=dim, max_size=dim))
    domain, surrogates, targets, m, closest = _study(seed, dim, logs, k_obs)
    names = list(surrogates)
    tolerance = closest / 3
    aset = evaluate_set(surrogates, domain, names, targets, tolerance, n, grid=grid)
    assert aset.method == EXACT_METHOD
    assert aset.fraction == 0.0 and aset.fraction_error == 0.0
    assert np.all(np.isnan(aset.lower)) and np.all(np.isnan(aset.upper))
    assert aset.at_bound == ("none",) * dim
    assert aset.best_error == pytest.approx(closest, rel=1e-9)
    lo, hi = domain.search_bounds()
    np.testing.assert_allclose((domain.to_search(aset.best_point[None])[0] - lo) / (hi - lo),
                               (m - lo) / (hi - lo), atol=2e-4)
    # every node is farther from the targets than the lowest point: the search moved off the grid
    nodes = domain.grid(n)
    node_errors = np.max([np.abs(surrogates[o].predict(nodes) - targets[o]) / abs(targets[o]) for o in names],
                         axis=0)
    assert node_errors.min() > closest * (1 + 1e-7)
    if grid:
        np.testing.assert_array_equal(aset.mask, np.zeros(n ** dim, dtype=bool))


@given(seed=st.integers(0, 10_000), dim=st.integers(1, 3), k_obs=st.integers(1, 3),
       start_at=st.sampled_from(["none", "corner", "centre"]))
@settings(max_examples=8, deadline=None, derandomize=True)
def test_closest_approach_from_any_start_reaches_the_lowest_point(seed, dim, k_obs, start_at):
    domain, surrogates, targets, m, closest = _study(seed, dim, [False] * dim, k_obs)
    start = {"none": None, "corner": np.array([domain.lower]), "centre": domain.from_unit(np.full((1, dim), 0.5))}
    value, point = closest_approach(surrogates, domain, list(surrogates), targets, start[start_at])
    assert value == pytest.approx(closest, rel=1e-9)
    lo, hi = domain.search_bounds()
    np.testing.assert_allclose((point - lo) / (hi - lo), (m - lo) / (hi - lo), atol=2e-4)

"""The closest approach of a set no point of the box reaches, when the largest error has two basins: its value
is the lower basin's, found by brute force (a fine grid, then scipy's bounded search from its best node), not
the basin of the start grid's best node.

``y1 = 1 + K (a - p)(a - q) + c (b - m)^2`` meets its target 1 on two curves, ``y2 = 1 + d + s a + r b`` (d, r >= 0;
both targets 1) grows along a and b, so the largest relative error has a basin near a = p and one near a = q, the lower
at p; on the start grid the node nearest q may well be the best one (the bottoms lie between nodes)."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import optimize

from demid.sampling import Domain
from demid.sampling.evaluate import closest_approach, evaluate_set
from demid.surrogate import Surrogate


def _surrogates(dim, p, q, k, s, c, m, r, d):
    if dim == 1:
        terms = [(0,), (1,), (2,)]
        y1 = [1 + k * p * q, -k * (p + q), k]
        y2 = [1.0 + d, s, 0.0]
    else:
        terms = [(0, 0), (1, 0), (2, 0), (0, 1), (0, 2)]
        y1 = [1 + k * p * q + c * m * m, -k * (p + q), k, -2 * c * m, c]
        y2 = [1.0 + d, s, 0.0, r, 0.0]
    factors = ["a", "b"][:dim]
    cov = np.zeros((len(terms), len(terms)))
    return {name: Surrogate(name, factors, terms, np.array(coef, dtype=float), cov, 0.0, 5)
            for name, coef in (("y1", y1), ("y2", y2))}


def _brute_force(surrogates, dim):
    """The lowest largest error on a fine grid of the unit box, refined by a bounded search from its best node."""
    axis = np.linspace(0.0, 1.0, 2001 if dim == 1 else 201)
    nodes = np.stack(np.meshgrid(*[axis] * dim, indexing="ij"), axis=-1).reshape(-1, dim)

    def worst(x):
        return np.max([np.abs(surrogates[o].predict(x) - 1.0) for o in ("y1", "y2")], axis=0)

    best = nodes[int(np.argmin(worst(nodes)))]
    # min t subject to |e_k(x)| <= t: smooth constraints, no kink for the search to stall on
    errors = [lambda z, o=o: surrogates[o].predict(z[None, :dim])[0] - 1.0 for o in ("y1", "y2")]
    constraints = [{"type": "ineq", "fun": lambda z, e=e, sign=sign: z[dim] - sign * e(z)}
                   for e in errors for sign in (1.0, -1.0)]
    res = optimize.minimize(lambda z: z[dim], np.append(best, worst(best[None])[0]), method="SLSQP",
                            bounds=[(0.0, 1.0)] * dim + [(0.0, None)], constraints=constraints,
                            options={"ftol": 1e-15, "maxiter": 500})
    return min(float(worst(np.clip(res.x[None, :dim], 0.0, 1.0))[0]), float(worst(best[None])[0]))


@given(seed=st.integers(0, 10_000), dim=st.integers(1, 2), grid=st.booleans())
@settings(max_examples=12, deadline=None, derandomize=True)
def test_the_closest_approach_is_the_lower_of_two_basins(seed, dim, grid):
    rng = np.random.default_rng(seed)
    p = rng.uniform(0.1, 0.35)
    q = rng.uniform(p + 0.35, 0.9)
    surrogates = _surrogates(dim, p, q, k=rng.uniform(5, 40), s=rng.uniform(0.05, 1.0), c=rng.uniform(0.5, 3),
                             m=rng.uniform(0.2, 0.8), r=rng.uniform(0.0, 0.05),
                             d=0.0 if seed % 2 == 0 else rng.uniform(0.1, 1.0))
    domain = Domain(tuple(["a", "b"][:dim]), (0.0,) * dim, (1.0,) * dim)
    want = _brute_force(surrogates, dim)
    value, point = closest_approach(surrogates, domain, ("y1", "y2"), {"y1": 1.0, "y2": 1.0}, None)
    assert value == pytest.approx(want, rel=1e-6, abs=1e-12)
    errors = [abs(float(surrogates[o].predict(point[None])[0]) - 1.0) for o in ("y1", "y2")]
    assert max(errors) == pytest.approx(value, rel=1e-9)
    tolerance = want / 2  # nothing within it: the set is empty and its closest approach is reported
    aset = evaluate_set(surrogates, domain, ("y1", "y2"), {"y1": 1.0, "y2": 1.0}, tolerance, 11, grid=grid)
    assert aset.fraction == 0.0
    assert aset.best_error == pytest.approx(want, rel=1e-6, abs=1e-12)


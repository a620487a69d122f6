"""The evaluator's choices at their boundaries, against rules written out here: polynomial surrogates of exactly three
factors get the exact set and four do not, nor surrogates on other log scales or factors in another order; the
search's start grid is 21 nodes a side up to three factors and 5 from four, in unit coordinates; the signed relative
errors at points of the unit cube against the predictions taken by hand (targets of either sign, log factors)."""

from __future__ import annotations

import itertools

import numpy as np
import pandas as pd
import pytest

from demid.sampling import Domain
from demid.sampling.evaluate import relative_errors, start_nodes, uses_exact
from demid.surrogate import fit_response


def _linear_surrogate(factors, log_factors=(), seed=0, sign=1.0):
    rng = np.random.default_rng(seed)
    k = len(factors)
    x = rng.uniform(1.0, 4.0, size=(3 * k + 4, k))
    table = pd.DataFrame(x, columns=factors)
    table["y"] = sign * (5.0 + x @ rng.uniform(0.5, 1.5, k)) + rng.normal(scale=0.01, size=len(x))
    terms = [tuple(0 for _ in factors)] + [tuple(int(i == j) for i in range(k)) for j in range(k)]
    return fit_response(table, list(factors), "y", terms=terms, log_factors=tuple(log_factors)).surrogate()


def _domain(k, log=()):
    names = tuple(f"f{i}" for i in range(k))
    return Domain(names, (1.0,) * k, (4.0,) * k, log=tuple(n in log for n in names))


@pytest.mark.parametrize("k, exact", [(1, True), (2, True), (3, True), (4, False)])
def test_polynomials_of_up_to_three_factors_are_exact(k, exact):
    domain = _domain(k)
    surrogates = {"y": _linear_surrogate(domain.factors), "w": _linear_surrogate(domain.factors, seed=1)}
    assert uses_exact(surrogates, ["y", "w"], domain) is exact


def test_other_log_scales_or_factor_orders_are_not_exact():
    domain = _domain(2, log=("f0",))
    assert uses_exact({"y": _linear_surrogate(domain.factors, ("f0",))}, ["y"], domain)
    assert not uses_exact({"y": _linear_surrogate(domain.factors)}, ["y"], domain)
    assert not uses_exact({"y": _linear_surrogate(domain.factors, ("f0", "f1"))}, ["y"], domain)
    assert not uses_exact({"y": _linear_surrogate(("f1", "f0"), ("f0",))}, ["y"], domain)
    # one observable that is not a polynomial surrogate: the set is the grid's
    plain = _linear_surrogate(domain.factors, ("f0",))

    class Field:
        factors, log_factors = plain.factors, plain.log_factors

        def predict(self, x):
            return plain.predict(x)

    assert not uses_exact({"y": plain, "z": Field()}, ["y", "z"], domain)
    assert uses_exact({"y": plain, "z": Field()}, ["y"], domain)


@pytest.mark.parametrize("k, per_axis", [(1, 21), (2, 21), (3, 21), (4, 5)])
def test_the_start_grid_is_21_a_side_up_to_three_factors_and_5_beyond(k, per_axis):
    domain = _domain(k, log=("f0",))
    nodes = start_nodes(domain)
    want = np.array(list(itertools.product(np.linspace(0, 1, per_axis), repeat=k)))
    assert nodes.shape == want.shape
    np.testing.assert_allclose(nodes, want, atol=1e-12)


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_relative_errors_at_unit_points(sign):
    domain = _domain(3, log=("f1",))
    surrogates = {"y": _linear_surrogate(domain.factors, ("f1",), sign=sign),
                  "w": _linear_surrogate(domain.factors, ("f1",), seed=4)}
    targets = {"y": sign * 9.0, "w": 7.5}
    u = np.random.default_rng(2).random((6, 3))
    search = np.column_stack([1 + 3 * u[:, 0], np.log10(1.0) + np.log10(4.0) * u[:, 1], 1 + 3 * u[:, 2]])
    x = search.copy()
    x[:, 1] = 10.0 ** search[:, 1]
    got = relative_errors(surrogates, domain, ["w", "y"], targets, u)
    want = np.stack([(surrogates[o].predict(x) - targets[o]) / abs(targets[o]) for o in ("w", "y")])
    np.testing.assert_allclose(got, want, rtol=1e-12, atol=1e-14)

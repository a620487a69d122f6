"""A polished Pareto front (demid.pareto.polish_front) against a study whose true front is known in closed form:
the capped response is y* (1 + m + s) with s the mean of the factors over the range's width (its relative error is
m + s: m = 0 reaches the target, m = 0.1 misses it by a tenth at least), the minimised one -s plus a penalty for
unequal factors, so the best objective at error e is m - e, reached where every factor is 2 (e - m).  Targets of
either sign, of magnitude one and not: every front point under the cap is such an optimum (the intervals a user
reads are taken over them), the front starts at the first cap (or at the least error there is) and ends at the
least objective, error 1 + m, exactly on the top of the search range; errors that agree after rounding
error / max_error to 9 decimals are one point (the one with the lower objective), errors farther apart are points
of their own."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from demid.pareto import pareto_analysis, polish_front
from demid.sampling import Domain


class Field:
    def __init__(self, f):
        self.f = f

    def predict(self, x):
        return self.f(np.atleast_2d(np.asarray(x, dtype=float)))


def _share(x):
    return x.mean(axis=1) / 2.0  # the factors run over [0, 2]


def _study(dim, target, max_error, nodes, levels, miss=0.0):
    names = [f"f{i}" for i in range(dim)]
    domain = Domain(tuple(names), (0.0,) * dim, (2.0,) * dim)
    capped = Field(lambda x: target * (1.0 + miss + _share(x)))
    objective = Field(lambda x: -_share(x) + 0.3 * np.sum((x - x.mean(axis=1, keepdims=True)) ** 2, axis=1))
    grid = pd.DataFrame(nodes, columns=names)
    grid["y1"], grid["y2"] = capped.predict(nodes), objective.predict(nodes)
    sampled = pareto_analysis(grid, names, "y1", target, "y2", max_error)
    front = polish_front({"y1": capped, "y2": objective}, domain, names, "y1", target, "y2", max_error,
                         sampled.front, levels=levels)
    return front, names, capped, objective


@pytest.mark.parametrize("dim", [2, 4])
@pytest.mark.parametrize("target, miss", [(14.0, 0.0), (1.0, 0.1), (-1.0, 0.0), (-0.37, 0.1)])
def test_every_polished_point_under_the_cap_is_an_optimum_and_the_front_ends_on_the_range(dim, target, miss):
    max_error, levels = 0.3, 7
    nodes = np.random.default_rng(dim).uniform(0.0, 2.0, (16, dim))
    front, names, capped, objective = _study(dim, target, max_error, nodes, levels, miss)
    x = front[names].to_numpy(dtype=float)
    error, value = front["error"].to_numpy(), front["objective"].to_numpy()
    np.testing.assert_allclose(error, np.abs(capped.predict(x) - target) / abs(target), rtol=1e-9, atol=1e-15)
    np.testing.assert_allclose(value, objective.predict(x), rtol=1e-12, atol=1e-15)
    under = error < max_error
    caps = np.linspace(0.0, max_error, levels)[1:]
    assert under.sum() >= np.sum((caps >= miss) & (caps < max_error))  # a point at every cap it can meet at least
    np.testing.assert_allclose(value[under], miss - error[under], rtol=0, atol=1e-9)  # on the true front
    if miss:
        assert error.min() == pytest.approx(miss, rel=1e-9)  # the least error there is
    else:
        assert error.min() <= max_error / (levels - 1) * (1 + 1e-6)  # polished from the first cap on
    # the front's end: the least objective, every factor at the top of its range, exactly
    end = int(np.argmin(value))
    assert error[end] == pytest.approx(1.0 + miss, rel=1e-9) and np.all(x[end] == 2.0)


def test_errors_agreeing_to_a_billionth_of_the_cap_are_one_point_and_others_stay_apart():
    max_error, levels = 0.001, 6  # caps 0.0002, 0.0004, ..., 0.001
    a, b = 0.0004, 0.0004 + 3e-7 * max_error  # 3e-7 of the cap apart: two points
    c, d = 0.0007, 0.0007 + 2e-10 * max_error  # 2e-10 of the cap apart: one point, the lower objective (d)
    optima = [a, b, c, d, 1.0]
    nodes = np.vstack([np.full((1, 2), 2.0 * e) for e in optima])
    front, _, _, _ = _study(2, 2.5, max_error, nodes, levels)
    under = front[front["error"] < max_error]
    expected = [0.0002, a, b, 0.0006, d, 0.0008]
    np.testing.assert_allclose(under["error"].to_numpy(), expected, rtol=0, atol=1e-15)
    np.testing.assert_allclose(under["objective"].to_numpy(), [-e for e in expected], rtol=0, atol=1e-15)

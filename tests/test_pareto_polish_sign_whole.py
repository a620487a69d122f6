"""A polished Pareto front does not depend on the sign convention of the response whose error it caps: the same
study written with that response and its target negated gives the same front, row for row, and every row's error
is |prediction - target| / |target| recomputed at its factors (never negative), its objective the prediction
there; no row is dominated by another.  Targets of either sign, two and three factors, caps that the polish
reaches from below and above the sampled front."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from demid.pareto import pareto_analysis, pareto_front, polish_front
from demid.sampling import Domain


class Field:
    def __init__(self, f):
        self.f = f

    def predict(self, x):
        return self.f(np.atleast_2d(np.asarray(x, dtype=float)))


def _study(dim, sign, target, max_error):
    names = ["a", "b", "c"][:dim]
    domain = Domain(tuple(names), (0.0,) * dim, (2.0,) * dim)
    weights = np.array([1.0, 0.6, 0.3])[:dim]
    error_field = Field(lambda x: sign * (10 + 4 * x @ weights))
    objective = Field(lambda x: 50 + np.sum((x - 0.7) ** 2, axis=1) + 2 * x[:, 0])
    nodes = domain.grid(7 if dim == 3 else 11)
    grid = pd.DataFrame(nodes, columns=names)
    grid["y1"], grid["y2"] = error_field.predict(nodes), objective.predict(nodes)
    sampled = pareto_analysis(grid, names, "y1", sign * target, "y2", max_error)
    front = polish_front({"y1": error_field, "y2": objective}, domain, names, "y1", sign * target, "y2",
                         max_error, sampled.front, levels=7)
    return front, names, error_field, objective


@pytest.mark.parametrize("dim, target, max_error", [(2, 14.0, 0.05), (3, 13.0, 0.08)])
def test_a_front_is_the_same_with_the_response_and_its_target_negated(dim, target, max_error):
    plus, names, error_plus, objective = _study(dim, 1.0, target, max_error)
    minus, _, error_minus, _ = _study(dim, -1.0, target, max_error)
    pd.testing.assert_frame_equal(plus, minus, check_exact=False, rtol=1e-9, atol=1e-9)
    for front, field, signed_target in ((plus, error_plus, target), (minus, error_minus, -target)):
        x = front[names].to_numpy(dtype=float)
        error = front["error"].to_numpy()
        assert np.all(error >= 0)
        np.testing.assert_allclose(error, np.abs(field.predict(x) - signed_target) / target, rtol=1e-9, atol=1e-12)
        np.testing.assert_allclose(front["objective"].to_numpy(), objective.predict(x), rtol=1e-12)
        assert np.array_equal(np.sort(pareto_front(error, front["objective"].to_numpy())), np.arange(len(front)))
    # the polish reached caps below the sampled front's least error: the front starts at (about) zero error
    assert plus["error"].min() <= max_error / 6 + 1e-9

"""A polished Pareto front whose optimum moves from one basin of the minimised response to another, against the
front in closed form: the polish under each error cap starts from the best sampled point under it (the one with the
least objective, in the basin where the optimum is), so past the crossing every front point is the optimum at its
error (the polished ones exactly, the sampled ones to the grid's step).  A target no grid node meets leaves the
smallest caps without a sampled point under them: their polish starts from the point of least error, in the basin
where the optimum is there, and the front's start is the optimum too."""

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


def _shift(a):
    # which basin of b is deeper: the one at b = 0.85 near a = 0.5 (shift > 0), the one at 0.15 below a = 0.34
    return 0.5 * (a - 0.3) - 0.02


def _objective(x):
    a, b = x[:, 0], x[:, 1]
    return 100 + 10 * (a - 0.3) ** 2 + 3 * np.minimum((b - 0.15) ** 2 + _shift(a), (b - 0.85) ** 2)


def _best(error, target):
    """The least objective at an error: a = (target - 10 - target e) / 10 (down to the unconstrained optimum
    a = 0.225), b in the deeper basin; the objective decreases along that path."""
    a = np.maximum((target - 10 - target * error) / 10, 0.225)
    return 100 + 10 * (a - 0.3) ** 2 + 3 * np.minimum(_shift(a), 0.0)


@pytest.mark.parametrize("target", [15.0, 15.05])
def test_past_the_basins_crossing_the_front_is_the_optimum_at_each_error(target):
    domain = Domain(("a", "b"), (0.0, 0.0), (1.0, 1.0))
    error_field = Field(lambda x: 10 + 10 * x[:, 0])  # error |10 + 10 a - target| / target
    objective = Field(_objective)
    nodes = domain.grid(31)
    grid = pd.DataFrame(nodes, columns=["a", "b"])
    grid["y1"], grid["y3"] = error_field.predict(nodes), objective.predict(nodes)
    sampled = pareto_analysis(grid, ["a", "b"], "y1", target, "y3", 0.02)
    front = polish_front({"y1": error_field, "y3": objective}, domain, ["a", "b"], "y1", target, "y3", 0.02,
                         sampled.front)
    error = front["error"].to_numpy()
    gap = front["objective"].to_numpy() - _best(error, target)
    assert np.all(gap >= -1e-9)  # nothing beats the optimum
    past = error > 0.115  # the deeper basin moved to b = 0.15 at a = 0.34, e = 0.107
    assert np.all(gap[past] <= 1e-3)  # the sampled points to about the grid's step, none in the other basin
    assert np.all(gap[error < 0.1] <= 1e-3)  # before the crossing too, from the front's start
    assert error.min() <= 0.001 + 1e-9
    assert np.sum(np.abs(gap[past]) <= 1e-7) >= 5  # polished points on the optimum
    assert np.all(np.abs(front.loc[past & (np.abs(gap) <= 1e-7), "b"].to_numpy() - 0.15) <= 1e-4)
    assert abs(error.max() - (target - 12.25) / target) <= 1e-5  # the front ends at the optimum, a = 0.225

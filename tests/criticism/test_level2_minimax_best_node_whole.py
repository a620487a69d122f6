"""Level 2's minimax search returns the point its value belongs to: when no local search improves on the best grid
node (the minimum sits on a node), the node itself, with its own value and shared bias."""

import itertools

import numpy as np
import pytest

from demid.criticism.searches import Level2Problem, minimax
from demid.sampling import Domain


class _Linear:
    """y = c + g . x (actual units)."""

    def __init__(self, c, g):
        self.c, self.g = float(c), np.asarray(g, dtype=float)

    def predict(self, x):
        return self.c + np.atleast_2d(x) @ self.g


@pytest.mark.parametrize("node", [(0.5, 0.5), (0.2, 0.9), (1.0, 0.0), (0.7, 0.3)])
@pytest.mark.parametrize("shared", [False, True])
def test_the_best_node_is_returned_with_its_own_value(node, shared):
    domain = Domain(("a", "b"), (0.0, 0.0), (1.0, 1.0), (False, False))
    # two observables each met on one line through the node: the node is the only point where both are met
    surrogates = {"y1": _Linear(10.0, (3.0, 1.0)), "y2": _Linear(20.0, (-1.0, 4.0))}
    targets = {o: float(s.predict(np.array(node))[0]) for o, s in surrogates.items()}
    problem = Level2Problem(surrogates, domain, targets, ["y1", "y2"])
    axis = np.linspace(0.0, 1.0, 11)
    grid_s = np.array(list(itertools.product(axis, axis)))
    grid_err = problem.errors(grid_s)
    value, point, delta = minimax(problem, grid_s, grid_err, [0, 1], shared=shared)
    assert value == pytest.approx(0.0, abs=1e-12)
    np.testing.assert_allclose(point, node, atol=1e-9)
    assert delta == pytest.approx(0.0, abs=1e-12)
    # the invariant on any input: the value is the largest weighted error at the returned point (less its bias)
    e = problem.errors(point)[:, 0]
    assert np.max(np.abs(e - delta)) == pytest.approx(value, abs=1e-12)

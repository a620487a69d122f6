"""Level 2's minimax search is a grid search polished by SLSQP: its value is never worse than the best grid node (a
brute force over the grid, written out here) and it is the largest weighted error at the point it returns.  Responses
with a sharp turn at a grid node (|x - x0| or its square root: no gradient there) make SLSQP step off the node to a
slightly worse point; the node itself must then be kept, with its own value, point and shared bias.  A smooth turn
(|x - x0|^2) is the control: there the polish stays on the node."""

import itertools

import numpy as np
import pytest

from demid.criticism.searches import Level2Problem, minimax
from demid.sampling import Domain


class _Kinked:
    """y = c + sum_i a_i |x_i - x0_i|^power (actual units): a response turning at x0, sharply for power <= 1."""

    def __init__(self, c, a, x0, power):
        self.c, self.a, self.x0 = float(c), np.asarray(a, dtype=float), np.asarray(x0, dtype=float)
        self.power = power

    def predict(self, x):
        return self.c + np.sum(self.a * np.abs(np.atleast_2d(x) - self.x0) ** self.power, axis=1)


def _brute_force(errors, weights, shared):
    """Per grid column: max_k w_k |e_k - delta| and delta, with delta = 0, or (two observables) the shared bias that
    leaves both equally far from it, w_1 (e_1 - delta) = w_2 (delta - e_2)."""
    if not shared:
        return np.max(weights[:, None] * np.abs(errors), axis=0), np.zeros(errors.shape[1])
    (w1, w2), (e1, e2) = weights, errors
    delta = (w1 * e1 + w2 * e2) / (w1 + w2)
    return w1 * np.abs(e1 - delta), delta


# (cases where SLSQP leaves the node within a few dozen steps: each search takes milliseconds)
@pytest.mark.parametrize("power, node, shared", [(1.0, (0.3,), True), (0.5, (0.3,), False), (0.5, (0.0, 0.6), False),
                                                 (0.5, (0.0, 0.6), True), (0.5, (0.5, 0.5, 0.5), False),
                                                 (2.0, (0.3, 0.8), True)])
def test_a_minimum_on_a_grid_node_is_kept_with_its_own_value(power, node, shared):
    d = len(node)
    node = np.array(node)
    domain = Domain(("a", "b", "c")[:d], (0.0,) * d, (1.0,) * d, (False,) * d)
    surrogates = {"y1": _Kinked(10.0, [5.0, 4.0, 3.0][:d], node, power),
                  "y2": _Kinked(20.0, [-3.0, -2.0, -4.0][:d], node, power)}
    # targets 3 % below y1 and 2 % above y2 at the node, both moving away from them off it: the smallest largest
    # error (with or without a shared bias) sits on the node, where both turn
    targets = {"y1": 10.0 * 0.97, "y2": 20.0 * 1.02}
    weights = np.array([1.0, 1.5])
    problem = Level2Problem(surrogates, domain, targets, ["y1", "y2"], weights)
    axis = np.linspace(0.0, 1.0, 5 if d == 3 else 11)
    grid_s = np.array(list(itertools.product(*[axis] * d)))
    grid_err = problem.errors(grid_s)
    # one local search (from the best node): the polish that steps off it is the one to be rejected
    value, point, delta = minimax(problem, grid_s, grid_err, [0, 1], shared=shared, starts=1)
    worst, best_delta = _brute_force(grid_err, weights, shared)
    best = int(np.argmin(worst))
    np.testing.assert_allclose(grid_s[best], node, atol=1e-12)
    assert value <= worst.min() + 1e-15  # never worse than the best grid node
    assert value == pytest.approx(worst.min(), rel=1e-9)
    np.testing.assert_array_equal(point, grid_s[best])  # the node itself, not a point SLSQP stepped to
    e = problem.errors(point)[:, 0]
    assert np.max(weights * np.abs(e - delta)) == pytest.approx(value, rel=1e-12)
    assert delta == pytest.approx(best_delta[best], rel=1e-9, abs=1e-15)

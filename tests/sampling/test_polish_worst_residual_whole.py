"""A polished span end is kept only when every observable is inside its band there: one observable met everywhere
and another whose response jumps out of its band past a step (a flat gradient the optimiser cannot see, so it runs
to the domain's bound) leave the grid's span ends as they are; either sign of the targets, either order of the
observables, the step on either side."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.sampling import Domain
from demid.sampling.grid import admissible_set
from demid.sampling.polish import polish_spans


class Flat:
    def __init__(self, value):
        self.value = float(value)

    def predict(self, x):
        return np.full(len(np.atleast_2d(x)), self.value)


class Step:
    """``target`` on the inside of ``edge``, ``target * (1 + jump)`` beyond it (above if ``above``, else below)."""

    def __init__(self, target, edge, jump, above):
        self.target, self.edge, self.jump, self.above = float(target), float(edge), float(jump), above

    def predict(self, x):
        a = np.atleast_2d(x)[:, 0]
        beyond = a > self.edge if self.above else a < self.edge
        return np.where(beyond, self.target * (1 + self.jump), self.target)


@given(sign=st.sampled_from([-1.0, 1.0]), scale=st.sampled_from([0.02, 1.0, 300.0]), flat_first=st.booleans(),
       above=st.booleans(), edge=st.sampled_from([0.58, 0.62, 0.7, 0.74]))
@settings(max_examples=10, deadline=None, derandomize=True)
def test_an_end_outside_one_band_is_not_taken(sign, scale, flat_first, above, edge):
    eps = 0.1
    t_flat, t_step = sign * scale, -sign * 2.5 * scale
    if not above:
        edge = 1.0 - edge
    names = ["flat", "step"] if flat_first else ["step", "flat"]
    surrogates = {"flat": Flat(t_flat), "step": Step(t_step, edge, 3 * eps, above)}
    targets = {"flat": t_flat, "step": t_step}
    domain = Domain(("a", "b"), (0.0, 0.0), (1.0, 1.0))
    aset = admissible_set(surrogates, domain, names, targets, eps, 7)
    grid_end = aset.upper[0] if above else aset.lower[0]
    assert abs(grid_end - edge) < 1 / 6  # the grid's span ends in the step's grid cell, on its inside
    lower, upper = polish_spans(surrogates, domain, names, targets, eps, aset)
    # the side without a step reaches the domain's bound; the other keeps the grid's end (never beyond the step)
    if above:
        assert lower[0] == 0.0 and grid_end <= upper[0] <= edge
    else:
        assert upper[0] == 1.0 and edge <= lower[0] <= grid_end
    # the other factor does not matter: its span is the whole domain
    assert (lower[1], upper[1]) == (0.0, 1.0)
    for end in (lower, upper):
        for o in names:
            y = surrogates[o].predict(end[None, :])[0]
            assert abs(y - targets[o]) <= eps * abs(targets[o]) * (1 + 1e-9)

"""Edges of the exact sets' inputs and tables, each against the rule as stated: exact_set refuses any target
that is not finite or is zero, wherever it stands among two to four observables (not only when it is the only
one), and the breakpoint table of owners without a single finite value still has one (NaN) column per owner."""

from __future__ import annotations

import numpy as np
import pytest

from demid.sampling.exact import Polynomial, exact_set
from demid.sampling.roots import ragged


@pytest.mark.parametrize("n_obs", [2, 3, 4])
@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf, 0.0])
def test_exact_set_refuses_one_bad_target_among_several_wherever_it_stands(n_obs, bad):
    poly = Polynomial(np.array([[0, 0], [1, 0], [0, 1]]), np.array([1.0, 2.0, -1.0]))
    for position in range(n_obs):
        targets = [1.5 * (-1) ** i for i in range(n_obs)]
        targets[position] = bad
        with pytest.raises(ValueError, match="every target must be finite, non-zero"):
            exact_set([poly] * n_obs, targets, 0.1, [0.0, 0.0], [1.0, 1.0])
    # the same targets, every one finite and non-zero, are accepted
    exact_set([poly] * n_obs, [1.5 * (-1) ** i for i in range(n_obs)], 0.1, [0.0, 0.0], [1.0, 1.0])


@pytest.mark.parametrize("n_owners", [1, 2, 5])
def test_a_breakpoint_table_without_a_finite_value_has_one_nan_column_per_owner(n_owners):
    owners = np.arange(3 * n_owners) % n_owners
    values = np.full(3 * n_owners, np.nan)
    values[::2] = np.inf
    table = ragged(owners, values, n_owners)
    assert table.shape == (n_owners, 1)
    assert np.isnan(table).all()

"""The next wave does not depend on where the factors' ranges lie: the same study moved along both factors (here
from ranges below zero to ranges above it, exact binary numbers, a face-centred design with runs on the box's
faces) plans the same runs moved by the same amount, the box and the runs it keeps as earlier ones included."""

from __future__ import annotations

import numpy as np
import pytest

from demid.next_wave import plan_next_wave

from .helpers import one_response_study


def _wave(shift: float, count: int):
    lower, upper = np.array([-3.0, -2.0]) + shift, np.array([-1.0, 0.0]) + shift
    centre = np.array([-2.25, -0.75]) + shift

    def responses(x):
        return {"y": 4.0 + ((x - centre) ** 2).sum(axis=1)}

    table, spec, surrogates, plausible = one_response_study(responses, lower, upper, 4.5, count, 0.5)
    return plan_next_wave("m", table, surrogates, spec, plausible, z=2.0)


@pytest.mark.parametrize("count", [3, 8])
def test_a_study_moved_along_its_factors_plans_the_same_runs_moved(count):
    below, above = _wave(0.0, count), _wave(16.0, count)
    np.testing.assert_allclose(above.domain[["lower", "upper"]].to_numpy(),
                               below.domain[["lower", "upper"]].to_numpy() + 16.0, atol=1e-9)
    assert len(below.runs) == len(above.runs) == count
    np.testing.assert_allclose(above.runs[["a", "b"]].to_numpy(), below.runs[["a", "b"]].to_numpy() + 16.0,
                               atol=1e-6)
    assert list(above.runs["purpose"]) == list(below.runs["purpose"])


@pytest.mark.parametrize("k", [2, 3])
def test_runs_separating_aliased_terms_over_omega_move_with_the_range(k):
    """a²b aliased with b in a two-level factorial with centre runs (a² = 1 on every corner): the runs that separate them are chosen
    in the range's own coding, so the same range and runs moved by a shift give the same runs moved."""
    from itertools import product

    from demid.next_wave import _separating_over_omega

    lo, hi = np.full(k, -3.0), np.full(k, 1.0)
    corners = np.array(list(product(*zip(lo, hi))))
    existing = np.vstack([corners, np.full((2, k), -1.0)])
    squares = (tuple([2, 1] + [0] * (k - 2)), tuple([0, 1] + [0] * (k - 2)))
    alias_sets = [(squares, ["y"])]
    below, labels = _separating_over_omega(alias_sets, existing, lo, hi, 10)
    above, moved_labels = _separating_over_omega(alias_sets, existing + 16.0, lo + 16.0, hi + 16.0, 10)
    assert len(below) >= 1 and labels == moved_labels == [(squares, ["y"])] * len(below)
    np.testing.assert_allclose(above, below + 16.0, atol=1e-9)
    # each lies in the range, on the levels of its coding
    assert np.all((below >= lo - 1e-9) & (below <= hi + 1e-9))

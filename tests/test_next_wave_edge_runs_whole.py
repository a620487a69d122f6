"""An earlier run on the next box's edge counts as inside it up to round-off of the box's own range, not of 1: a
run 1e-13 of the range past a face (what a sheet's printed digits or a unit conversion leaves of a run on the
bound) still counts among the earlier runs the next wave is planned around, whatever the range's scale (ranges
of 20 and of 2e-6), and a run 1e-9 of the range past it does not."""

from __future__ import annotations

import re

import numpy as np
import pytest

from demid.next_wave import plan_next_wave

from .helpers import one_response_study


def _study(lower, upper):
    lower, upper = np.asarray(lower, float), np.asarray(upper, float)

    def responses(x):  # nearly flat: the plausible set fills the range and the box is the whole range
        return {"y": 4.0 + 1e-3 * (((x - lower) / (upper - lower)) ** 2).sum(axis=1)}

    return one_response_study(responses, lower, upper, 4.0, 6, 0.5)


def _moved_off_the_faces(table, lower, upper, share):
    """The runs on a face moved ``share`` of the range outwards."""
    moved = table.copy()
    for j, f in enumerate("ab"):
        step = share * (upper[j] - lower[j])
        moved[f] = np.where(table[f] == upper[j], upper[j] + step,
                            np.where(table[f] == lower[j], lower[j] - step, table[f]))
    return moved


def _earlier_inside(reason: str) -> int:
    return int(re.search(r"given the (\d+) earlier run\(s\) inside the box", reason).group(1))


@pytest.mark.parametrize("lower, upper", [([10.0, 20.0], [30.0, 50.0]), ([1e-6, 2e-6], [3e-6, 5e-6])])
def test_runs_a_round_off_past_the_box_count_as_earlier_runs_inside_it(lower, upper):
    lower, upper = np.asarray(lower), np.asarray(upper)
    table, spec, surrogates, plausible = _study(lower, upper)
    plan = plan_next_wave("m", table, surrogates, spec, plausible, z=2.0)
    np.testing.assert_array_equal(plan.domain[["lower", "upper"]].to_numpy(), np.column_stack([lower, upper]))
    assert _earlier_inside(plan.reason) == len(table)  # a face-centred CCD: every run in the range

    nudged = plan_next_wave("m", _moved_off_the_faces(table, lower, upper, 1e-13), surrogates, spec, plausible,
                            z=2.0)
    assert _earlier_inside(nudged.reason) == len(table)
    assert nudged.reason == plan.reason
    np.testing.assert_allclose(nudged.runs[["a", "b"]].to_numpy(), plan.runs[["a", "b"]].to_numpy(),
                               rtol=0, atol=1e-9 * float(np.max(upper - lower)))

    # a billionth of the range past a face is outside: the runs on a face are left out, those on none kept
    off = plan_next_wave("m", _moved_off_the_faces(table, lower, upper, 1e-9), surrogates, spec, plausible, z=2.0)
    on_no_face = int(np.sum(np.all((table[["a", "b"]].to_numpy() != lower) & (table[["a", "b"]].to_numpy() != upper),
                                   axis=1)))
    assert _earlier_inside(off.reason) == on_no_face

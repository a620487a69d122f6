"""The ranking walk's first sentences, the targets no set can meet, written out here for rankings of three
observables listed in any order: one, two or three targets out of reach alone (singular or plural wording, named
in the ranking's order), and targets each within reach whose pairs cannot be met together (each conflict named
once, smallest sets first, then by name, whatever the table's row order).  The observables are named in the
ranking's order (r, p, q), not the alphabet's."""

from __future__ import annotations

from itertools import combinations

import numpy as np
import pandas as pd
import pytest

from demid.story.measurements import measurement_order

NAMES = ("r", "p", "q")  # the ranking's order, not the alphabet's
LABELS = {"p": "P", "q": "Q", "r": "R"}


def _ranking(nan_sets, row_order) -> pd.DataFrame:
    sets = [s for size in (1, 2, 3) for s in combinations(NAMES, size)]
    rows = [{"observables": "+".join(s), "information_gain_bits": np.nan if s in nan_sets else 1.0 + len(s),
             "feasible_fraction_pct": 50.0 / len(s)} for s in sets]
    return pd.DataFrame([rows[i] for i in row_order])


@pytest.mark.parametrize("unreachable", [("q",), ("p", "r"), ("p", "q", "r")])
@pytest.mark.parametrize("reverse", [False, True])
def test_targets_out_of_reach_are_named_once_with_their_number(unreachable, reverse):
    nan_sets = {s for size in (1, 2, 3) for s in combinations(NAMES, size) if set(s) & set(unreachable)}
    order = list(range(7))[::-1] if reverse else list(range(7))
    lines = measurement_order(_ranking(nan_sets, order), LABELS)
    many = len(unreachable) > 1
    named = " + ".join(LABELS[o] for o in NAMES if o in unreachable)
    assert lines[0] == (f"The target{'s' if many else ''} of {named} cannot be met anywhere in the search range within "
                        "the tolerance: a discrepancy between simulation and experiment (see level 2), not information. "
                        f"Sets with {'them' if many else 'it'} get no information gain and rank last; the advice below "
                        f"leaves {'them' if many else 'it'} out.")
    assert not any("can each be met but not together" in line for line in lines)
    assert all(LABELS[o] not in line.split(":")[0] for line in lines[1:] for o in unreachable
               if line.startswith(("As a first", "From")))


@pytest.mark.parametrize("row_order", [list(range(7)), [6, 5, 4, 3, 2, 1, 0], [0, 1, 2, 5, 4, 3, 6]])
def test_pairs_that_cannot_be_met_together_are_named_smallest_first_then_by_name(row_order):
    # r+p and p+q cannot be met together (nor, then, can all three); r+q can
    lines = measurement_order(_ranking({("r", "p"), ("p", "q"), ("r", "p", "q")}, row_order), LABELS)
    conflicts = [line for line in lines if "can each be met but not together" in line]
    assert conflicts == [f"The targets of {pair} can each be met but not together within the tolerance: a discrepancy "
                         "between simulation and experiment (see level 2), not information; sets with all of them get "
                         "no information gain and rank last." for pair in ("P + Q", "R + P")]
    assert lines[:2] == conflicts  # before the walk

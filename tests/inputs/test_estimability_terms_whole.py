"""The whole refusal of a design that cannot estimate the full quadratic (demid.estimability), over generated
designs of 2-4 factors: the rank quoted is numpy's (singular values above 1e-8 of the largest), the terms named
are exactly those a null vector of the model matrix involves (scipy's null_space), listed as a sentence in the
model's order, and the reason follows the design: factors at fewer than three levels are named; squares that
only move together (a two-level factorial with centre runs) get the advice to add axial runs.  Factor names
given or left to the default (x1, x2, ... : counted from one)."""

from __future__ import annotations

from itertools import product

import numpy as np
import pytest
from hypothesis import Phase, given, settings
from hypothesis import strategies as st
from scipy.linalg import null_space

from demid.design import model_matrix, quadratic_terms, term_name
from demid.errors import InputError
from demid.estimability import require_estimable

SETTINGS = settings(max_examples=10, deadline=None, derandomize=True, phases=[Phase.explicit, Phase.generate])


def _expected_detail(coded, names):
    terms = quadratic_terms(coded.shape[1])
    x = model_matrix(coded, terms)
    singular = np.linalg.svd(x, compute_uv=False)
    rank = int(np.sum(singular > 1e-8 * singular[0]))
    null = null_space(x, rcond=1e-8)
    term_names = ["intercept" if sum(t) == 0 else term_name(t, names) for t in terms]
    involved = [n for n, w in zip(term_names, np.abs(null).max(axis=1)) if w > 1e-6]
    listed = involved[0] if len(involved) == 1 else ", ".join(involved[:-1]) + f" and {involved[-1]}"
    text = f"the usable runs cannot tell {listed} apart"
    few = [f for i, f in enumerate(names) if len(np.unique(coded[:, i])) < 3]
    if few:
        text += f" ({', '.join(few)} at fewer than three levels: a squared term needs three)"
    elif sum(n.endswith("^2") for n in involved) > 1:
        text += (" (every run away from the centre has its squared terms equal, as in a two-level factorial "
                 "with centre runs); axial runs (a CCD) or a three-level factorial separate them")
    return f"the quadratic model cannot be estimated (rank {rank} of {len(terms)} terms): {text}"


def _refusal(coded, names):
    with pytest.raises(InputError) as info:
        require_estimable(coded, np.ones(len(coded), dtype=bool), None, "t.csv", "y", names)
    return info.value.detail


@given(k=st.integers(2, 4), centre=st.integers(1, 4), replicates=st.integers(1, 2), named=st.booleans())
@SETTINGS
def test_a_two_level_factorial_with_centre_runs_names_every_square(k, centre, replicates, named):
    corners = np.array(list(product((-1.0, 1.0), repeat=k)))
    coded = np.vstack([np.tile(corners, (replicates, 1)), np.zeros((centre, k))])
    p = (k + 1) * (k + 2) // 2
    if len(coded) <= p:  # too few runs is another refusal: add replicates of the centre
        coded = np.vstack([coded, np.zeros((p + 1 - len(coded), k))])
    names = [f"f{i}" for i in range(k)] if named else None
    shown = names or [f"x{i + 1}" for i in range(k)]
    detail = _refusal(coded, names)
    assert detail == _expected_detail(coded, shown)
    assert all(f"{f}^2" in detail for f in shown) and "intercept" not in detail  # the centre runs place it


@given(k=st.integers(2, 4), flat=st.data(), named=st.booleans())
@SETTINGS
def test_factors_at_two_levels_are_named_as_the_reason(k, flat, named):
    two = sorted(flat.draw(st.sets(st.integers(0, k - 1), min_size=1, max_size=k - 1)))
    levels = [(-1.0, 1.0) if i in two else (-1.0, 0.0, 1.0) for i in range(k)]
    coded = np.array(list(product(*levels)))
    while len(coded) <= (k + 1) * (k + 2) // 2:  # enough runs that only the rank can refuse
        coded = np.vstack([coded, coded])
    names = [f"g{i}" for i in range(k)] if named else None
    shown = names or [f"x{i + 1}" for i in range(k)]
    detail = _refusal(coded, names)
    assert detail == _expected_detail(coded, shown)
    assert detail.endswith(f"({', '.join(shown[i] for i in two)} at fewer than three levels: a squared term needs "
                           "three)")


def test_a_star_design_without_factor_names_counts_its_factors_from_one():
    k = 3
    axial = np.vstack([sign * 1.5 * np.eye(k) for sign in (-1.0, 1.0)])
    coded = np.vstack([axial, np.zeros((5, k))])
    assert _refusal(coded, None) == ("the quadratic model cannot be estimated (rank 7 of 10 terms): the usable runs "
                                     "cannot tell x1:x2, x1:x3 and x2:x3 apart")


@pytest.mark.parametrize("named", [True, False])
def test_one_square_confounded_with_a_factor_gets_no_two_level_advice(named):
    """A second factor set to the square of the first (five levels of x1, three of x2): only x2 and x1^2 move
    together; every factor has three levels or more and one square is involved, so neither reason is added."""
    x1 = np.repeat([-1.0, -0.5, 0.0, 0.5, 1.0], 2)
    coded = np.column_stack([x1, x1 ** 2])
    names = ["a", "b"] if named else None
    shown = names or ["x1", "x2"]
    detail = _refusal(coded, names)
    assert detail == _expected_detail(coded, shown)
    assert detail == (f"the quadratic model cannot be estimated (rank 5 of 6 terms): the usable runs cannot tell "
                      f"{shown[1]} and {shown[0]}^2 apart")

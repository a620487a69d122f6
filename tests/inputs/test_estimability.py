"""Whether a table's usable runs can estimate the full quadratic (demid.estimability), over designs of two to four
factors, spherical and face-centred CCDs, factorials with centre runs and failed runs: the decision, and the
numbers and terms its one-line message quotes, against the design's own counts."""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.design import ccd_points, classify_points, rotatable_alpha
from demid.errors import InputError
from demid.estimability import require_estimable

SETTINGS = settings(max_examples=15, deadline=None, derandomize=True)


def _refusal(coded, usable, types, factors=None) -> str:
    with pytest.raises(InputError) as info:
        require_estimable(coded, usable, types, "t.csv", "y", factors)
    assert info.value.source == "t.csv" and info.value.column == "y"
    return info.value.detail


@given(k=st.integers(2, 4), short=st.integers(0, 3))
@SETTINGS
def test_too_few_usable_runs_quotes_the_runs_the_coefficients_and_the_runs_needed(k, short):
    p = (k + 1) * (k + 2) // 2
    coded = ccd_points(k, rotatable_alpha(k), 5)
    usable = np.zeros(len(coded), dtype=bool)
    usable[:p - short] = True
    assert _refusal(coded, usable, None) == (
        f"only {p - short} usable runs for a quadratic model with {p} coefficients; at least {p + 1} are needed "
        f"(with {p} the fit is saturated and says nothing about its error)")


@given(k=st.integers(2, 4), centre=st.integers(1, 5), labelled=st.booleans())
@SETTINGS
def test_a_spherical_ccd_whose_centre_runs_failed_cannot_separate_intercept_and_squares(k, centre, labelled):
    alpha = np.sqrt(k)  # every non-centre point on the sphere of radius sqrt(k)
    coded = ccd_points(k, alpha, centre)
    types = classify_points(coded, alpha) if labelled else None
    usable = ~np.all(coded == 0, axis=1)
    detail = _refusal(coded, usable, types)
    assert detail.startswith("the quadratic model cannot be estimated: every usable run lies at the same distance")
    assert detail.endswith(f"(all {centre} centre run(s) failed); at least one centre run is needed" if labelled
                           else "; the design needs at least one centre run")


@given(k=st.integers(2, 4), centre=st.integers(1, 5))
@SETTINGS
def test_a_ccd_off_the_sphere_whose_centre_runs_failed_is_refused_as_extrapolated(k, centre):
    coded = ccd_points(k, 1.0, centre)  # face-centred: runs at radius 1 and sqrt(k)
    types = classify_points(coded, 1.0)
    usable = types != "center"
    assert _refusal(coded, usable, types).startswith(
        f"the quadratic model cannot be trusted: all {centre} centre run(s) failed, so its value at the design "
        "centre would be extrapolated")
    usable[np.flatnonzero(types == "center")[0]] = True  # one centre run is enough
    require_estimable(coded, usable, types, "t.csv", "y")


@given(k=st.integers(2, 3))
@SETTINGS
def test_a_three_level_factorial_without_axial_runs_needs_no_centre_run(k):
    """The centre-run rule is the CCD's (its centre is otherwise extrapolated from axial and factorial runs)."""
    coded = np.array(list(itertools.product([-1.0, 0.0, 1.0], repeat=k)))
    types = np.where(np.all(coded == 0, axis=1), "center", "factorial")
    require_estimable(coded, types != "center", types, "t.csv", "y")


@given(k=st.integers(2, 4), centre=st.integers(1, 4))
@SETTINGS
def test_a_two_level_factorial_with_centre_runs_names_its_confounded_squares(k, centre):
    coded = np.vstack([np.array(list(itertools.product([-1.0, 1.0], repeat=k))), np.zeros((centre, k))])
    p = (k + 1) * (k + 2) // 2
    if len(coded) <= p:
        coded = np.vstack([coded, coded[:p + 1 - len(coded)]])  # replicated corners: runs enough, squares still tied
    factors = [f"f{i}" for i in range(k)]
    detail = _refusal(coded, np.ones(len(coded), dtype=bool), None, factors)
    squares = [f"{f}^2" for f in factors]
    listed = ", ".join(squares[:-1]) + f" and {squares[-1]}"
    assert detail.startswith(f"the quadratic model cannot be estimated (rank {p - (k - 1)} of {p} terms): the usable "
                             f"runs cannot tell {listed} apart")
    assert "axial runs (a CCD) or a three-level factorial separate them" in detail


@given(k=st.integers(2, 4), flat=st.integers(0, 3))
@SETTINGS
def test_a_factor_at_two_levels_is_named_as_the_reason_its_square_cannot_be_fitted(k, flat):
    flat = flat % k
    coded = np.array(list(itertools.product([-1.0, 0.0, 1.0], repeat=k)))
    coded[:, flat] = np.where(coded[:, flat] == 0, 1.0, coded[:, flat])  # that factor at -1 and +1 only
    factors = [f"f{i}" for i in range(k)]
    detail = _refusal(coded, np.ones(len(coded), dtype=bool), None, factors)
    assert detail.startswith(f"the quadratic model cannot be estimated (rank {(k + 1) * (k + 2) // 2 - 1} of ")
    assert f"cannot tell intercept and f{flat}^2 apart" in detail
    assert detail.endswith(f"(f{flat} at fewer than three levels: a squared term needs three)")

"""Reported numbers at their boundaries: the printed form of a value (``value_text``), a reproduced number
rounding to a published one (``rounds_to``, ``printed_decimals``), the run sheet's accepted counts and a far
target's one-keystroke repair at the simulated range's ends; each against a rule written out in the test."""
from decimal import Decimal

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings, strategies as st

from demid.data import far_target_warnings
from demid.design_generation import _check_counts
from demid.errors import InputError
from demid.paper import printed_decimals, rounds_to
from demid.precision import MAX_DIGITS, UNCERTAINTY_DIGITS, ZERO, value_text

_FAST = settings(max_examples=60, derandomize=True, deadline=None)


def _place(x: float, digits: int) -> Decimal:
    """The power of ten of ``x``'s last kept digit once rounded to ``digits`` significant ones (by Decimal)."""
    rounded = Decimal(f"{abs(x):.{digits - 1}e}")
    return Decimal(1).scaleb(rounded.adjusted() - digits + 1)


@_FAST
@given(mantissa=st.floats(1.0, 9.99), exponent=st.integers(-7, 8), sign=st.sampled_from([-1.0, 1.0]),
       u_mantissa=st.floats(1.0, 9.99), u_shift=st.integers(-6, 3))
def test_value_text_is_the_value_at_the_uncertaintys_place_in_fixed_form_between_1e_4_and_1e6(
        mantissa, exponent, sign, u_mantissa, u_shift):
    value = sign * mantissa * 10.0 ** exponent
    uncertainty = u_mantissa * 10.0 ** (exponent + u_shift)
    place = max(_place(uncertainty, UNCERTAINTY_DIGITS), _place(value, MAX_DIGITS))
    text = value_text(value, uncertainty)
    if Decimal(abs(value)) < place / 2:
        assert text == ZERO
        return
    assert text != ZERO
    number = float(text.replace("−", "-"))
    assert np.sign(number) == sign
    exponential = not (1e-4 <= abs(value) < 10.0 ** (MAX_DIGITS + 2))
    assert ("e" in text) == exponential, (value, uncertainty, text)
    if exponential:
        kept = int(text.replace("−", "-").split("e")[0].replace("-", "").replace(".", "").lstrip("0") or "0")
        assert abs(number - value) <= float(place) / 2 * (1 + 1e-9) or len(str(kept)) == 1
    else:
        decimals = len(text.split(".")[1]) if "." in text else 0
        assert decimals == max(0, -place.adjusted()), (value, uncertainty, text)
        assert abs(number - value) <= float(place) / 2 * (1 + 1e-9)


@pytest.mark.parametrize("value, uncertainty, expected", [
    (1.5e6, 1e3, "1.5e+06"), (999_000.0, 1e3, "999000"), (5e4, 10.0, "50000"), (-2.5e6, 1e4, "−2.5e+06"),
    (1.2e-4, 1e-5, "0.000120"), (9.5e-5, 1e-6, "9.5e-05"), (0.4, 10.0, ZERO), (0.6, 10.0, "1"),
])
def test_value_text_known_answers_at_the_fixed_forms_ends(value, uncertainty, expected):
    assert value_text(value, uncertainty) == expected


@_FAST
@given(published=st.integers(-99_999, 99_999), decimals=st.integers(0, 4),
       units=st.sampled_from([0.0, 0.25, 0.49, 0.51, 0.75, 1.0, 2.0]), sign=st.sampled_from([-1, 1]))
def test_rounds_to_is_within_half_a_unit_of_the_last_printed_digit(published, decimals, units, sign):
    text = f"{Decimal(published).scaleb(-decimals):.{decimals}f}"
    assert printed_decimals(text) == decimals
    unit = 10.0 ** -decimals
    reproduced = float(text) + sign * units * unit
    assert rounds_to(reproduced, text, decimals) is (units <= 0.5)
    assert rounds_to(reproduced, float(text), decimals) is (units <= 0.5)


def test_rounds_to_on_the_half_unit_exactly_and_off_the_finite_numbers():
    # 0.5 and 1.5 are exact in binary: the half unit itself rounds to the published digit
    assert rounds_to(1.5, "1", 0) and rounds_to(0.5, "1", 0) and rounds_to(1.25, "1.2", 1)
    assert not rounds_to(1.5 + 1e-6, "1", 0) and not rounds_to(0.5 - 1e-6, "1", 0)
    for bad in (np.nan, np.inf, -np.inf):
        assert rounds_to(bad, "1", 0) is False


@pytest.mark.parametrize("text, decimals", [
    ("3.980", 3), ("0.0397", 4), ("12", 0), ("-4.5", 1), ("1.5e-05", 6), ("2E-3", 3), ("7.25e2", 0), (0.0397, 4),
])
def test_printed_decimals_of_quoted_and_exponent_forms(text, decimals):
    assert printed_decimals(text) == decimals


@pytest.mark.parametrize("design_type, n_factors, center_runs, accepted", [
    ("ccd", 1, 1, True), ("ccd", 6, 1, True), ("ccd", 7, 1, False), ("ccd", 0, 1, False),
    ("ccd", 2, 0, False), ("ccd", 2, 1, True), ("factorial", 2, 1, True), ("factorial", 2, 0, False),
    ("box_behnken", 3, 1, True), ("box_behnken", 5, 1, True), ("box_behnken", 2, 1, False),
    ("box_behnken", 6, 1, False), ("ccd", 3, -1, False),
])
def test_run_sheet_counts_accepted_exactly_at_their_bounds(design_type, n_factors, center_runs, accepted):
    if accepted:
        _check_counts(design_type, n_factors, center_runs)
    else:
        with pytest.raises(InputError):
            _check_counts(design_type, n_factors, center_runs)


@pytest.mark.parametrize("column", [[20.0, 23.0, 26.4], [26.4, 28.0, 30.0]])
def test_a_far_targets_decimal_shift_onto_either_end_of_the_runs_is_named(column):
    # 264 is far beyond both columns; its decimal shift 26.4 is exactly the highest (first) or lowest (second)
    # simulated value: still among the simulated values, so the slip is named, not a unit change
    table = pd.DataFrame({"y": column})
    (warning,) = far_target_warnings(table, {"y": 264.0}, "runs.csv")
    assert "looks like 26.4 with" in warning and "another unit" not in warning
    (moved,) = far_target_warnings(pd.DataFrame({"y": [c + (0.01 if c == 26.4 and c == max(column) else 0)
                                                      for c in column]}), {"y": 264.0}, "runs.csv")
    assert "looks like 26.4 with" in moved


@pytest.mark.parametrize("side", ["upper", "lower"])
@pytest.mark.parametrize("runs_range, refused", [(100.0, False), (20.0, True)])
def test_a_bound_a_swap_away_from_the_runs_extreme_is_refused_only_beyond_a_tenth_of_their_range(
        side, runs_range, refused):
    # the bound 21 (-21 below) is the runs' extreme 12 (-12) with two digits swapped, 9 beyond it: a slip when the
    # runs span 20 (margin 2), a bound rounded outwards when they span 100 (margin 10)
    from demid.data import check_bound_slips
    from demid.spec import Factor

    sign = 1.0 if side == "upper" else -1.0
    extreme = 12.0 * sign
    runs = np.array([extreme, extreme - sign * runs_range])
    bound, other = 21.0 * sign, float(runs.min() if side == "upper" else runs.max()) - sign * 1000
    lower, upper = (other, bound) if side == "upper" else (bound, other)
    factor = Factor(name="x", lower=lower, upper=upper, log=False, label="x", unit="")
    table = pd.DataFrame({"x": runs})
    if refused:
        with pytest.raises(InputError, match=f"{side}: {bound:g} lies beyond the runs.*looks like {extreme:g}"):
            check_bound_slips(table, "m", (factor,), "runs.csv")
    else:
        check_bound_slips(table, "m", (factor,), "runs.csv")


def test_published_scenario_sets_without_a_search_domain_compare_their_fraction_and_bounds():
    # a paper that gives a scenario's set (fraction, one bound) but no search ranges: nothing is unresolved,
    # so no range is needed, and each number is compared with the reproduced table's own
    from demid.paper import paper_comparison

    fit = pd.DataFrame({"material": ["m"], "response": ["y"], "r2": [0.95], "rmse": [2.0]})
    ident = pd.DataFrame({"material": ["m"] * 2, "scenario": ["a"] * 2, "observables": ["y"] * 2,
                          "tolerance": [0.02] * 2, "feasible_fraction_pct": [12.5] * 2, "factor": ["x", "z"],
                          "lower": [0.1, 3.0], "upper": [0.9, 7.0], "width": [0.8, 4.0]})
    published = {"scenario_sets": {"m": {"a": {"feasible_fraction_pct": 12.49, "upper": {"z": 7.02}}}}}
    table = paper_comparison(published, fit, ident, {}).set_index("quantity")
    assert list(table.index) == ["feasible fraction [%] a", "upper bound z (≲), a"]
    assert table["reproduced"].tolist() == [12.5, 7.0]
    assert table["published"].tolist() == [12.49, 7.02]


@_FAST
@given(centre=st.floats(-1e3, 1e3).filter(lambda c: abs(c) > 1e-3), unit=st.floats(0.01, 50.0),
       alpha=st.sampled_from([None, 1.414, 2.0]), with_centre=st.booleans(), with_axial=st.booleans())
def test_level_coding_recovers_the_centre_and_unit_of_a_design_with_or_without_its_centre_run(
        centre, unit, alpha, with_centre, with_axial):
    from demid.design_check import _level_coding

    levels = np.array([-1.0, 0.0, 1.0] if alpha is None else [-alpha, -1.0, 0.0, 1.0, alpha])
    used = [-1.0, 1.0] + ([0.0] if with_centre else []) + ([-alpha, alpha] if alpha and with_axial else [])
    values = np.array(sorted(centre + unit * np.array(used)))
    found = _level_coding(values, np.ones(len(values), dtype=int), levels)
    assert found == (pytest.approx(centre, rel=1e-9, abs=1e-9 * unit), pytest.approx(unit, rel=1e-9))


def _spread_reference(order, grid, starts):
    taken = []
    for node in order:
        if len(taken) == starts:
            break
        if all(np.max(np.abs(grid[node] - grid[t])) > 0.1 for t in taken):
            taken.append(node)
    return taken


@_FAST
@given(seed=st.integers(0, 10_000), n=st.integers(1, 40), k=st.integers(1, 4), starts=st.integers(1, 6))
def test_spread_starts_takes_the_best_ranked_node_first_then_the_next_far_enough_ones(seed, n, k, starts):
    from demid.criticism.searches import spread_starts

    rng = np.random.default_rng(seed)
    grid = rng.random((n, k))
    order = rng.permutation(n)
    picks = spread_starts(order, grid, starts)
    assert [int(p) for p in picks] == [int(p) for p in _spread_reference(order, grid, starts)]
    assert picks[0] == order[0]


@_FAST
@given(mantissa=st.floats(1.0, 9.99), exponent=st.integers(-7, 8), sign=st.sampled_from([-1.0, 1.0]))
def test_rough_text_is_one_significant_digit_in_fixed_form_between_1e_4_and_1e6(mantissa, exponent, sign):
    from demid.precision import rough_text

    value = sign * mantissa * 10.0 ** exponent
    text = rough_text(value)
    one_digit = float(f"{value:.0e}")
    assert float(text.replace("−", "-")) == pytest.approx(one_digit, rel=1e-12)
    assert ("e" in text) == (not 1e-4 <= abs(value) < 1e6), (value, text)


@pytest.mark.parametrize("value, expected", [(6e5, "600000"), (-9.4e5, "−900000"), (2e6, "2e+06"), (1.23e-4, "0.0001"),
                                             (9e-5, "9e-05"), (12.34, "10")])
def test_rough_text_known_answers_at_the_fixed_forms_ends(value, expected):
    from demid.precision import rough_text

    assert rough_text(value) == expected

"""The typo screen's building blocks against computations written apart here, over generated printed cells of
either sign, zero to four decimals, leading digits and exponent forms: every single-cell repair (each value a slip
of the named kind can turn into the printed text, once, under the first kind of the documented order; no leading
zero, no value equal to the printed one), the stray-digit repairs, printed decimals, the two-sided t tail against
scipy, the studentised residuals against statsmodels' definitions, and the level-dependent scale against Harvey's
model fitted with numpy."""

from __future__ import annotations

import math
from decimal import Decimal

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import stats

from demid.design import model_matrix, quadratic_terms
from demid.transcription.typos import (KINDS, _decimal_places, added_digit_repairs, cell_decimals, local_scale,
                                       single_cell_slips, studentised_residuals, two_sided_t_p)

DIGITS = "0123456789"
CELLS = st.builds(lambda sign, whole, decimals, frac: sign + str(whole) + (f".{frac:0{decimals}d}" if decimals else ""),
                  st.sampled_from(["", "-"]), st.sampled_from([0, 1, 7, 10, 11, 39, 106, 2024, 5500]),
                  st.integers(0, 3), st.integers(0, 999)).map(lambda t: t if "." not in t or len(t.split(".")[1]) < 4
                                                              else t[:t.index(".") + 4])


def _candidates(text: str) -> list[tuple[str, str]]:
    """(kind, text) of every slip's inverse, generated apart: the value the slip was applied to."""
    found = Decimal(text)
    plain = format(found, "f") if "e" in text.lower() else text
    sign, body = ("-", plain[1:]) if plain.startswith("-") else ("", plain)
    out = []
    digits = [i for i, ch in enumerate(body) if ch.isdigit()]
    out += [("digit_substitution", sign + body[:i] + d + body[i + 1:]) for i in digits for d in DIGITS]
    for i in digits:
        if i + 1 in digits:
            if body[i] == body[i + 1]:
                out.append(("digit_doubled", sign + body[:i] + body[i + 1:]))
            else:
                out.append(("transposition", sign + body[:i] + body[i + 1] + body[i] + body[i + 2:]))
    out += [("decimal_shift", format(found * Decimal(10) ** s, "f")) for s in (-2, -1, 1, 2)]
    out.append(("sign_lost", format(-found, "f")))
    out += [("digit_dropped", sign + body[:i] + d + body[i:]) for i in range(len(body) + 1) for d in DIGITS]
    return out


def _expected_repairs(text: str) -> dict[float, str]:
    found = float(Decimal(text))
    best: dict[float, str] = {}
    for kind, candidate in _candidates(text):
        bare = candidate.lstrip("-")
        if bare[:1] == "0" and bare[1:2].isdigit():
            continue
        try:
            value = float(Decimal(candidate))
        except ArithmeticError:
            continue
        if value == found or not math.isfinite(value):
            continue
        if value not in best or KINDS.index(kind) < KINDS.index(best[value]):
            best[value] = kind
    return best


@given(cell=st.one_of(CELLS, st.sampled_from(["1.5e-3", "-2.25E2", "0.0", "100", "99.9", "3.1415", "−4.5"])))
@settings(max_examples=120, deadline=None, derandomize=True)
def test_every_single_cell_repair_once_under_the_first_kind(cell):
    got = single_cell_slips(cell)
    want = _expected_repairs(cell.replace("\u2212", "-"))
    assert {value: kind for kind, _, value in got} == want
    assert len(got) == len(want)
    for kind, candidate, value in got:
        assert float(Decimal(candidate)) == value and kind in KINDS


def test_cells_that_are_no_finite_number_have_no_repairs():
    assert single_cell_slips("abc") == [] and single_cell_slips("nan") == [] and single_cell_slips("inf") == []
    assert added_digit_repairs("abc") == []


@given(cell=CELLS)
@settings(max_examples=60, deadline=None, derandomize=True)
def test_a_stray_digit_repair_is_every_digit_removed_that_leaves_another_number(cell):
    found = float(Decimal(cell))
    want = []
    for i, ch in enumerate(cell):
        candidate = cell[:i] + cell[i + 1:]
        bare = candidate.lstrip("-")
        if not ch.isdigit() or not any(c.isdigit() for c in bare) or (bare[:1] == "0" and bare[1:2].isdigit()):
            continue
        if float(Decimal(candidate)) != found:
            want.append(("digit_added", candidate, float(Decimal(candidate))))
    assert added_digit_repairs(cell) == want


@pytest.mark.parametrize("text, decimals", [("1.50", 2), ("-0.125", 3), ("12", 0), ("1.5e-3", 4), ("2E+2", 0),
                                            ("−3.7", 1), ("x", 0), ("1200.0", 1)])
def test_printed_decimals_of_a_cell(text, decimals):
    assert cell_decimals(text) == decimals


def test_a_column_s_decimals_are_the_most_any_printed_cell_shows():
    assert _decimal_places(["1.5", "2.25", "", " ", "3"]) == 2
    assert _decimal_places(["", " "]) is None
    assert _decimal_places(["10", "1.000"]) == 3


@pytest.mark.parametrize("df", [1, 2, 3, 4, 5, 6, 7, 10, 11, 30, 31, 120])
def test_the_two_sided_t_tail_is_scipy_s(df):
    t = np.array([0.0, 0.1, -0.5, 1.0, 2.0, -3.5, 6.0, 25.0])
    np.testing.assert_allclose(two_sided_t_p(t, df), 2 * stats.t.sf(np.abs(t), df), rtol=1e-9, atol=1e-14)


@given(seed=st.integers(0, 10_000), k=st.integers(1, 3), extra=st.integers(2, 10))
@settings(max_examples=10, deadline=None, derandomize=True)
def test_studentised_residuals_follow_statsmodels_definitions(seed, k, extra):
    rng = np.random.default_rng(seed)
    terms = quadratic_terms(k)
    n = len(terms) + extra
    coded = rng.uniform(-1.5, 1.5, size=(n, k))
    y = rng.normal(size=n) * 2 + 10
    x = model_matrix(coded, terms)
    beta, *_ = np.linalg.lstsq(x, y, rcond=None)
    e = y - x @ beta
    h = np.diag(x @ np.linalg.inv(x.T @ x) @ x.T)
    s2_without = (e @ e - e ** 2 / (1 - h)) / (n - len(terms) - 1)
    got = studentised_residuals(coded, y, terms)
    np.testing.assert_allclose(got["residual"], e, rtol=1e-8, atol=1e-10)
    np.testing.assert_allclose(got["leverage"], h, rtol=1e-8)
    np.testing.assert_allclose(got["student_resid"], e / np.sqrt(s2_without * (1 - h)), rtol=1e-7)


@given(seed=st.integers(0, 10_000), n=st.integers(5, 60), slope=st.sampled_from([0.0, 0.3, -0.2]))
@settings(max_examples=10, deadline=None, derandomize=True)
def test_the_level_dependent_scale_is_harvey_s_model_normalised(seed, n, slope):
    rng = np.random.default_rng(seed)
    fitted = rng.uniform(0, 10, n)
    residual = rng.normal(size=n) * np.exp(slope * fitted / 2)
    leverage = rng.uniform(0.01, 0.5, n)
    raw = residual ** 2 / (1 - leverage)
    b, a = np.polyfit(fitted, np.log(raw), 1)
    variance = np.exp(a + b * fitted)
    variance *= np.mean(raw / variance)
    np.testing.assert_allclose(local_scale(fitted, residual, leverage), np.sqrt(variance / np.mean(raw)), rtol=1e-7)


def test_a_scale_with_too_few_positive_residuals_or_one_level_is_one():
    assert np.array_equal(local_scale(np.arange(5.0), np.array([0.0, 0.0, 1.0, 2.0, 0.0]), np.zeros(5)), np.ones(5))
    assert np.array_equal(local_scale(np.full(4, 2.0), np.array([1.0, -1.0, 2.0, 0.5]), np.zeros(4)), np.ones(4))

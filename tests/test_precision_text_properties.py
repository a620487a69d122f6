"""The numbers the report's sentences print (demid.precision's texts), over generated values of either sign and
magnitudes from 1e-6 to 1e7: each text read back as a number equals the value rounded to the place the rule gives,
computed apart here (two significant digits of an uncertainty; a value to the place its uncertainty supports, at
most four significant digits; a p-value to two; a percentage to three; a run's coordinate to a thousandth of its
factor's range), and shows that place's decimals."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.precision import coordinate_text, p_text, percent_text, pm_text, uncertainty_text, value_text

SETTINGS = settings(max_examples=150, deadline=None, derandomize=True)
magnitudes = st.builds(lambda m, e, s: s * m * 10.0 ** e, st.floats(1.0, 9.99), st.integers(-6, 7),
                       st.sampled_from([-1.0, 1.0]))


def _number(text: str) -> float:
    return float(text.replace("−", "-").replace(",", ""))


def _decimals(text: str) -> int:
    return len(text.partition(".")[2]) if "e" not in text else -1


def _sig_place(x: float, digits: int) -> float:
    """The place of x's last significant digit once rounded to ``digits`` (0.0998 to 2 digits: 0.10, place 0.01)."""
    rounded = float(f"{abs(x):.{digits}g}")
    return 10.0 ** (math.floor(math.log10(rounded)) - digits + 1)


@given(u=magnitudes)
@SETTINGS
def test_an_uncertainty_is_printed_to_two_significant_digits(u):
    text = uncertainty_text(u)
    assert _number(text) == pytest.approx(float(f"{u:.2g}"), rel=1e-9)
    if 1e-4 <= abs(u) < 1e4:
        assert _decimals(text) == max(0, -round(math.log10(_sig_place(u, 2))))


@given(v=magnitudes, u=magnitudes)
@SETTINGS
def test_a_value_is_printed_to_the_place_its_uncertainty_supports(v, u):
    u = abs(u)
    text = value_text(v, u)
    place = max(_sig_place(u, 2), _sig_place(v, 4))
    if abs(v) < place / 2:
        assert text == "≈ 0"
        assert pm_text(v, u) == f"0 ± {uncertainty_text(u)}"
        return
    assert abs(_number(text) - v) <= place / 2 * (1 + 1e-9) + 1e-12 * abs(v)
    if 1e-4 <= abs(v) < 1e6:
        assert _number(text) == pytest.approx(round(v / place) * place, rel=1e-9)
        assert _decimals(text) == max(0, -round(math.log10(place)))
    assert text.startswith("−") == (v < 0)
    assert pm_text(v, u) == f"{text} ± {uncertainty_text(u)}"


@given(v=magnitudes)
@SETTINGS
def test_a_value_without_an_uncertainty_keeps_four_significant_digits(v):
    for missing in (None, float("nan"), 0.0):
        assert _number(value_text(v, missing)) == pytest.approx(float(f"{v:.4g}"), rel=1e-12)


@given(p=st.floats(1e-9, 1.0))
@SETTINGS
def test_a_p_value_has_two_significant_digits_and_a_floor(p):
    text = p_text(p)
    if p < 1e-4:
        assert text == "< 0.0001"
    else:
        assert _number(text) == pytest.approx(float(f"{p:.2g}"), rel=1e-12)


@given(f=magnitudes)
@SETTINGS
def test_a_relative_difference_is_a_percentage_to_three_significant_digits(f):
    text = percent_text(f)
    if abs(f) > 10:
        assert text == "more than 10×"
    elif abs(f) < 1e-4:
        assert text == "< 0.01 %"
    else:
        assert text.endswith(" %") and "e" not in text  # a percentage in plain digits, never 1e+03
        assert _number(text[:-2]) == pytest.approx(float(f"{100 * f:.3g}"), rel=1e-9)
    assert percent_text(0.0) == "0 %"
    assert percent_text(1e-4) == "0.01 %"  # the trace's end itself is printed


@given(lower=magnitudes, width=st.floats(1e-3, 1e6), share=st.floats(0.0, 1.0))
@SETTINGS
def test_a_proposed_runs_coordinate_is_written_to_a_thousandth_of_its_range(lower, width, share):
    upper = lower + width
    value = lower + share * width
    text = coordinate_text(value, lower, upper)
    place = 10.0 ** math.floor(math.log10(1e-3 * (upper - lower)))  # the range as the caller gives it
    assert abs(_number(text) - value) <= place / 2 * (1 + 1e-9) + 1e-12 * abs(value)
    assert _decimals(text) == max(0, -round(math.log10(place))) or _number(text) == 0


@SETTINGS
@given(st.floats(-5.0, 1.0))
def test_a_q2_below_one_never_prints_as_one_and_is_its_value_rounded(q2):
    """Q² to two decimals, or as many more as keep a value below 1 from reading "1.00" (0.9966 is not a perfect
    prediction); the text read back is the value rounded to the decimals it shows."""
    from demid.precision import q2_text

    text = q2_text(q2)
    places = _decimals(text)
    assert places >= 2
    assert _number(text) == pytest.approx(round(q2, places), abs=10.0 ** -(places + 3))
    if q2 < 1:
        assert _number(text) < 1 or text.startswith(">")
    if places > 2:  # more decimals only where two would read as 1
        assert round(q2, 2) >= 1 and q2 < 1


@pytest.mark.parametrize("q2, text", [(0.9966, "0.997"), (0.994, "0.99"), (0.99949, "0.999"), (0.99951, "0.9995"), (1.0, "1.00"),
                                      (-0.304, "-0.30"), (0.42, "0.42"), (float("nan"), "undefined")])
def test_q2_texts_of_known_values(q2, text):
    from demid.precision import q2_text

    assert q2_text(q2) == text


@pytest.mark.parametrize("n, text", [(1, "1 wave"), (2, "2 waves"), (0, "0 waves"), (11, "11 waves")])
def test_a_count_takes_its_noun_in_the_number_it_needs(n, text):
    from demid.precision import counted

    assert counted(n, "wave") == text

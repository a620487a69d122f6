"""One table cell read as a number (csv_cells.parse_number, is_number), over generated values printed in plain,
exponent, signed and Unicode-minus forms: the value is Python's reading of the text; spelled-out nan and inf keep
their meaning (a failed run); a number outside the magnitudes demid computes with, or one too small for a float,
is refused with the cell quoted."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.csv_cells import is_number, parse_number

SETTINGS = settings(max_examples=60, deadline=None, derandomize=True)


@given(mantissa=st.floats(1.0, 9.999), exponent=st.integers(-29, 29), negative=st.booleans(),
       form=st.sampled_from(["{:.6g}", "{:.4e}", "{:.3E}", " {:.5g} "]), unicode_minus=st.booleans())
@SETTINGS
def test_a_printed_number_reads_as_pythons_float_of_its_text(mantissa, exponent, negative, form, unicode_minus):
    text = form.format((-1 if negative else 1) * mantissa * 10.0 ** exponent)
    expected = float(text)
    if unicode_minus:
        text = text.replace("-", "\u2212")
    assert parse_number(text) == expected
    assert is_number(text)


@given(word=st.sampled_from(["nan", "NaN", "inf", "Infinity", "-inf", "+INF", "-Infinity"]))
@SETTINGS
def test_spelled_out_nan_and_inf_keep_their_meaning(word):
    value = parse_number(word)
    assert math.isnan(value) if "nan" in word.lower() else value == float(word)
    assert is_number(word)


@given(exponent=st.integers(31, 300), negative=st.booleans())
@SETTINGS
def test_a_number_beyond_the_magnitudes_demid_computes_with_is_refused(exponent, negative):
    text = f"{'-' if negative else ''}2.5e{exponent}"
    with pytest.raises(ValueError, match=rf"found '{text}', outside the magnitudes demid computes with"):
        parse_number(text)
    assert not is_number(text)
    tiny = f"{'-' if negative else ''}3e-{exponent + 330}"  # below the smallest float: reads as 0
    with pytest.raises(ValueError, match=rf"found '{tiny}', too small for a float"):
        parse_number(tiny)
    overflow = f"1e{exponent + 400}"
    with pytest.raises(ValueError, match="too large for a float"):
        parse_number(overflow)


@given(text=st.sampled_from(["", "   ", "abc", "1.2.3", "1,5", "1_000", "--2", "12a", "0x10"]))
@SETTINGS
def test_text_that_is_no_number_is_not_one(text):
    assert not is_number(text)
    with pytest.raises(ValueError):
        parse_number(text)

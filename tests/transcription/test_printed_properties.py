"""How many decimals a printed cell needs, and whether a repair of it fits its column's print (-1: it brings a cell
printed with more decimals than its column back in line, +1: it needs more decimals than the column shows, 0:
neither), over generated values printed to 0-6 decimals, plain or with an exponent."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from demid.transcription.printed import _irregularity, _precision

SETTINGS = settings(max_examples=80, deadline=None, derandomize=True)


def _printed(digits: int, places: int, trailing_zeros: int) -> str:
    """A number whose last non-zero digit is at ``places`` decimals, printed with ``trailing_zeros`` more zeros."""
    whole, frac = divmod(digits, 10 ** places) if places else (digits, 0)
    text = f"{whole}" if not places else f"{whole}.{frac:0{places}d}"
    if not places and trailing_zeros:
        text += "."
    return text + "0" * trailing_zeros


@given(digits=st.integers(1, 10 ** 7).filter(lambda n: n % 10), places=st.integers(0, 6),
       trailing_zeros=st.integers(0, 3))
@SETTINGS
def test_a_cells_precision_is_its_last_non_zero_decimal(digits, places, trailing_zeros):
    text = _printed(digits, places, trailing_zeros)
    assert _precision(text) == places


@given(found=st.integers(0, 6), suggested=st.integers(0, 6), column=st.integers(0, 6))
@SETTINGS
def test_a_repairs_irregularity_compares_both_prints_with_the_columns(found, suggested, column):
    found_text, suggested_text = _printed(1234567, found, 0), _printed(7654321, suggested, 0)
    expected = 1 if suggested > column else -1 if found > column else 0
    assert _irregularity(found_text, suggested_text, column) == expected

"""A published statistic given as a float (as YAML reads 2.5e16 or 5e-05) by demid.transcription.printed.parse_printed,
over floats of either sign from 1e-12 to 1e22: the text is the float's shortest digits written out without an
exponent and without a trailing point (Decimal's fixed-point form of its repr), the value is the float, and the
decimals are those the text shows."""

from __future__ import annotations

from decimal import Decimal

from hypothesis import given, settings
from hypothesis import strategies as st

from demid.transcription.printed import parse_printed


def _positional(value: float) -> str:
    return format(Decimal(repr(value)), "f")


@given(mantissa=st.integers(1, 99_999), exponent=st.integers(-16, 22), sign=st.sampled_from([-1, 1]))
@settings(max_examples=60, deadline=None, derandomize=True)
def test_a_float_is_read_as_its_shortest_digits_written_out(mantissa, exponent, sign):
    value = float(f"{sign * mantissa}e{exponent}")
    printed = parse_printed(value)
    text = _positional(value)
    assert printed.text == text
    assert not printed.text.endswith(".")
    assert printed.value == value
    assert printed.decimals == (len(text.split(".")[1]) if "." in text else 0)
    assert printed.relation == "="


def test_large_and_small_floats_as_yaml_gives_them():
    assert parse_printed(2.5e16).text == "25000000000000000"
    assert parse_printed(1e22).text == "10000000000000000000000"
    assert parse_printed(5e-05).text == "0.00005"
    assert parse_printed(-1.25e-07).text == "-0.000000125"
    assert (parse_printed(2.5e16).decimals, parse_printed(5e-05).decimals) == (0, 5)

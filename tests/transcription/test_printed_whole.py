"""A published number as the transcription check reads it, against rules written out here: its value, decimals
and relation from every printed form (trailing zeros, bounds, percentages, a typeset minus, YAML floats and ints,
a {value, decimals} entry, the decimals given apart), agreement and misfit on and just past the half-width of the
last printed digit for each relation, and a column's printed forms (positional text, the column's decimals, the
decimals a number needs, the precision of the other cells, the irregularity of a repair), over generated values
of either sign and zero to five decimals."""

from __future__ import annotations

from decimal import Decimal

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.errors import InputError
from demid.transcription.printed import (_MISFIT_CAP, PrintedValue, _irregularity, _jsonable, _precision,
                                         _precision_elsewhere, _printed_column, parse_printed, positional)

SETTINGS = settings(max_examples=60, deadline=None, derandomize=True)
PRINTED = st.builds(lambda sign, whole, decimals, frac: f"{sign}{whole}" + (f".{frac % 10 ** decimals:0{decimals}d}"
                                                                            if decimals else ""),
                    st.sampled_from(["", "-", "−"]), st.integers(0, 5000), st.integers(0, 5), st.integers(0, 99999))


@given(text=PRINTED, prefix=st.sampled_from(["", "<", ">", "<=", ">=", "≤", "≥"]), percent=st.booleans())
@SETTINGS
def test_a_printed_string_gives_its_value_decimals_and_relation(text, prefix, percent):
    raw = f" {prefix}{text}{'%' if percent else ''} "
    got = parse_printed(raw)
    body = text.replace("−", "-")
    decimals = len(body.partition(".")[2])
    value = Decimal(body) / (100 if percent else 1)
    assert got.value == float(value)
    assert got.decimals == decimals + (2 if percent else 0)
    assert got.relation == {"": "=", "<": "<", "<=": "<", "≤": "<", ">": ">", ">=": ">", "≥": ">"}[prefix]
    assert got.text == raw.strip()
    assert got.half_width == 0.5 * 10.0 ** -got.decimals
    assert parse_printed(raw, 7).decimals == 7
    assert parse_printed({"value": raw, "decimals": 1}).decimals == 1


@pytest.mark.parametrize("value, number, decimals", [(0.97, 0.97, 2), (12, 12.0, 0), (np.int64(-3), -3.0, 0),
                                                     (1e-05, 1e-05, 5), (np.float64(2.5e-7), 2.5e-7, 8),
                                                     (-123.25, -123.25, 2), (1.5e20, 1.5e20, 0)])
def test_a_yaml_number_gives_the_decimals_of_its_shortest_form(value, number, decimals):
    got = parse_printed(value)
    assert (got.value, got.decimals, got.relation) == (number, decimals, "=")


@pytest.mark.parametrize("value", [True, None, float("nan"), float("inf"), "abc", "nan", [1], {"decimals": 2}])
def test_what_is_not_a_number_is_refused(value):
    with pytest.raises(InputError):
        parse_printed(value)


def test_decimals_that_are_not_an_integer_are_refused():
    for decimals in (1.5, True, "2"):
        with pytest.raises(InputError, match="decimals must be an integer"):
            parse_printed("1.25", decimals)


@given(value=st.integers(-5000, 5000), decimals=st.integers(0, 4), relation=st.sampled_from(["=", "<", ">"]),
       scale=st.sampled_from([-3.0, -1.0000021, -1.0000005, -0.5, 0.0, 0.5, 1.0000005, 1.0000021, 3.0]))
@SETTINGS
def test_agreement_and_misfit_on_and_just_past_the_half_width(value, decimals, relation, scale):
    v = value / 10 ** decimals
    printed = PrintedValue(text="t", value=v, decimals=decimals, relation=relation)
    half = 0.5 * 10.0 ** -decimals
    x = v + scale * half
    gap = {"=": abs(x - v), "<": max(x - v, 0.0), ">": max(v - x, 0.0)}[relation]
    # the slack is a millionth of the half-width: 1.0000005 half-widths agree, 1.0000021 do not
    inside = {"=": abs(scale) <= 1.000001, "<": scale <= 0.000001, ">": scale >= -0.000001}[relation]
    assert bool(printed.agrees(x)) is inside
    assert float(printed.misfit(x)) == pytest.approx(gap / half, rel=1e-9, abs=1e-9)
    assert not printed.agrees(np.nan) and float(printed.misfit(np.nan)) == _MISFIT_CAP
    assert float(printed.misfit(v + 1e9 * half * (1 if relation != ">" else -1))) == _MISFIT_CAP
    np.testing.assert_array_equal(printed.agrees([x, np.inf, np.nan]), [inside, False, False])


@given(values=st.lists(st.one_of(st.floats(-1e4, 1e4, allow_nan=False).map(lambda v: round(v, 3)),
                                 st.just(float("nan")), st.sampled_from([1e-5, -2.5e-6, 0.1, 3.0])),
                       min_size=1, max_size=8))
@SETTINGS
def test_a_column_s_printed_forms_share_its_largest_decimals(values):
    texts = _printed_column(np.array(values))
    finite = [v for v in values if np.isfinite(v)]
    places = max((len(repr(float(v)).partition(".")[2]) if "e" not in repr(float(v))
                  else len(np.format_float_positional(v, trim="-").partition(".")[2]) for v in finite), default=0)
    assert texts == [f"{v:.{places}f}" if np.isfinite(v) else None for v in values]
    for v in finite:
        assert float(positional(v)) == v and "e" not in positional(v)


@pytest.mark.parametrize("text, precision", [("0.2000", 1), ("0.0757", 4), ("12", 0), ("12.0", 0), ("1.5e-3", 4),
                                             ("-3.140", 2), ("2E+2", 0)])
def test_the_decimals_a_number_needs(text, precision):
    assert _precision(text) == precision


@given(texts=st.lists(st.one_of(st.none(), PRINTED.map(lambda t: t.replace("−", "-"))), min_size=1, max_size=8))
@SETTINGS
def test_each_cell_s_precision_elsewhere_is_the_largest_of_the_other_cells(texts):
    got = _precision_elsewhere(texts)
    need = [_precision(t) if t is not None else -1 for t in texts]
    if len(texts) < 2:
        want = [max(need[0], 0)]
    else:
        want = [max(max(need[:i] + need[i + 1:]), 0) for i in range(len(texts))]
    np.testing.assert_array_equal(got, want)


@pytest.mark.parametrize("found, suggested, column, irregularity", [
    ("1.25", "1.2", 2, 0), ("1.25", "1.253", 2, 1), ("1.253", "1.25", 2, -1), ("1.253", "1.2531", 2, 1),
    ("1.2", "1.25", 2, 0), ("10", "100", 0, 0)])
def test_a_repair_s_irregularity(found, suggested, column, irregularity):
    assert _irregularity(found, suggested, column) == irregularity


def test_json_values():
    assert _jsonable(np.int64(3)) == 3 and type(_jsonable(np.int64(3))) is int
    assert _jsonable(np.float64(2.5)) == 2.5 and type(_jsonable(np.float64(2.5))) is float
    assert _jsonable(float("nan")) is None and _jsonable(np.inf) is None and _jsonable("r7") == "r7"

"""JSON values of a nested result (demid.io.json_ready) at every depth, against the cleaning written out here, for
each float format a caller passes: None keeps every float to the last bit (the criticism's document), "%.10g" is
the written files' ten digits, "%.3g" a caller's own; floats inside numpy arrays (of any shape), tuples, lists and
dicts in any nesting follow the same format as a float at the top, NaN and infinities are null, numpy integers and
booleans plain ones, keys text; over generated values of every magnitude and sign."""

from __future__ import annotations

import math

import numpy as np
import pytest

from demid.io import json_ready


def _float(value: float, float_format):
    if not math.isfinite(value):
        return None
    return value if float_format is None else float(float_format % value)


def _values(rng, n):
    out = rng.normal(size=n) * 10.0 ** rng.integers(-12, 13, size=n)
    out[rng.random(n) < 0.2] = rng.choice([np.nan, np.inf, -np.inf])
    return out


@pytest.mark.parametrize("float_format", [None, "%.10g", "%.3g"])
@pytest.mark.parametrize("seed", range(3))
def test_every_float_at_every_depth_follows_the_one_format_given(seed, float_format):
    rng = np.random.default_rng(seed)
    flat, grid, scalars = _values(rng, 5), _values(rng, 6).reshape(2, 3), _values(rng, 3)
    ints = rng.integers(-10 ** 9, 10 ** 9, size=3)
    obj = {"flat": flat, 7: (np.float64(scalars[0]), [grid, {"deep": np.array([scalars[1]])}]),
           "scalar": float(scalars[2]), "ints": [np.int64(i) for i in ints], "flag": np.bool_(seed % 2 == 0),
           "text": "Φ", "none": None}

    def f(v):
        return _float(float(v), float_format)

    expected = {"flat": [f(v) for v in flat], "7": [f(scalars[0]), [[[f(v) for v in row] for row in grid],
                                                                     {"deep": [f(scalars[1])]}]],
                "scalar": f(scalars[2]), "ints": [int(i) for i in ints], "flag": seed % 2 == 0, "text": "Φ",
                "none": None}
    got = json_ready(obj, float_format)
    assert got == expected
    # the same types as JSON reads them back: plain floats, ints and bools, never numpy's
    assert type(got["ints"][0]) is int and type(got["flag"]) is bool
    assert all(v is None or type(v) is float for v in got["flat"])

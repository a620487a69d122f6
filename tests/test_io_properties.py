"""What demid's writers put in the files a user reads, over generated values, against the formats written out
here: JSON (keys as text and sorted, floats to 10 significant digits, NaN and infinities as null, numpy integers
and booleans as JSON integers and booleans, arrays and tuples as lists, text unescaped), CSV (every float cell
at 6 significant digits, integers and text as given, missing cells empty, '\\n' line ends), Parquet (a round
trip that keeps every value, its dtype and nothing of the index) and the content digest (sha256 of the bytes)."""

from __future__ import annotations

import hashlib
import json
import math

import numpy as np
import pandas as pd
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from demid.io import (as_stored, content_digest, read_parquet, round_significant, to_json_text, write_csv, write_json,
                     write_parquet)

# each example overwrites the same files in tmp_path, so sharing the fixture across examples is harmless
SETTINGS = settings(max_examples=10, deadline=None, derandomize=True,
                    suppress_health_check=[HealthCheck.function_scoped_fixture])

_FLOATS = st.one_of(st.floats(allow_nan=True, allow_infinity=True, width=64),
                    st.sampled_from([0.1 + 0.2, -1234567.891234567, 1e-300, -2.5e17, 1 / 3]))


def _expected_float(value: float):
    return float(f"{value:.10g}") if math.isfinite(value) else None


@given(values=st.lists(_FLOATS, min_size=1, max_size=6), ints=st.lists(st.integers(-10**12, 10**12), max_size=4),
       flag=st.booleans())
@SETTINGS
def test_json_text_has_sorted_text_keys_ten_digit_floats_nulls_and_plain_ints(values, ints, flag, tmp_path):
    obj = {"b_floats": [np.float64(v) for v in values], 3: tuple(np.int64(i) for i in ints),
           "a_array": np.array(values, dtype=float).reshape(1, -1), "flag": np.bool_(flag), "µ": "ø text",
           "nested": {"z": np.float32(0.5), "y": values[0]}}
    text = to_json_text(obj)
    expected_floats = [_expected_float(float(v)) for v in values]
    expected = {"3": list(ints), "a_array": [expected_floats], "b_floats": expected_floats, "flag": flag,
                "nested": {"y": expected_floats[0], "z": 0.5}, "µ": "ø text"}
    assert text == json.dumps(expected, sort_keys=True, indent=2, ensure_ascii=False) + "\n"
    write_json(obj, tmp_path / "out.json")
    assert (tmp_path / "out.json").read_text(encoding="utf-8") == text
    assert content_digest(tmp_path / "out.json") == hashlib.sha256(text.encode("utf-8")).hexdigest()
    assert content_digest(tmp_path / "missing.json") == ""


@given(values=st.lists(st.one_of(st.just(math.nan), st.floats(min_value=-1e12, max_value=1e12)),
                       min_size=1, max_size=8), seed=st.integers(0, 1000))
@SETTINGS
def test_csv_cells_are_six_significant_digits_and_parquet_keeps_every_value(values, seed, tmp_path):
    n = len(values)
    rng = np.random.default_rng(seed)
    counts = rng.integers(-5, 10**9, size=n)
    frame = pd.DataFrame({"x": values, "count": counts, "name": [f"r{i}" for i in range(n)],
                          "scale": rng.normal(size=n) * 10.0 ** rng.integers(-8, 9, size=n)},
                         index=rng.permutation(n) + 7)
    write_csv(frame, tmp_path / "t.csv")
    raw = (tmp_path / "t.csv").read_bytes()
    assert b"\r" not in raw
    lines = raw.decode("utf-8").split("\n")
    assert lines[0] == "x,count,name,scale" and lines[-1] == "" and len(lines) == n + 2

    def cell(v):
        return "" if math.isnan(v) else f"{float(f'{v:.6g}'):.6g}"

    expected = [f"{cell(x)},{c},{name},{cell(s)}" for x, c, name, s in
                zip(frame["x"], frame["count"], frame["name"], frame["scale"])]
    assert lines[1:-1] == expected

    # the rounded copy the CSV is written from: float columns stay floats, each value the 6-digit one
    rounded = round_significant(frame)
    for column in ("x", "scale"):
        assert rounded[column].dtype == np.float64
        np.testing.assert_array_equal(rounded[column].to_numpy(), [float(f"{v:.6g}") for v in frame[column]])
    pd.testing.assert_frame_equal(rounded[["count", "name"]], frame[["count", "name"]])

    write_parquet(frame, tmp_path / "t.parquet")
    back = read_parquet(tmp_path / "t.parquet")
    pd.testing.assert_frame_equal(back, frame.reset_index(drop=True), check_exact=True)
    assert isinstance(back.index, pd.RangeIndex)
    pd.testing.assert_frame_equal(as_stored(frame), back, check_exact=True)

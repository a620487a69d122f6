"""The transcription check's sentences and records (demid.transcription.check), each against the documented wording
and numbers written out here, over generated counts: the explained verdict (one repair and one published
statistic: a lead among the repairs tried; one repair: the slip; several: leads), the unexplained one (every
disagreeing statistic with its reproduced value, the statistics a table cannot compute, the partial repairs), the
printed-statistic slip (only when exactly one of two or more statistics disagrees, printed as a plain number), the
JSON record and the CSV rows (printed texts beyond six significant digits rounded, their decimals kept)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import Phase, given, settings
from hypothesis import strategies as st

from demid.transcription.check import (Suspect, TranscriptionResult, _explained_message, _printed_cells,
                                       _printed_slip, _printed_slip_message, _unexplained_message)
from demid.transcription.printed import parse_printed

SETTINGS = settings(max_examples=20, deadline=None, derandomize=True, phases=[Phase.explicit, Phase.generate])
SUSPECT = Suspect(run=7, column="y", found=21.0, suggested=12.0, kind="transposition", restores=3,
                  found_text="21.0", suggested_text="12.0")


@given(n_pub=st.integers(1, 6), data=st.data(), n_full=st.integers(1, 5), n_candidates=st.integers(10, 900))
@SETTINGS
def test_the_explained_verdict_quotes_its_counts(n_pub, data, n_full, n_candidates):
    n_agree = data.draw(st.integers(0, n_pub - 1))
    got = _explained_message("y", SUSPECT, n_pub, n_agree, n_full, n_candidates)
    head = f"the table does not reproduce {n_pub - n_agree} of {n_pub} published statistics of 'y'"
    cell = f"run 7, column 'y' reads 21.0 where 12.0 restores all {n_pub} (transposition)"
    if n_full == 1 and n_pub == 1:
        want = (f"{head}; one single-cell repair restores it: {cell}; with a single published statistic a chance "
                f"match among the {n_candidates} repairs tried cannot be ruled out, so check that cell against the "
                "source (a second published statistic would confirm or clear it)")
    elif n_full == 1:
        want = f"{head}; a single-cell slip explains it: {cell}"
    else:
        want = (f"{head}; a single-cell slip could explain it, but {n_full} different single-cell repairs restore "
                "all of them, so the published statistics do not locate the slip; the closest to the printed values: "
                f"{cell} (all listed as leads; check them against the source)")
    assert got == want


@given(values=st.lists(st.tuples(st.sampled_from(["r2", "adj_r2", "rmse", "lof_p"]),
                                 st.sampled_from([0.91234567, -3.5, float("nan"), 1234567.0]), st.booleans()),
                       min_size=1, max_size=4, unique_by=lambda v: v[0]),
       n_partial=st.integers(0, 3), best=st.integers(0, 3))
@SETTINGS
def test_the_unexplained_verdict_lists_every_disagreement_and_what_cannot_be_computed(values, n_partial, best):
    targets = {name: parse_printed("0.95") for name, _, _ in values}
    reproduced = {name: value for name, value, _ in values}
    agrees = {name: ok for name, _, ok in values}
    got = _unexplained_message("y", targets, reproduced, agrees, n_partial, best)
    off = "; ".join(f"{name} {'NaN' if not np.isfinite(value) else format(value, '.6g')} vs printed 0.95"
                    for name, value, ok in values if not ok)
    want = (f"'y' disagrees with the source ({off}). No single-cell slip explains the disagreement: the table or the "
            "model differs from the source's in a bigger way (a different model, a dropped run, more than one typo), "
            "or the printed value is itself wrong")
    missing = [name for name, value, _ in values if not np.isfinite(value)]
    if missing:
        want += f"; {', '.join(missing)} cannot be computed from this table (e.g. no replicated runs for lack of fit)"
    if n_partial:
        want += f"; the closest single-cell repairs restore only {best} of {len(values)} statistics and are listed as leads"
    assert got == want


@pytest.mark.parametrize("printed, reproduced, others, expected", [
    ("0.899", 0.989, {"rmse": True}, ("0.989", "transposition")),
    ("0.899", 0.989, {}, None),                                   # one statistic alone: no other to trust
    ("0.899", 0.989, {"rmse": True, "adj_r2": False}, None),      # two disagree
    ("<0.899", 0.989, {"rmse": True}, None),                      # a bound
    ("89.9%", 0.989, {"rmse": True}, None),                       # a percentage
    ("-0.95", 0.95, {"rmse": True, "q2": True}, ("0.95", "sign_lost")),
    ("9.5", 0.95, {"rmse": True}, ("0.95", "decimal_shift")),
    ("11", 1.1, {"rmse": True}, ("1.1", "decimal_shift")),        # the commoner slip before a doubled digit's 1
    ("0.95", 0.95 + 0.3, {"rmse": True}, None),                   # no slip lands on it
])
def test_a_printed_statistic_slip_only_where_exactly_one_of_several_disagrees(printed, reproduced, others, expected):
    targets = {"r2": parse_printed(printed), **{name: parse_printed("1.5") for name in others}}
    values = {"r2": reproduced, **{name: 1.5 for name in others}}
    agrees = {"r2": False, **others}
    slip = _printed_slip(targets, values, agrees)
    if expected is None:
        assert slip is None
    else:
        assert slip == {"statistic": "r2", "printed": printed, "looks_like": expected[0], "kind": expected[1]}
        n_agree = sum(agrees.values())
        words = {"transposition": "two adjacent digits swapped", "sign_lost": "its sign lost",
                 "decimal_shift": "the decimal point shifted"}
        assert _printed_slip_message("y", slip, len(targets), n_agree) == (
            f"the table reproduces {n_agree} of {len(targets)} published statistics of 'y'; the printed r2, "
            f"{printed}, looks like {expected[0]} with {words[expected[1]]}: the slip is in the printed or "
            "transcribed statistic, not in the table — check the source's value")


@pytest.mark.parametrize("text, shown, decimals", [
    ("", "", math.nan), ("0.970", "0.970", 3), ("7579.048", "7579.05", 3), ("<0.0001", "<0.0001", 4),
    ("-12345.6789", "-12345.7", 4), ("98.27%", "98.27%", 4), ("123456", "123456", 0), ("1234567", "1234570", 0)])
def test_a_printed_cell_keeps_six_significant_digits_and_its_decimals(text, shown, decimals):
    got_text, got_decimals = _printed_cells(text)
    assert got_text == shown
    assert (math.isnan(got_decimals) and math.isnan(decimals)) or got_decimals == decimals


def test_the_record_and_rows_of_a_result():
    result = TranscriptionResult(response="y", consistent=False, published={"r2": 0.95, "rmse": 2.0},
                                 reproduced={"r2": 0.9, "rmse": np.float64(2.0)}, agrees={"r2": np.bool_(False),
                                                                                          "rmse": True},
                                 suspects=[SUSPECT], explained=True, message="m",
                                 printed={"r2": "0.950", "rmse": "2.0000001"}, n_candidates=40)
    assert result.n_published == 2
    record = result.to_json()
    assert record == {"consistent": False, "published": {"r2": 0.95, "rmse": 2.0},
                      "reproduced": {"r2": 0.9, "rmse": 2.0}, "response": "y",
                      "suspects": [{"run": 7, "column": "y", "found": 21.0, "suggested": 12.0, "kind": "transposition",
                                    "restores": 3}],
                      "agrees": {"r2": False, "rmse": True}, "printed": {"r2": "0.950", "rmse": "2.0000001"},
                      "n_published": 2, "explained": True, "printed_slip": None, "message": "m"}
    rows = result.to_frame()
    assert rows.values.tolist() == [["y", "r2", 0.95, 0.9, False, "0.950", 3.0], ["y", "rmse", 2.0, 2.0, True, "2", 7.0]]

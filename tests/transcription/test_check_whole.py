"""The transcription check's whole verdict against a fit written out with numpy, over generated CCD tables of two
or three factors with responses of either sign: statistics printed from the table's own least-squares fit at
three or four decimals are reproduced (each number equal to numpy's), agree and make the table consistent; with
one response cell's digits transposed the check disagrees on as many statistics as the slipped table's own fit
misses by more than half a printed unit, names the run, the column, both texts and the kind, and quotes those
counts in its message; every row of its frame is the published, reproduced and printed value."""

from __future__ import annotations

import re

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.design import Coding, ccd_points, model_matrix, quadratic_terms
from demid.transcription.check import TRANSCRIPTION_FRAME_COLUMNS, check_transcription


def _statistics(x_coded, y):
    """R², adjusted R², RMSE and the coded intercept of the full quadratic, written out."""
    terms = quadratic_terms(x_coded.shape[1])
    m = model_matrix(x_coded, terms)
    beta, *_ = np.linalg.lstsq(m, y, rcond=None)
    sse = float(np.sum((y - m @ beta) ** 2))
    sst = float(np.sum((y - y.mean()) ** 2))
    n, p = m.shape
    return {"r2": 1 - sse / sst, "adj_r2": 1 - (sse / (n - p)) / (sst / (n - 1)), "rmse": np.sqrt(sse / n),
            "b0": float(beta[0])}


def _table(seed, k, sign):
    rng = np.random.default_rng(seed)
    alpha = 1.5
    coded = ccd_points(k, alpha, 3)
    centre, half = rng.uniform(1, 5, k), rng.uniform(0.5, 2, k)
    actual = np.round(centre + coded * half, 4)
    y = sign * (50 + coded @ rng.normal(size=k) * 5 + 2 * (coded ** 2).sum(axis=1) + rng.normal(size=len(coded)))
    y = np.round(y, 2)
    names = [f"x{i + 1}" for i in range(k)]
    table = pd.DataFrame({"run": np.arange(1, len(coded) + 1), **{f: actual[:, i] for i, f in enumerate(names)},
                          "y": y})
    coding = Coding.from_levels(names, actual, alpha)
    return table, names, coding, alpha


def _printed(stats, decimals):
    return {"r2": f"{stats['r2']:.{decimals}f}", "adj_r2": f"{stats['adj_r2']:.{decimals}f}",
            "rmse": f"{stats['rmse']:.{decimals}f}",
            "coefficients": {"units": "coded", "values": {"Intercept": f"{stats['b0']:.{decimals}f}"}}}


def _transposed(text):
    """The first adjacent pair of different digits swapped (a transposition slip) that reads as a printed number."""
    digits = [i for i, ch in enumerate(text) if ch.isdigit()]
    for i in digits:
        if i + 1 in digits and text[i] != text[i + 1]:
            swapped = text[:i] + text[i + 1] + text[i] + text[i + 2:]
            bare = swapped.lstrip("-")
            if not (bare[0] == "0" and bare[1:2].isdigit()):  # no table prints 07.16
                return swapped
    return None


@given(seed=st.integers(0, 10_000), k=st.integers(2, 3), sign=st.sampled_from([-1.0, 1.0]),
       decimals=st.integers(3, 4), data=st.data())
@settings(max_examples=6, deadline=None, derandomize=True)
def test_the_verdict_before_and_after_a_transposed_cell(seed, k, sign, decimals, data):
    table, names, coding, alpha = _table(seed, k, sign)
    coded = coding.to_coded(table[names].to_numpy())
    stats = _statistics(coded, table["y"].to_numpy())
    published = _printed(stats, decimals)
    half = 0.5 * 10.0 ** -decimals

    clean = check_transcription(table, names, "y", published, alpha=alpha)
    assert clean.consistent and clean.explained is None and clean.suspects == []
    for name, key in (("r2", "r2"), ("adj_r2", "adj_r2"), ("rmse", "rmse"), ("coef_coded[Intercept]", "b0")):
        assert clean.reproduced[name] == pytest.approx(stats[key], rel=1e-9, abs=1e-12), name
        assert clean.agrees[name]
    frame = clean.to_frame()
    assert list(frame.columns) == TRANSCRIPTION_FRAME_COLUMNS and len(frame) == 4
    assert (frame["printed_decimals"] == decimals).all() and frame["agrees"].all()
    np.testing.assert_allclose(frame["published"], [float(published[s]) for s in ("r2", "adj_r2", "rmse")]
                               + [float(published["coefficients"]["values"]["Intercept"])])

    row = data.draw(st.integers(0, len(table) - 1))
    found_text = f"{table.loc[row, 'y']:.2f}"
    slipped_text = _transposed(found_text)
    if slipped_text is None or float(slipped_text) == float(found_text):
        return
    slipped = table.copy()
    slipped.loc[row, "y"] = float(slipped_text)
    off = _statistics(coded, slipped["y"].to_numpy())
    misses = sum(abs(off[key] - float(text)) > half * (1 + 1e-6) for key, text in
                 (("r2", published["r2"]), ("adj_r2", published["adj_r2"]), ("rmse", published["rmse"]),
                  ("b0", published["coefficients"]["values"]["Intercept"])))
    result = check_transcription(slipped, names, "y", published, alpha=alpha)
    assert sum(not v for v in result.agrees.values()) == misses
    if misses == 0:
        assert result.consistent
        return
    assert not result.consistent
    said = re.search(r"does not reproduce (\d+) of (\d+) published statistics", result.message)
    assert said and (int(said.group(1)), int(said.group(2))) == (misses, 4), result.message
    assert result.explained
    leads = [(s.run, s.column, s.found_text, s.suggested_text) for s in result.suspects]
    assert (row + 1, "y", slipped_text, found_text) in leads
    if len(leads) == 1:
        best = result.suspects[0]
        assert best.kind == "transposition" and best.restores == 4
        assert f"run {row + 1}, column 'y' reads {slipped_text} where {found_text} restores all 4" in result.message


@given(seed=st.integers(0, 10_000), k=st.integers(2, 3), sign=st.sampled_from([-1.0, 1.0]),
       statistic=st.sampled_from(["r2", "adj_r2", "rmse"]))
@settings(max_examples=6, deadline=None, derandomize=True)
def test_a_transposed_printed_statistic_is_named_as_the_slip_not_the_table(seed, k, sign, statistic):
    """Every statistic but one reproduced, and two digits of that one's print swapped: the check says the slip is
    in the printed statistic, quoting its print and the value it looks like, and counts the others."""
    table, names, coding, alpha = _table(seed, k, sign)
    stats = _statistics(coding.to_coded(table[names].to_numpy()), table["y"].to_numpy())
    published = _printed(stats, 3)
    right = published[statistic]
    wrong = _transposed(right)
    if wrong is None or float(wrong) == float(right) or abs(float(wrong) - stats[statistic]) <= 0.0005:
        return
    published[statistic] = wrong
    result = check_transcription(table, names, "y", published, alpha=alpha)
    assert not result.consistent and [n for n, ok in result.agrees.items() if not ok] == [statistic]
    slip = result.printed_slip
    assert slip is not None, result.message
    assert (slip["statistic"], slip["printed"]) == (statistic, wrong)
    assert abs(float(slip["looks_like"]) - stats[statistic]) <= 0.0005 * (1 + 1e-6)
    assert f"the table reproduces 3 of 4 published statistics of 'y'; the printed {statistic}, {wrong}, looks like " \
           f"{slip['looks_like']}" in result.message

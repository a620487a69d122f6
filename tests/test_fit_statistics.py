"""The fit's ANOVA table as it is stored and printed (demid.fit_statistics), over generated sums of squares and
degrees of freedom, with and without blocks, replicates and a round-off floor: every row's mean square, F-ratio
and p-value against the formulas computed apart (scipy's F distribution), and pure error against a group-by."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import stats

from demid.fit_statistics import LackOfFitAnova, pure_error_ss

SETTINGS = settings(max_examples=40, deadline=None, derandomize=True)


def _f_and_p(ss_a, df_a, ss_b, df_b, floor):
    if df_a <= 0 or df_b <= 0 or ss_b <= floor * df_b:
        return np.nan, np.nan
    f = (ss_a / df_a) / (ss_b / df_b)
    return f, stats.f.sf(f, df_a, df_b)


@given(ss=st.lists(st.floats(0.01, 1e4), min_size=4, max_size=4), df_model=st.integers(1, 9),
       df_lof=st.integers(0, 6), df_pe=st.integers(0, 6), df_block=st.integers(0, 3),
       floor=st.sampled_from([0.0, 0.0, 1e-3, 10.0]), scale=st.sampled_from([1e-6, 1.0, 1e6]),
       pe_share=st.sampled_from([None, None, 0.0, 0.5, 1.0, 1.5]))
@SETTINGS
def test_every_rows_mean_square_f_and_p_are_the_anova_formulas(ss, df_model, df_lof, df_pe, df_block, floor, scale,
                                                               pe_share):
    """``pe_share``: pure error as a share of the round-off floor's (identical replicates at 0)."""
    ss_model, ss_lof, ss_pe, ss_block = (v * scale for v in ss)
    floor = floor * scale
    if pe_share is not None:
        ss_pe = pe_share * floor * df_pe
    if df_lof == 0:
        ss_lof = 0.0
    if df_pe == 0:
        ss_pe = 0.0
    if df_block == 0:
        ss_block = 0.0
    ss_res, df_res = ss_lof + ss_pe, df_lof + df_pe
    anova = LackOfFitAnova("y", ss_model, df_model, ss_res, df_res, ss_lof, df_lof, ss_pe, df_pe,
                           ss_model + ss_res + ss_block, df_model + df_res + df_block, ss_floor=floor,
                           ss_block=ss_block, df_block=df_block)
    frame = anova.to_frame().set_index("source")
    expected = {"Model": (ss_model, df_model, *_f_and_p(ss_model, df_model, ss_res, df_res, floor)),
                "Residual": (ss_res, df_res, np.nan, np.nan),
                "Lack of fit": (ss_lof, df_lof, *_f_and_p(ss_lof, df_lof, ss_pe, df_pe, floor)),
                "Pure error": (ss_pe, df_pe, np.nan, np.nan),
                "Total (corrected)": (ss_model + ss_res + ss_block, df_model + df_res + df_block, np.nan, np.nan)}
    if df_block:
        expected = {"Blocks": (ss_block, df_block, *_f_and_p(ss_block, df_block, ss_res, df_res, floor)), **expected}
    assert list(frame.index) == list(expected)
    assert list(frame.columns) == ["response", "df", "sum_sq", "mean_sq", "F", "p_value", "note"]
    for source, (sum_sq, df, f, p) in expected.items():
        row = frame.loc[source]
        assert row["df"] == df and row["sum_sq"] == pytest.approx(sum_sq, rel=1e-12)
        mean_sq = sum_sq / df if df > 0 else np.nan
        np.testing.assert_allclose([row["mean_sq"], row["F"], row["p_value"]], [mean_sq, f, p], rtol=1e-9)
    assert anova.lof_f == pytest.approx(expected["Lack of fit"][2:], rel=1e-9, nan_ok=True)
    assert anova.model_f == pytest.approx(expected["Model"][2:], rel=1e-9, nan_ok=True)
    note = frame.loc["Lack of fit", "note"]
    if df_pe == 0:
        assert note.startswith("undefined: no replicated runs")
    elif df_lof == 0:
        assert note == "undefined: no degrees of freedom for lack of fit"
    elif ss_pe <= floor * df_pe:
        assert note.startswith("undefined: pure error is zero")
    else:
        assert note == ""
    assert (frame.drop(index="Lack of fit")["note"] == "").all()


@given(values=st.lists(st.floats(-1e3, 1e3), min_size=1, max_size=12), seed=st.integers(0, 1000),
       n_groups=st.integers(1, 5))
@SETTINGS
def test_pure_error_is_the_spread_about_each_groups_mean(values, seed, n_groups):
    groups = np.random.default_rng(seed).integers(0, n_groups, size=len(values)).astype(str)
    frame = pd.DataFrame({"y": values, "g": groups})
    expected = float(((frame["y"] - frame.groupby("g")["y"].transform("mean")) ** 2).sum())
    assert pure_error_ss(values, groups) == pytest.approx(expected, rel=1e-9, abs=1e-9)

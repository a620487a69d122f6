"""The ANOVA a fit stores and the report prints (SurrogateFit.anova_frame), every row and column against least squares
written out with numpy: the blocks' sum of squares (the spread of the block means), the model's, each term group's
partial sum of squares (the rise of the residual sum when the group is dropped), the residual, lack of fit and
pure error (replicates within their block) and the total; each F against the residual (lack of fit against pure
error) with scipy's F tail; no mean square, F or p where a row has no degrees of freedom.

Generated fits of one to three factors, linear or quadratic, one to three blocks, designs whose every point is
replicated (no degree of freedom for lack of fit: its sum of squares is round-off, never a mean square) or not
(a saturated fit leaves no residual degree of freedom)."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
from hypothesis import Phase, given, settings
from hypothesis import strategies as st
from scipy import stats

from demid.precision import round_off_floor
from demid.surrogate import fit_response

GROUPS = ("Linear", "Two-factor interaction", "Pure quadratic")


def _terms(k, quadratic):
    eye = [tuple(int(i == j) for i in range(k)) for j in range(k)]
    terms = [tuple([0] * k), *eye]
    if quadratic:
        terms += [tuple(a + b for a, b in zip(eye[i], eye[j])) for i in range(k) for j in range(i + 1, k)]
        terms += [tuple(2 * v for v in row) for row in eye]
    return terms


def _group(term):
    return "Linear" if sum(term) == 1 else "Pure quadratic" if max(term) == 2 else "Two-factor interaction"


def _sse(x, y):
    beta, *_ = np.linalg.lstsq(x, y, rcond=None)
    return float(np.sum((y - x @ beta) ** 2))


def _f_p(ss_a, df_a, ss_b, df_b, floor):
    if df_a <= 0 or df_b <= 0 or ss_b <= floor * df_b:
        return math.nan, math.nan
    f = (ss_a / df_a) / (ss_b / df_b)
    return f, float(stats.f.sf(f, df_a, df_b))


def _expected_rows(coded, y, terms, blocks):
    n = len(y)
    columns = np.column_stack([np.prod(coded ** np.array(t), axis=1) for t in terms])
    labels = sorted(set(blocks)) if blocks is not None else []
    indicators = [(np.asarray(blocks) == b).astype(float) for b in labels[1:]]
    x = np.column_stack([columns, *indicators])
    sse, sst = _sse(x, y), float(np.sum((y - y.mean()) ** 2))
    block_of = np.asarray(blocks) if blocks is not None else np.zeros(n)
    ss_block = sum(float(np.sum(block_of == b)) * (y[block_of == b].mean() - y.mean()) ** 2
                   for b in set(block_of.tolist())) if blocks is not None else 0.0
    keys = [tuple(np.round(row, 6)) + (b,) for row, b in zip(coded, block_of.tolist())]
    ss_pe = sum(float(np.sum((y[[i for i, k in enumerate(keys) if k == key]]
                              - y[[i for i, k in enumerate(keys) if k == key]].mean()) ** 2)) for key in set(keys))
    df_pe = n - len(set(keys))
    df_res = n - x.shape[1]
    floor = round_off_floor(y) ** 2
    rows = []
    if len(labels) > 1:
        rows.append(("Blocks", len(labels) - 1, ss_block, *_f_p(ss_block, len(labels) - 1, sse, df_res, floor)))
    rows.append(("Model", len(terms) - 1, sst - sse - ss_block, *_f_p(sst - sse - ss_block, len(terms) - 1, sse,
                                                                      df_res, floor)))
    for name in GROUPS:
        dropped = [j for j, t in enumerate(terms) if sum(t) > 0 and _group(t) == name]
        if dropped:
            ss = _sse(np.delete(x, dropped, axis=1), y) - sse
            rows.append((name, len(dropped), ss, *_f_p(ss, len(dropped), sse, df_res, floor)))
    rows += [("Residual", df_res, sse, math.nan, math.nan),
             ("Lack of fit", df_res - df_pe, sse - ss_pe, *_f_p(sse - ss_pe, df_res - df_pe, ss_pe, df_pe, floor)),
             ("Pure error", df_pe, ss_pe, math.nan, math.nan),
             ("Total (corrected)", n - 1, sst, math.nan, math.nan)]
    note = ("undefined: no replicated runs" if df_pe <= 0 else
            "undefined: no degrees of freedom for lack of fit" if df_res - df_pe <= 0 else
            "undefined: pure error is zero" if ss_pe <= floor * df_pe else "")
    return rows, note, sst


def _close(got, want, scale):
    if math.isnan(want):
        return math.isnan(got)
    return math.isclose(got, want, rel_tol=1e-6, abs_tol=1e-9 * scale)


@given(k=st.integers(1, 3), quadratic=st.booleans(), n_blocks=st.integers(1, 3), replicated=st.booleans(),
       extra=st.sampled_from([0, 0, 2, 5]), seed=st.integers(0, 10_000), scale=st.sampled_from([1e-3, 1.0, 300.0]))
@settings(max_examples=20, deadline=None, derandomize=True, phases=[Phase.explicit, Phase.generate])
def test_every_row_of_the_anova_is_least_squares_written_out(k, quadratic, n_blocks, replicated, extra, seed, scale):
    rng = np.random.default_rng(seed)
    terms = _terms(k, quadratic)
    p = len(terms) + n_blocks - 1
    points = rng.uniform(-1, 1, size=(p + extra, k)).round(3)
    coded = np.repeat(points, 2, axis=0) if replicated else points  # every point run twice: lack of fit has 0 df
    n = len(coded)
    blocks = None
    if n_blocks > 1:
        # every block holds a run; replicated points stay together in their block
        per_point = np.concatenate([np.arange(n_blocks), rng.integers(0, n_blocks, len(points) - n_blocks)])
        blocks = [f"B{b + 1}" for b in (np.repeat(per_point, 2) if replicated else per_point)]
    y = scale * (2.0 + coded @ rng.normal(size=k) + (coded ** 2).sum(axis=1) + rng.normal(size=n))
    table = pd.DataFrame(coded * 2.0 + 10.0, columns=[f"f{i + 1}" for i in range(k)])  # unit 2 about 10
    table.insert(0, "run", np.arange(1, n + 1))
    table["y"] = y
    if blocks is not None:
        table["block"] = blocks
    fit = fit_response(table, list(table.columns[1:k + 1]), "y", terms=terms)
    frame = fit.anova_frame()

    rows, note, sst = _expected_rows(fit.coded, y, terms, blocks)
    assert list(frame.columns) == ["response", "source", "df", "sum_sq", "mean_sq", "F", "p_value", "note"]
    assert list(frame["source"]) == [r[0] for r in rows] and (frame["response"] == "y").all()
    for (source, df, ss, f, p_value), got in zip(rows, frame.itertuples(index=False)):
        assert got.df == df, source
        assert _close(got.sum_sq, ss, sst), (source, got.sum_sq, ss)
        if df > 0:
            assert _close(got.mean_sq, ss / df, sst), source
        else:  # the round-off left in a sum without degrees of freedom is no mean square
            assert math.isnan(got.mean_sq), (source, got.sum_sq, got.mean_sq)
        assert _close(got.F, f, 1.0) and _close(got.p_value, p_value, 1e-3), (source, got.F, f)
    notes = dict(zip(frame["source"], frame["note"]))
    assert notes.pop("Lack of fit").startswith(note) and set(notes.values()) == {""}
    if replicated and extra == 0:  # as many distinct points as parameters, each run twice
        assert frame.set_index("source").loc["Lack of fit", "df"] == 0

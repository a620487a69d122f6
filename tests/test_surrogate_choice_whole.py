"""Every output of the surrogate choice against the rule written out here, over generated waves: 1-3 responses of
either sign (a saturating one, a quadratic one, one with too few finite runs for kriging), failed and missing runs,
factors in another order than the table's, lack-of-fit p-values given or not; the statistics frame (the quadratic's
columns kept, the four choice columns), the surrogates rebuilt for the next wave, each response's Q² used, its
record and its sentence (every quoted number parsed back), the criticism's marks and the untrustworthy-set rule."""

from __future__ import annotations

import re
from collections import namedtuple

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.kriging import KIND, QUADRATIC, KrigingSurrogate
from demid.precision import q2_text
from demid.surrogate_choice import (CHOICE_COLUMNS, SETS_SURROGATE_KEY, choice_text, choose_surrogates,
                                    chosen_surrogates, kriging_fits, mark_criticism, response_runs,
                                    sets_do_not_predict, surrogate_record, used_q2)

NAN = float("nan")
LO, HI = np.array([0.1, 1.0]), np.array([0.9, 11.0])


def _spec(responses):
    from demid.config import validate_schema
    from demid.spec import MaterialSpec

    material = {"data": "unused.csv", "design": {"type": "custom"},
                "factors": {"a": {"lower": float(LO[0]), "upper": float(HI[0])},
                            "b": {"lower": float(LO[1]), "upper": float(HI[1])}},
                "responses": {r: {"target": 1.0} for r in responses},
                "scenarios": {"all": {"observables": list(responses), "tolerance": 0.05}}}
    config = validate_schema({"materials": {"m": material}})  # the table is given to the choice, not read
    return MaterialSpec.from_material("m", config["materials"]["m"], grid_points=config["grid_points"])


_SHAPES = {
    "saturating": lambda u: 18 * np.tanh(4 * (u[:, 0] - 0.25)) + 6 * np.tanh(3 * u[:, 1]),
    "quadratic": lambda u: 6 * u[:, 0] + 4 * u[:, 1] - 3 * u[:, 0] ** 2 + 2 * u[:, 0] * u[:, 1],
    "sparse": lambda u: 3 * u[:, 0] - u[:, 1],
}


def _wave(seed, shapes, signs, failed):
    rng = np.random.default_rng(seed)
    n = 16
    u = rng.random((n, 2))
    x = LO + u * (HI - LO)
    table = pd.DataFrame({"run": np.arange(1, n + 1), "b": x[:, 1], "a": x[:, 0]})
    for i, (shape, sign) in enumerate(zip(shapes, signs)):
        y = sign * (20 + _SHAPES[shape](u)) + 0.05 * rng.standard_normal(n)
        if shape == "sparse":  # too few finite runs for kriging (a quadratic in 2 factors needs 6 + 3)
            y[8:] = [np.nan, np.inf, -np.inf, np.nan, np.nan, np.inf, np.nan, np.nan]
        table[f"y{i}"] = y
    table["status"] = ["failed" if i in failed else "ok" for i in range(n)]
    return table


def _quadratic_fits(table, responses):
    from demid.surrogate import fit_frames, fit_response, surrogates_from_frame

    fits = [fit_response(table[table["status"] != "failed"], ["a", "b"], r) for r in responses]
    frames = fit_frames(fits)
    return surrogates_from_frame(frames["fits"], ["a", "b"]), frames["statistics"]


def _prefers(q2_q, q2_k, lof_p):
    if not np.isfinite(q2_k):
        return False
    if not np.isfinite(q2_q):
        return True
    misfits = lof_p <= 0.05 if np.isfinite(lof_p) else q2_q < 0.9
    return (1 - q2_k) <= (0.8 if misfits else 0.5) * (1 - q2_q)


@pytest.mark.parametrize("seed, shapes, signs, failed, lof", [
    (2, ["sparse", "saturating", "quadratic"], [1.0, -1.0, 1.0], {12, 13}, None),
    (1, ["quadratic", "sparse"], [-1.0, 1.0], {3}, 0.01),
])
def test_the_choice_per_response_follows_its_rule_on_the_kept_runs(seed, shapes, signs, failed, lof):
    table = _wave(seed, shapes, signs, failed)
    responses = [f"y{i}" for i in range(len(shapes))]
    spec = _spec(responses)
    quadratic, statistics = _quadratic_fits(table, responses)
    if lof is not None:
        statistics = statistics.assign(lof_p=lof)
    elif "lof_p" in statistics:
        statistics = statistics.drop(columns="lof_p")
    choice = choose_surrogates(table, spec, quadratic, statistics)
    out = choice.statistics
    assert list(out.columns) == list(statistics.columns) + CHOICE_COLUMNS
    refitted = False
    pd.testing.assert_frame_equal(out[list(statistics.columns)], statistics.reset_index(drop=True))
    for i, response in enumerate(responses):
        keep = (table["status"] != "failed").to_numpy() & np.isfinite(table[response].to_numpy(dtype=float))
        x, y = table.loc[keep, ["a", "b"]].to_numpy(dtype=float), table.loc[keep, response].to_numpy(dtype=float)
        got_x, got_y = response_runs(table, ["a", "b"], response)
        assert np.array_equal(got_x, x) and np.array_equal(got_y, y)
        row = out.iloc[i]
        q2_q = float(statistics["q2"].iloc[i])
        assert row["q2_quadratic"] == pytest.approx(q2_q, nan_ok=True)
        if len(y) <= 8:  # the trend's 6 coefficients and 2: no kriging
            assert np.isnan(row["q2_kriging"]) and row["kriging_hyperparameters"] == ""
            assert row["surrogate"] == QUADRATIC and choice.surrogates[response] is quadratic[response]
            continue
        # the stored hyper-parameters are the likelihood's pick on the kept runs (refitted here for the first
        # kriging response only, to keep the test fast); the Q² is kriging's on those runs with them
        hyper = row["kriging_hyperparameters"]
        kriging = KrigingSurrogate.from_hyperparameters(response, ["a", "b"], x, y, LO, HI, hyper)
        if not refitted:
            assert hyper == KrigingSurrogate.fit(response, ["a", "b"], x, y, LO, HI).hyperparameters_json()
            refitted = True
        assert row["q2_kriging"] == pytest.approx(kriging.q2, rel=1e-9)
        expected = KIND if _prefers(q2_q, kriging.q2, NAN if lof is None else lof) else QUADRATIC
        assert row["surrogate"] == expected
        used = choice.surrogates[response]
        if expected == QUADRATIC:
            assert used is quadratic[response]
        else:
            at = LO + np.random.default_rng(1).random((5, 2)) * (HI - LO)
            assert used.kind == KIND and np.array_equal(used.predict(at), kriging.predict(at))
    # the next wave rebuilds the same surrogates from the stored statistics
    rebuilt = chosen_surrogates(table, spec, quadratic, out)
    at = LO + np.random.default_rng(2).random((6, 2)) * (HI - LO)
    for response in responses:
        assert np.array_equal(rebuilt[response].predict(at), choice.surrogates[response].predict(at))
    assert chosen_surrogates(table, spec, quadratic, statistics) == quadratic
    assert chosen_surrogates(table, spec, quadratic, None) == quadratic


def test_runs_are_those_not_failed_with_a_finite_response_and_a_table_without_status_keeps_every_finite_one():
    table = pd.DataFrame({"b": [1.0, 2.0, 3.0, 4.0], "a": [5.0, 6.0, 7.0, 8.0], "y": [1.0, np.nan, 3.0, 4.0],
                          "status": ["ok", "ok", "failed", "ok"]})
    x, y = response_runs(table, ["a", "b"], "y")
    assert x.tolist() == [[5.0, 1.0], [8.0, 4.0]] and y.tolist() == [1.0, 4.0]
    x, y = response_runs(table.drop(columns="status"), ["b", "a"], "y")
    assert x.tolist() == [[1.0, 5.0], [3.0, 7.0], [4.0, 8.0]] and y.tolist() == [1.0, 3.0, 4.0]


@pytest.mark.parametrize("k", [1, 2, 3, 4])
def test_kriging_needs_three_runs_beyond_its_trend_and_at_most_a_thousand(k):
    from types import SimpleNamespace

    spec = SimpleNamespace(dim=k)
    trend = (k + 1) * (k + 2) // 2
    assert [kriging_fits(n, spec) for n in (trend + 2, trend + 3, 1000, 1001)] == [False, True, True, False]


_Row = namedtuple("_Row", "response q2 surrogate q2_kriging lof_p")
_Plain = namedtuple("_Plain", "response q2")


def _numbers(text):
    return [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?", text)]


@given(q2=st.one_of(st.floats(-3.0, 0.999), st.just(NAN)), q2_k=st.one_of(st.floats(-3.0, 0.999), st.just(NAN)),
       lof_p=st.sampled_from([NAN, 0.01, 0.05, 0.2]), kriged=st.booleans())
@settings(max_examples=60, deadline=None, derandomize=True)
def test_used_q2_record_and_sentence_quote_the_used_surrogates_numbers(q2, q2_k, lof_p, kriged):
    row = _Row("y", q2, KIND if kriged else QUADRATIC, q2_k, lof_p)
    used = q2_k if kriged else q2
    assert used_q2(row) == pytest.approx(used, nan_ok=True) and type(used_q2(row)) is float
    assert used_q2(_Plain("y", q2)) == pytest.approx(q2, nan_ok=True)
    record = surrogate_record(row)
    assert record == {"used": row.surrogate, "q2_quadratic": None if np.isnan(q2) else q2,
                      "q2_kriging": None if np.isnan(q2_k) else q2_k}
    assert all(v is None or type(v) is float for v in record.values() if v not in (KIND, QUADRATIC))
    assert surrogate_record(_Plain("y", q2)) == {"used": QUADRATIC, "q2_quadratic": None if np.isnan(q2) else q2,
                                                 "q2_kriging": None}
    text = choice_text("θ", row)
    if kriged:
        assert text == f"θ by kriging (Q² {q2_text(q2_k)} against the quadratic's {q2_text(q2)})"
    elif np.isfinite(q2_k):
        misfits = lof_p <= 0.05 if np.isfinite(lof_p) else q2 < 0.9
        assert text.startswith(f"θ by the quadratic (Q² {q2_text(q2)}: kriging's {q2_text(q2_k)} does not cut")
        assert _numbers(text)[-1] == (0.8 if misfits else 0.5)
    else:
        assert text == f"θ by the quadratic (Q² {q2_text(q2)})"
    assert choice_text("θ", _Plain("y", q2)) == f"θ by the quadratic (Q² {q2_text(q2)})"


def test_the_criticism_learns_only_of_kriging_judged_responses_it_has_each_with_its_own_q2():
    statistics = pd.DataFrame({"response": ["a", "b", "c", "d"], "q2": [0.1, 0.2, 0.3, 0.4],
                               "surrogate": [KIND, QUADRATIC, KIND, KIND], "q2_kriging": [0.7, 0.8, -0.2, 0.95]})
    summary = {"level1": {"a": {"verdict": "does_not_predict"}, "b": {"verdict": "ok"}, "c": {}}}
    mark_criticism(summary, statistics)
    assert summary["level1"] == {"a": {"verdict": "does_not_predict", SETS_SURROGATE_KEY: {"surrogate": KIND, "q2": 0.7}},
                                 "b": {"verdict": "ok"},
                                 "c": {SETS_SURROGATE_KEY: {"surrogate": KIND, "q2": -0.2}}}
    empty = {}
    mark_criticism(empty, statistics)
    assert empty == {}


@pytest.mark.parametrize("entry, expected", [
    ({"verdict": "ok"}, False),
    ({"verdict": "does_not_predict"}, True),
    ({"verdict": "does_not_predict", SETS_SURROGATE_KEY: {"surrogate": KIND, "q2": 0.0}}, False),
    ({"verdict": "does_not_predict", SETS_SURROGATE_KEY: {"surrogate": KIND, "q2": 0.4}}, False),
    ({"verdict": "does_not_predict", SETS_SURROGATE_KEY: {"surrogate": KIND, "q2": -1e-9}}, True),
    ({"verdict": "does_not_predict", SETS_SURROGATE_KEY: {"surrogate": KIND, "q2": None}}, True),
    ({"verdict": "does_not_predict", SETS_SURROGATE_KEY: {}}, True),
    ({"verdict": "ok", SETS_SURROGATE_KEY: {"surrogate": KIND, "q2": -0.5}}, False),
])
def test_a_set_is_untrustworthy_only_where_the_surrogate_it_rests_on_does_not_predict(entry, expected):
    assert sets_do_not_predict(entry) is expected

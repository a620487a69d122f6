"""The waves' outputs a user reads, against computations written here over generated inputs: the wave history's
plausible columns (share of Omega and interval per scenario and factor, NaN where a frame lacks a set), the waves
summary with 1-3 responses judged by either surrogate (labels, both Q², the sentence of each, failed runs, the
refocus scenario's share and intervals), each response's leave-one-out error in the stop rule (the quadratic's
sqrt(PRESS / n), kriging's from its Q² over the same total sum of squares) and its share of the band, the
band-fixes-the-boundary rule at its threshold, and the share the stop sentence quotes."""

from __future__ import annotations

import math
import re
from collections import namedtuple

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.config import validate_schema
from demid.kriging import KIND, QUADRATIC
from demid.precision import q2_text
from demid.spec import MaterialSpec
from demid.waves import (BAND_FIXED_SHARE, WaveEvidence, _largest_share, band_fixes_boundary, loo_error,
                         stop_decision, surrogate_evidence, wave_history, wave_summary)

NAN = float("nan")
_Row = namedtuple("_Row", "response n_runs press q2 lof_p surrogate q2_kriging")


def _spec(responses=("y",), labels=None) -> MaterialSpec:
    material = {"data": "m.csv", "design": {"type": "ccd", "alpha": 1.41421, "center_runs": 3},
                "factors": {"a": {"lower": -2.0, "upper": 6.0}, "b": {"lower": 0.1, "upper": 100.0, "scale": "log"}},
                "responses": {r: {"target": 5.0 - 4 * i, **({"label": labels[i]} if labels else {})}
                              for i, r in enumerate(responses)},
                "scenarios": {"s": {"observables": [responses[0]], "tolerance": 0.05},
                              "t": {"observables": list(responses), "tolerance": 0.02}}}
    return MaterialSpec.from_material("m", validate_schema({"materials": {"m": material}})["materials"]["m"])


@given(n=st.integers(1, 40), press=st.floats(0.0, 50.0), q2=st.floats(-2.0, 0.999), q2_k=st.floats(-2.0, 1.5),
       band=st.sampled_from([0.0, -1.0, 0.01, 2.5, 1e3]), kriged=st.booleans(), lof=st.sampled_from([NAN, 0.01, 0.7]))
@settings(max_examples=60, deadline=None, derandomize=True)
def test_the_leave_one_out_error_is_the_used_surrogates_and_its_share_of_the_band(n, press, q2, q2_k, band, kriged,
                                                                                 lof):
    row = _Row("y", n, press, q2, lof, KIND if kriged else QUADRATIC, q2_k)
    sst = press / (1.0 - q2)  # the quadratic's PRESS over its unexplained share: the runs' total sum of squares
    expected = math.sqrt(max(1.0 - q2_k, 0.0) * sst / n) if kriged else math.sqrt(press / n)
    assert loo_error(row) == pytest.approx(expected, rel=1e-9, abs=1e-300)
    evidence = surrogate_evidence(row, band)
    assert evidence["q2"] == (q2_k if kriged else q2)
    assert (math.isnan(evidence["lof_p"]) if kriged or math.isnan(lof) else evidence["lof_p"] == lof)
    if band > 0:
        assert evidence["loo_band"] == pytest.approx(expected / band, rel=1e-9, abs=1e-300)
    else:
        assert math.isnan(evidence["loo_band"])


@pytest.mark.parametrize("row", [_Row("y", 0, 1.0, 0.5, NAN, QUADRATIC, NAN), _Row("y", 10, NAN, 0.5, NAN, QUADRATIC, NAN),
                                 _Row("y", 10, 1.0, 1.0, NAN, KIND, 0.9), _Row("y", 10, 1.0, NAN, NAN, KIND, 0.9)])
def test_the_leave_one_out_error_is_undefined_without_runs_press_or_a_quadratic_q2_below_one(row):
    assert math.isnan(loo_error(row))


@pytest.mark.parametrize("shares, fixed", [
    ([], False), ([0.1], True), ([BAND_FIXED_SHARE], True), ([BAND_FIXED_SHARE * (1 + 1e-12)], False),
    ([0.1, 0.2], True), ([0.1, 0.3], False), ([0.1, None], False), ([0.1, NAN], False), ([0.0], True)])
def test_the_band_fixes_the_boundary_only_where_every_error_is_within_a_quarter_of_it(shares, fixed):
    surrogates = {f"y{i}": {"q2": 0.9, "lof_p": NAN, "loo_band": s} for i, s in enumerate(shares)}
    assert band_fixes_boundary(surrogates) is fixed


@pytest.mark.parametrize("shares", [[0.3], [0.26, 1.7, 0.4], [2.345]])
def test_the_stop_sentence_quotes_the_largest_share_to_two_decimals(shares):
    surrogates = {f"y{i}": {"q2": 0.9, "lof_p": NAN, "loo_band": s} for i, s in enumerate(shares)}
    text = _largest_share(surrogates)
    assert f"up to {max(shares):.2f} of the tolerance band's half-width (more than 0.25)" in text
    for unknown in (None, NAN):
        partial = {**surrogates, "z": {"q2": 0.9, "lof_p": NAN, "loo_band": unknown}}
        assert _largest_share(partial) == "the surrogates' leave-one-out error against the tolerance band is not known"
    # a settled share with an error too large to stop on: the sentence goes on and quotes the same largest share
    evidence = WaveEvidence(wave=2, max_waves=5, plausible_pct=10.0, previous_pct=10.5, surrogates=surrogates,
                            model_limit=False, proposed=9, criticism_runs=0)
    decision = stop_decision(None, evidence)
    assert decision["stop"] is False and f"up to {max(shares):.2f} of" in decision["reason"]
    change = re.search(r"\(([+-]\d+\.\d) %\)", decision["reason"]).group(1)
    assert float(change) == round(100 * (10.0 - 10.5) / 10.5, 1)


def _plausible(rng, scenarios=("s", "t"), factors=("a", "b"), missing=()):
    rows = []
    for sc in scenarios:
        pct = float(rng.uniform(0, 60))
        for f in factors:
            if (sc, f) in missing:
                continue
            lo = float(rng.uniform(-2, 2) if f == "a" else rng.uniform(0.1, 5))
            rows.append({"scenario": sc, "factor": f, "robust_fraction_pct": pct, "robust_lower": lo,
                         "robust_upper": lo + float(rng.uniform(0, 3))})
    return pd.DataFrame(rows)


@given(waves=st.integers(1, 3), seed=st.integers(0, 10_000), drop=st.booleans())
@settings(max_examples=8, deadline=None, derandomize=True)
def test_the_wave_history_quotes_each_sets_plausible_share_and_interval(waves, seed, drop):
    rng = np.random.default_rng(seed)
    spec = _spec(("y", "z"))
    given_waves, frames = [], []
    for number in range(1, waves + 1):
        scenarios = pd.DataFrame([{"scenario": sc, "factor": f, "feasible_fraction_pct": 1.0, "lower": 0.0,
                                   "upper": 1.0, "width": 1.0} for sc in ("s", "t") for f in ("a", "b")])
        plausible = _plausible(rng, missing={("t", "b")} if drop else ())
        frames.append(plausible)
        given_waves.append({"scenarios": scenarios, "domain": None, "simulated": 10, "analysed": 10,
                            "plausible": plausible if number != 2 else None})
    history = wave_history(spec, given_waves)
    for row in history.itertuples():
        frame = frames[row.wave - 1]
        hit = frame[(frame["scenario"] == row.scenario) & (frame["factor"] == row.factor)]
        got = [row.plausible_fraction_of_omega_pct, row.plausible_lower, row.plausible_upper]
        if row.wave == 2 or not len(hit):
            assert all(math.isnan(v) for v in got)
        else:
            assert got == [hit["robust_fraction_pct"].iloc[0], hit["robust_lower"].iloc[0], hit["robust_upper"].iloc[0]]


@given(seed=st.integers(0, 10_000), responses=st.integers(1, 3), labelled=st.booleans(), waves=st.integers(1, 3))
@settings(max_examples=10, deadline=None, derandomize=True)
def test_the_waves_summary_quotes_each_waves_runs_surrogates_and_refocus_set(seed, responses, labelled, waves):
    rng = np.random.default_rng(seed)
    names = ("y", "z", "w")[:responses]
    labels = ("θ", "μ", "ρ")[:responses] if labelled else None
    spec = _spec(names, labels)
    refocus = "t"  # the most observables; a tie (one response) goes to the smaller tolerance, t's
    given_waves = []
    for number in range(1, waves + 1):
        runs = int(rng.integers(10, 30))
        failed = int(rng.integers(0, 4))
        table = pd.DataFrame({"run": range(runs), "status": ["failed"] * failed + ["ok"] * (runs - failed)})
        kinds = [KIND if rng.random() < 0.5 else QUADRATIC for _ in names]
        stats = pd.DataFrame({"response": list(names), "q2": rng.uniform(-0.5, 0.99, responses),
                              "surrogate": kinds, "q2_kriging": rng.uniform(-0.5, 0.99, responses),
                              "lof_p": rng.uniform(0, 1, responses)})
        analysed = int(rng.integers(5, runs + 1))
        given_waves.append({"table": table, "analysed": table.head(analysed), "domain": None,
                            "plausible": _plausible(rng), "statistics": stats})
    summary = wave_summary(spec, given_waves, None)
    assert summary["material"] == "m" and summary["decision"] is None and len(summary["waves"]) == waves
    for number, (wave, got) in enumerate(zip(given_waves, summary["waves"]), start=1):
        table, stats = wave["table"], wave["statistics"]
        assert (got["wave"], got["simulated"], got["failed"], got["analysed"]) == (
            number, len(table), int((table["status"] == "failed").sum()), len(wave["analysed"]))
        assert got["scenario"] == refocus
        frame = wave["plausible"][wave["plausible"]["scenario"] == refocus]
        assert got["plausible_fraction_of_omega_pct"] == frame["robust_fraction_pct"].iloc[0]
        assert got["plausible"] == {r.factor: [r.robust_lower, r.robust_upper] for r in frame.itertuples()}
        sentences = got["surrogate"].split("; ")  # one sentence per response, and no "; " inside one
        assert len(sentences) == responses
        for i, row in enumerate(stats.itertuples()):
            used = row.q2_kriging if row.surrogate == KIND else row.q2
            assert got["q2"][row.response] == used
            assert got["surrogates"][row.response] == {"used": row.surrogate, "q2_quadratic": row.q2,
                                                       "q2_kriging": row.q2_kriging}
            label = labels[i] if labelled else row.response
            assert sentences[i].startswith(f"{label} by {'kriging' if row.surrogate == KIND else 'the quadratic'} (Q² ")
            quoted = re.findall(r"Q² (-?\d+\.\d+)|kriging's (-?\d+\.\d+)|quadratic's (-?\d+\.\d+)", sentences[i])
            numbers = [next(v for v in group if v) for group in quoted]
            expected = ([row.q2_kriging, row.q2] if row.surrogate == KIND else [row.q2, row.q2_kriging])
            assert numbers == [q2_text(v) for v in expected]


@pytest.mark.parametrize("k, log_mask, centre", [(2, 0b01, 2), (3, 0b110, 1), (2, 0b11, 3)])
def test_the_first_wave_is_the_three_level_factorial_over_the_bounds_with_log_factors_in_log10(k, log_mask, centre):
    from collections import Counter

    from demid.waves import first_wave

    bounds = [(0.02 * (i + 1), 50.0 * (i + 1)) if log_mask >> i & 1 else (-3.0 + i, 4.5 + i) for i in range(k)]
    factors = {f"f{i}": {"lower": lo, "upper": hi, **({"scale": "log"} if log_mask >> i & 1 else {})}
               for i, (lo, hi) in enumerate(bounds)}
    material = {"data": "m.csv", "design": {"type": "factorial", "center_runs": centre}, "factors": factors,
                "responses": {"y": {"target": 1.0}}, "scenarios": {"s": {"observables": ["y"], "tolerance": 0.05}}}
    spec = MaterialSpec.from_material("m", validate_schema({"materials": {"m": material}})["materials"]["m"])
    frame = first_wave(spec, seed=5)
    runs = 3 ** k - 1 + centre
    assert list(frame.columns) == ["run", *factors] and frame["run"].tolist() == list(range(1, runs + 1))
    # each factor at its bounds and middle (a log factor's geometric mean), every combination once, the centre as
    # often as the centre runs (the middles compared to 8 significant digits: the sheet rounds a log factor's log10)
    levels = [(lo, math.sqrt(lo * hi) if log_mask >> i & 1 else (lo + hi) / 2, hi) for i, (lo, hi) in enumerate(bounds)]
    grid = np.array(np.meshgrid(*levels, indexing="ij")).reshape(k, -1).T
    expected = Counter(tuple(float(f"{v:.8g}") for v in row) for row in grid)
    expected[tuple(float(f"{lv[1]:.8g}") for lv in levels)] += centre - 1
    got = Counter(tuple(float(f"{v:.8g}") for v in row) for row in frame[list(factors)].to_numpy())
    assert got == expected
    # a bound run is on the declared bound exactly, log factors too (not 50.0000000005 for 50), never outside it
    for name, (lo, hi) in zip(factors, bounds):
        values = frame[name]
        assert values.min() == lo and values.max() == hi
        assert int((values == lo).sum()) == int((values == hi).sum()) == 3 ** (k - 1)
    assert frame.equals(first_wave(spec, seed=5))


@pytest.mark.parametrize("criticism, spent", [(0, False), (3, False), (1, True), (5, True)])
def test_a_surrogate_that_cannot_be_stopped_on_quotes_the_proposed_and_the_criticisms_runs(criticism, spent):
    bad = {"y": {"q2": 0.3, "lof_p": NAN, "loo_band": 0.1}}
    evidence = WaveEvidence(wave=3 if spent else 2, max_waves=3, plausible_pct=5.0, previous_pct=5.0, surrogates=bad,
                            model_limit=False, proposed=11, criticism_runs=criticism)
    reason = stop_decision(None, evidence)["reason"]
    clause = re.search(r"the next wave's (\d+) proposed runs(?:, (\d+) of them replicates or runs the criticism asks "
                       r"for,)? add runs where", reason)
    assert int(clause[1]) == 11 and (int(clause[2]) if clause[2] else 0) == criticism
    assert ("the budget of 3 waves is spent" in reason) is spent


@pytest.mark.parametrize("shares", [[0.1], [0.25, 0.04], [0.123, 0.2, 0.0]])
def test_a_settled_stop_quotes_the_largest_leave_one_out_share_and_the_change(shares):
    surrogates = {f"y{i}": {"q2": 0.9, "lof_p": NAN, "loo_band": s} for i, s in enumerate(shares)}
    evidence = WaveEvidence(wave=4, max_waves=6, plausible_pct=8.0, previous_pct=7.5, surrogates=surrogates,
                            model_limit=False, proposed=9, criticism_runs=0)
    decision = stop_decision(None, evidence)
    assert decision["stop"] is True and decision["action"] == "stop"
    quoted = re.search(r"leave-one-out error is at most (\d\.\d\d) of the tolerance band", decision["reason"])
    assert float(quoted[1]) == round(max(shares), 2)
    assert "went 7.5 % → 8 % from wave 3 to wave 4 (+6.7 %)" in decision["reason"]

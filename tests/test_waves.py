"""The waves of a simulated material (demid/waves.py): the stop decision over generated evidence, judged against
its rule written out here and with every number its sentence quotes parsed back; the measured change; which runs
lie in a box; the next wave's run numbers; a box's share of the search range (log factors in decades); and the
smallest next-runs count a wave accepts, for two to four factors."""

from __future__ import annotations

import math
import re

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.config import check_semantics, validate_schema
from demid.errors import InputError
from demid.spec import MaterialSpec
from demid.wave_value import STOP_CONTRACTION
from demid.waves import (BAND_FIXED_SHARE, LACK_OF_FIT_ALPHA, STOP_Q2, WaveEvidence, box_share, check_simulated, inside_domain,
                         measured_change, next_wave_runs, stop_decision, stops_early, surrogate_limits, wave_evidence,
                         wave_material, wave_summary, waves_max)

_NUMBER = r"[-+]?\d+(?:\.\d+)?(?:e[-+]?\d+)?"


def _evidence(**changes) -> WaveEvidence:
    base = dict(wave=2, max_waves=4, plausible_pct=1.55, previous_pct=1.40,
                surrogates={"y1": {"q2": 0.97, "lof_p": 0.40, "loo_band": 0.1}}, model_limit=False, proposed=9,
                criticism_runs=0)
    return WaveEvidence(**{**base, **changes})


def _value(contraction: float, stop: bool) -> dict:
    return {"scenario": "both", "count": 9, "plausible_fraction_pct": 9.3,
            "expected_fraction_pct": 9.3 * (1 - contraction), "expected_contraction": contraction, "stop": stop}


# ------------------------------------------------------------------------------------------ measured change
@given(previous=st.one_of(st.none(), st.floats(-1.0, 100.0)), now=st.floats(0.0, 100.0))
@settings(max_examples=60, deadline=None, derandomize=True)
def test_measured_change_is_the_relative_change_of_the_plausible_share(previous, now):
    change = measured_change(_evidence(previous_pct=previous, plausible_pct=now))
    if previous is None or previous <= 0:
        assert change is None
    else:
        assert change == pytest.approx(now / previous - 1.0, rel=1e-12, abs=1e-12)


# ------------------------------------------------------------------------------------------ surrogate limits
@pytest.mark.parametrize("q2, lof_p, clauses", [
    (STOP_Q2, LACK_OF_FIT_ALPHA + 1e-9, []),  # both at their thresholds' passing side
    (STOP_Q2 - 1e-9, 0.5, ["does not predict well enough (Q² = 0.50 < 0.5)"]),
    (0.31, 0.5, ["does not predict well enough (Q² = 0.31 < 0.5)"]),
    (-2.4, 0.5, ["does not predict well enough (Q² = -2.40 < 0.5)"]),
    (0.9, LACK_OF_FIT_ALPHA, ["misfits the replicated runs (lack of fit p = 0.05)"]),
    (0.9, 0.0123, ["misfits the replicated runs (lack of fit p = 0.012)"]),
    (0.2, 0.001, ["does not predict well enough (Q² = 0.20 < 0.5)", "misfits the replicated runs (lack of fit "
                                                                   "p = 0.001)"]),
    (float("nan"), 0.5, ["is not checked on left-out runs"]),
    (None, None, ["is not checked on left-out runs"]),
    (0.9, float("nan"), []),
    (0.9, None, []),
])
def test_surrogate_limits_name_each_response_that_cannot_be_stopped_on(q2, lof_p, clauses):
    assert (STOP_Q2, LACK_OF_FIT_ALPHA) == (0.5, 0.05)
    out = surrogate_limits({"y1": {"q2": 0.95, "lof_p": 0.6}, "y7": {"q2": q2, "lof_p": lof_p}})
    assert len(out) == len(clauses)
    for line, clause in zip(out, clauses):
        assert line.startswith("the surrogate of y7 ") and clause in line, (line, clause)


# ------------------------------------------------------------------------------------------ the stop rule
def _expected(value, ev: WaveEvidence) -> tuple[bool, str]:
    """The stop rule of the module docstring, written out: (stop, action)."""
    spent = ev.wave >= ev.max_waves
    bad = any(s["q2"] is None or not math.isfinite(s["q2"]) or s["q2"] < 0.5
              or (s["lof_p"] is not None and math.isfinite(s["lof_p"]) and s["lof_p"] <= 0.05)
              for s in ev.surrogates.values())
    if bad:
        return (True, "recalibrate") if spent else (False, "next_runs")
    if ev.model_limit:
        return True, "stop"
    change = None if ev.previous_pct is None or ev.previous_pct <= 0 else ev.plausible_pct / ev.previous_pct - 1
    band_fixed = all(s.get("loo_band") is not None and math.isfinite(s["loo_band"]) and s["loo_band"] <= 0.25
                     for s in ev.surrogates.values())
    if change is not None and abs(change) <= 0.10 and band_fixed:
        return True, "stop"
    if change is None and value and value["stop"] and band_fixed:
        return True, "stop"
    return (True, "next_runs") if spent else (False, "next_runs")


_surrogate = st.fixed_dictionaries({"q2": st.sampled_from([0.97, 0.62, 0.5, 0.49, float("nan")]),
                                    "lof_p": st.sampled_from([0.8, 0.051, 0.05, 0.003, float("nan")]),
                                    "loo_band": st.sampled_from([0.05, 0.25, 0.26, 0.9, float("nan")])})


@given(wave=st.integers(1, 5), max_waves=st.integers(1, 5), previous=st.sampled_from([None, 0.0, 1.0, 2.5, 40.0]),
       ratio=st.sampled_from([0.5, 0.85, 0.89, 0.91, 0.95, 1.0, 1.05, 1.09, 1.11, 1.2, 2.0]),
       surrogates=st.lists(_surrogate, min_size=1, max_size=3), model_limit=st.booleans(),
       value=st.sampled_from([None, "small", "big"]), proposed=st.integers(7, 30), criticism=st.integers(0, 6))
@settings(max_examples=150, deadline=None, derandomize=True)
def test_stop_decision_follows_the_stop_rule_and_quotes_its_numbers(wave, max_waves, previous, ratio, surrogates,
                                                                   model_limit, value, proposed, criticism):
    now = 3.0 if previous is None or previous == 0 else previous * ratio
    ev = _evidence(wave=wave, max_waves=max_waves, previous_pct=previous, plausible_pct=now,
                   surrogates={f"y{i + 1}": s for i, s in enumerate(surrogates)}, model_limit=model_limit,
                   proposed=proposed, criticism_runs=min(criticism, proposed))
    wave_value = {"small": _value(0.04, True), "big": _value(0.35, False)}.get(value)
    decision = stop_decision(wave_value, ev)
    stop, action = _expected(wave_value, ev)
    assert (decision["stop"], decision["action"]) == (stop, action), decision["reason"]
    reason = decision["reason"]
    if action == "recalibrate" or (action == "next_runs" and wave >= max_waves):
        assert f"the budget of {max_waves} wave{'s' if max_waves != 1 else ''} is spent" in reason
    else:
        assert "budget" not in reason
    change = measured_change(ev)
    quoted = re.search(rf"went ({_NUMBER}) % → ({_NUMBER}) % from wave (\d+) to wave (\d+) \(({_NUMBER}) %\)",
                       reason)
    if quoted:  # the change sentence: both shares, both waves and the change, each as a number
        assert change is not None
        assert float(quoted[1]) == pytest.approx(previous, rel=5.1e-3)  # three significant digits
        assert float(quoted[2]) == pytest.approx(now, rel=5.1e-3)
        assert (int(quoted[3]), int(quoted[4])) == (wave - 1, wave)
        assert float(quoted[5]) == pytest.approx(100 * change, abs=0.051)
    if "proposed runs" in reason and action != "stop":
        assert f"{proposed} proposed runs" in reason
    if action == "stop" and "within the" in reason:
        assert "within the 10 % change" in reason


def test_stop_decision_reads_the_change_threshold_on_both_sides_and_for_a_shrink_and_a_growth():
    assert STOP_CONTRACTION == 0.10
    for previous, now, stops in [(2.0, 1.81, True), (2.0, 2.19, True), (2.0, 1.79, False), (2.0, 2.21, False),
                                 (10.0, 9.05, True), (10.0, 11.5, False), (10.0, 5.0, False)]:
        decision = stop_decision(None, _evidence(previous_pct=previous, plausible_pct=now))
        assert decision["stop"] is stops, (previous, now, decision)


def test_a_predicted_shrink_is_quoted_as_its_numbers():
    fixed = {"y1": {"q2": 0.97, "lof_p": 0.40, "loo_band": 0.12}}
    decision = stop_decision(_value(0.04, True), _evidence(wave=1, previous_pct=None, surrogates=fixed))
    assert "leave-one-out error is at most 0.12 of the tolerance band's half-width" in decision["reason"]
    quoted = re.search(rf"the (\d+) proposed runs are expected to shrink the plausible set of 'both' by only "
                       rf"({_NUMBER}) % \(({_NUMBER}) % → ({_NUMBER}) %", decision["reason"])
    assert quoted, decision["reason"]
    assert int(quoted[1]) == 9 and float(quoted[2]) == pytest.approx(4.0)
    assert float(quoted[3]) == pytest.approx(9.3) and float(quoted[4]) == pytest.approx(9.3 * 0.96, rel=1e-3)
    # a measured change decides over a prediction: the same prediction after a moving wave goes on
    assert stop_decision(_value(0.04, True), _evidence(previous_pct=1.0, plausible_pct=2.0))["stop"] is False


@pytest.mark.parametrize("shares, stops", [((0.1,), True), ((BAND_FIXED_SHARE,), True), ((0.1, 0.2), True),
                                           ((0.26,), False), ((0.1, 0.7), False), ((float("nan"),), False),
                                           ((None,), False)])
def test_after_the_first_design_a_predicted_shrink_stops_only_where_the_band_fixes_the_boundary(shares, stops):
    """After the first design nothing is measured yet: a small predicted shrink stops the waves only when every
    surrogate's leave-one-out error is small against the tolerance band; otherwise the stop line says how large
    it is and the next wave runs."""
    assert BAND_FIXED_SHARE == 0.25
    surrogates = {f"y{i}": {"q2": 0.95, "lof_p": 0.5, **({} if s is None else {"loo_band": s})}
                  for i, s in enumerate(shares)}
    decision = stop_decision(_value(0.04, True), _evidence(wave=1, previous_pct=None, surrogates=surrogates))
    assert (decision["stop"], decision["action"]) == ((True, "stop") if stops else (False, "next_runs"))
    if not stops:
        assert "expected to shrink the set by only 4.0 %, but" in decision["reason"]
        known = [s for s in shares if s is not None and math.isfinite(s)]
        if len(known) == len(shares):
            assert f"up to {max(known):.2f} of the tolerance band's half-width" in decision["reason"]
        else:
            assert "is not known" in decision["reason"]


def test_a_settled_share_stops_only_where_the_band_fixes_the_boundary():
    """A plausible share that moved by less than 10 % between two waves stops the waves only when the
    surrogates' leave-one-out error is small against the band: a share can stay while the boundary, uncertain by
    a good part of the band, still moves."""
    fixed = stop_decision(None, _evidence(previous_pct=2.0, plausible_pct=1.9))
    assert fixed["stop"] is True and "at most 0.10 of the tolerance band's half-width" in fixed["reason"]
    loose = {"y1": {"q2": 0.97, "lof_p": 0.40, "loo_band": 0.1}, "y2": {"q2": 0.9, "lof_p": 0.3, "loo_band": 0.6}}
    going = stop_decision(None, _evidence(previous_pct=2.0, plausible_pct=1.9, surrogates=loose))
    assert (going["stop"], going["action"]) == (False, "next_runs")
    assert "(-5.0 %), but the surrogates' leave-one-out error is up to 0.60" in going["reason"]
    last = stop_decision(None, _evidence(wave=4, previous_pct=2.0, plausible_pct=1.9, surrogates=loose))
    assert (last["stop"], last["action"]) == (True, "next_runs") and "budget of 4 waves is spent" in last["reason"]


def test_a_misfitting_surrogate_asks_for_the_next_runs_and_counts_the_criticisms():
    bad = {"y1": {"q2": 0.3, "lof_p": 0.5}}
    going = stop_decision(None, _evidence(surrogates=bad, proposed=12, criticism_runs=5))
    assert "the next wave's 12 proposed runs, 5 of them replicates or runs the criticism asks for," in going["reason"]
    plain = stop_decision(None, _evidence(surrogates=bad, proposed=12, criticism_runs=0))
    assert "the next wave's 12 proposed runs add runs" in plain["reason"] and "of them" not in plain["reason"]
    spent = stop_decision(None, _evidence(surrogates=bad, wave=3, max_waves=3, proposed=12))
    assert spent["action"] == "recalibrate" and "the budget of 3 waves is spent" in spent["reason"]
    not_yet = stop_decision(None, _evidence(surrogates=bad, wave=2, max_waves=3, proposed=12))
    assert not_yet == {"stop": False, "action": "next_runs", "reason": not_yet["reason"]}


# ------------------------------------------------------------------------------------------ runs and boxes
def test_inside_domain_keeps_the_runs_in_the_box_up_to_a_relative_tolerance():
    table = pd.DataFrame({"run": range(1, 8), "a": [0.2, 0.2 - 1e-12, 0.2 - 1e-6, 0.5, 0.8, 0.8 + 5e-11, 0.9],
                          "b": [10.0, 20.0, 30.0, 40.0, 60.0, 50.0, 50.0]})
    domain = pd.DataFrame({"factor": ["a", "b"], "lower": [0.2, 10.0], "upper": [0.8, 50.0]})
    # a: tolerance 1e-9 * 0.6; b: 1e-9 * 40.  Run 5 (b = 60) lies outside b's range, run 7 outside a's
    assert list(inside_domain(table, domain)["run"]) == [1, 2, 4, 6]
    assert list(inside_domain(table, domain, rel_tol=1e-5)["run"]) == [1, 2, 3, 4, 6]
    assert list(inside_domain(table, domain).index) == [0, 1, 2, 3]
    assert inside_domain(table, None) is table


@given(k=st.integers(1, 4), seed=st.integers(0, 10_000), rel_tol=st.sampled_from([0.0, 1e-9, 1e-3]))
@settings(max_examples=40, deadline=None, derandomize=True)
def test_inside_domain_keeps_runs_on_the_box_and_within_its_tolerance_and_drops_the_others(k, seed, rel_tol):
    """Runs on the box's faces (as placed), within the tolerance of them or beyond it, in 1-4 factors of
    different scales and signs: a run is kept exactly when each factor lies in [lower - tol, upper + tol]."""
    rng = np.random.default_rng(seed)
    names = [f"f{i}" for i in range(k)]
    lower = rng.uniform(-50.0, 50.0, k) * 10.0 ** rng.integers(-3, 3, k)
    upper = lower + rng.uniform(0.1, 10.0, k) * np.abs(lower).clip(1e-3)
    tol = rel_tol * (upper - lower)
    # each run's factor at a face, at a face's tolerance, just past it, or inside
    where = rng.integers(0, 7, size=(12, k))
    inner = lower + rng.uniform(0.0, 1.0, (12, k)) * (upper - lower)
    edges = [lower, upper, lower - tol, upper + tol, np.nextafter(lower - tol, -np.inf),
             np.nextafter(upper + tol, np.inf)]
    values = np.where(where == 6, inner, np.choose(np.minimum(where, 5), [np.broadcast_to(e, (12, k)) for e in edges]))
    table = pd.DataFrame(values, columns=names)
    table.insert(0, "run", np.arange(1, 13))
    domain = pd.DataFrame({"factor": names, "lower": lower, "upper": upper})
    expected = [run for run, row in zip(table["run"], values)
                if all(lower[j] - tol[j] <= row[j] <= upper[j] + tol[j] for j in range(k))]
    kept = inside_domain(table, domain, rel_tol=rel_tol)
    assert list(kept["run"]) == expected and list(kept.index) == list(range(len(expected)))


@pytest.mark.parametrize("first_run", [1, 12, 40])
def test_next_wave_runs_number_on_from_the_first_free_run(first_run):
    proposals = pd.DataFrame({"b": [3, 4, 5], "purpose": ["fill"] * 3, "a": [0.1, 0.2, 0.3]}, index=[7, 2, 9])
    frame = next_wave_runs(proposals, ["a", "b"], first_run)
    assert list(frame.columns) == ["run", "a", "b"]
    assert list(frame["run"]) == [first_run, first_run + 1, first_run + 2]
    assert frame["b"].dtype == float and list(frame["b"]) == [3.0, 4.0, 5.0] and list(frame["a"]) == [0.1, 0.2, 0.3]


def _spec(k: int, log: tuple = ()) -> MaterialSpec:
    factors = {f"f{i}": {"lower": 1.0 + i, "upper": 100.0 * (i + 1), **({"scale": "log"} if i in log else {})}
               for i in range(k)}
    material = {"data": "m.csv", "design": {"type": "ccd", "alpha": 1.41421, "center_runs": 3}, "factors": factors,
                "responses": {"y": {"target": 5.0}}, "scenarios": {"s": {"observables": ["y"], "tolerance": 0.05}}}
    return MaterialSpec.from_material("m", validate_schema({"materials": {"m": material}})["materials"]["m"])


@given(k=st.integers(2, 4), log_mask=st.integers(0, 15), seed=st.integers(0, 10_000))
@settings(max_examples=25, deadline=None, derandomize=True)
def test_box_share_is_the_product_of_each_factors_share_in_search_units(k, log_mask, seed):
    log = tuple(i for i in range(k) if log_mask >> i & 1)
    spec = _spec(k, log)
    rng = np.random.default_rng(seed)
    rows, expected = [], 1.0
    for i, f in enumerate(spec.factors):
        u = np.sort(rng.uniform(0.0, 1.0, 2))
        to = (lambda v: math.log10(v)) if i in log else (lambda v: v)
        back = (lambda s: 10 ** s) if i in log else (lambda s: s)
        lo_s, hi_s = to(f.lower), to(f.upper)
        lower, upper = back(lo_s + u[0] * (hi_s - lo_s)), back(lo_s + u[1] * (hi_s - lo_s))
        rows.append({"factor": f.name, "lower": lower, "upper": upper})
        expected *= (to(upper) - to(lower)) / (hi_s - lo_s)
    domain = pd.DataFrame(rows[::-1])  # the box's rows in another order than the factors
    assert box_share(spec, domain) == pytest.approx(expected, rel=1e-9)
    assert box_share(spec, None) == 1.0


# ------------------------------------------------------------------------------------------ next-runs count
def _simulated(k: int, count: int, max_waves: int = 2) -> dict:
    factors = {f"f{i}": {"lower": 0.0, "upper": 1.0} for i in range(k)}
    material = {"design": {"type": "ccd", "alpha": 1.41421, "center_runs": 3},
                "simulation": {"command": "sim {f0}", "runtime_min": 0.05, "retries": 0}, "factors": factors,
                "responses": {"y": {"target": 5.0}}, "scenarios": {"s": {"observables": ["y"], "tolerance": 0.05}},
                "waves": {"max": max_waves, "next_runs": {"count": count}}}
    config = validate_schema({"materials": {"m": material}})
    check_semantics(config)
    return config


@pytest.mark.parametrize("k", [2, 3, 4])
def test_next_runs_count_must_determine_a_quadratic_with_one_degree_of_freedom_to_spare(k):
    needed = math.comb(k + 2, 2) + 1  # 1 + k + k + k(k-1)/2 coefficients, and one more
    check_simulated(_simulated(k, needed))
    with pytest.raises(InputError) as err:
        check_simulated(_simulated(k, needed - 1))
    assert (f"waves.next_runs.count: {needed - 1} runs cannot determine a quadratic in {k} factors" in str(err.value)
            and f"at least {needed}" in str(err.value))



@pytest.mark.parametrize("scenario, known", [("s", True), ("t", True), ("nope", False)])
def test_next_runs_may_name_a_scenario_of_the_material_and_no_other(scenario, known):
    config = _simulated(2, 7)
    material = config["materials"]["m"]
    material["scenarios"]["t"] = {"observables": ["y"], "tolerance": 0.1}
    material["waves"]["next_runs"]["scenario"] = scenario
    if known:
        check_simulated(config)
        return
    with pytest.raises(InputError) as err:
        check_simulated(config)
    assert "waves.next_runs.scenario: unknown scenario 'nope' (known: s, t)" in str(err.value)


def _refusal(edit) -> str:
    config = _simulated(2, 7, max_waves=3)
    edit(config["materials"]["m"])
    with pytest.raises(InputError) as err:
        check_simulated(config)
    return str(err.value)


def test_each_simulated_material_refusal_names_its_key():
    """Every cross-reference check_simulated makes, one line naming the config key (a valid config passes)."""
    check_simulated(_simulated(2, 7, max_waves=3))

    def no_simulation(m):
        del m["simulation"]

    def clash(m):
        m["responses"]["seed"] = {"target": 1.0}

    def own_file(m):
        m["simulation"]["responses_file"] = "log.txt"

    def custom(m):
        m["design"] = {"type": "custom"}

    def old_next_runs(m):
        m["next_runs"] = {"count": 9}

    def no_next_runs(m):
        del m["waves"]["next_runs"]

    assert "config key materials.m.waves: waves need simulation" in _refusal(no_simulation)
    assert "config key materials.m: 'seed' names the simulated table's wave column" in _refusal(clash)
    assert "config key materials.m.simulation.responses_file: 'log.txt' is demid's own file" in _refusal(own_file)
    assert "config key materials.m.design.type: the first wave of a simulated material is its design" in \
        _refusal(custom)
    assert "config key materials.m.next_runs: with waves, each wave's next runs are waves.next_runs" in \
        _refusal(old_next_runs)
    assert "config key materials.m.waves: max 3 needs next_runs" in _refusal(no_next_runs)
    one = _simulated(2, 7, max_waves=1)
    del one["materials"]["m"]["waves"]["next_runs"]
    check_simulated(one)  # a single wave needs no next runs

# ------------------------------------------------------------------------------------------ the summary
def _wave(runs: int, failed: int | None, plausible: float, statistics: pd.DataFrame, domain=None) -> dict:
    table = pd.DataFrame({"run": range(1, runs + 1)})
    if failed is not None:
        table["status"] = ["failed"] * failed + ["ok"] * (runs - failed)
    plausible = pd.DataFrame({"scenario": ["s", "s", "other", "other"], "factor": ["f0", "f1", "f0", "f1"],
                           "robust_fraction_pct": [plausible, plausible, 99.0, 99.0],
                           "robust_lower": [1.5, 2.5, 1.0, 2.0], "robust_upper": [40.0, 90.0, 100.0, 200.0]})
    return {"table": table, "analysed": table.head(runs - (failed or 0)), "domain": domain, "plausible": plausible,
            "statistics": statistics}


def test_the_wave_summary_counts_runs_and_reads_the_refocus_scenarios_share_and_intervals():
    spec = _spec(2)
    stats = pd.DataFrame({"response": ["y"], "q2": [0.93], "surrogate": ["quadratic"]})
    empty = pd.DataFrame({"response": [], "q2": [], "surrogate": []})
    box = pd.DataFrame({"factor": ["f0", "f1"], "lower": [2.0, 3.0], "upper": [50.0, 100.0]})
    decision = {"stop": True, "action": "stop", "reason": "r"}
    summary = wave_summary(spec, [_wave(11, None, 12.5, stats), _wave(18, 3, 4.25, empty, box)], decision)
    assert summary["material"] == "m" and summary["decision"] == decision
    first, second = summary["waves"]
    assert (first["wave"], first["simulated"], first["failed"], first["analysed"]) == (1, 11, 0, 11)
    assert (second["wave"], second["simulated"], second["failed"], second["analysed"]) == (2, 18, 3, 15)
    assert first["surrogate"] == "y by the quadratic (Q² 0.93)" and second["surrogate"] == "quadratic"
    assert first["q2"] == {"y": 0.93} and second["q2"] == {}
    assert first["scenario"] == second["scenario"] == "s"
    assert (first["plausible_fraction_of_omega_pct"], second["plausible_fraction_of_omega_pct"]) == (12.5, 4.25)
    assert first["plausible"] == {"f0": [1.5, 40.0], "f1": [2.5, 90.0]}


def _two_scenario_spec(**extra) -> MaterialSpec:
    material = {"data": "m.csv", "design": {"type": "ccd", "alpha": 1.41421, "center_runs": 3},
                "factors": {"a": {"lower": 0.0, "upper": 1.0}, "b": {"lower": 1.0, "upper": 11.0}},
                "responses": {"y1": {"target": 5.0}, "y2": {"target": 7.0}, "y3": {"target": 9.0}},
                "scenarios": {"one": {"observables": ["y1"], "tolerance": 0.05},
                              "two": {"observables": ["y1", "y2"], "tolerance": 0.05}},
                "waves": {"max": 3, "stop_early": True, "next_runs": {"count": 9}}, **extra}
    return MaterialSpec.from_material("m", validate_schema({"materials": {"m": material}})["materials"]["m"])


@pytest.mark.parametrize("previous, feasible", [(None, True), ({"plausible_fraction_of_omega_pct": 3.5}, False),
                                                ({}, None)])
def test_wave_evidence_reads_the_refocus_scenarios_share_its_surrogates_and_the_criticisms_runs(previous, feasible):
    from demid.run_purposes import CONFIRM, DECIDE

    spec = _two_scenario_spec()
    plausible = pd.DataFrame({"scenario": ["one", "one", "two", "two"], "factor": ["a", "b"] * 2,
                           "robust_fraction_pct": [40.0, 40.0, 6.25, 6.25]})
    statistics = pd.DataFrame({"response": ["y3", "y2", "y1"], "q2": [0.1, 0.8, 0.95], "lof_p": [0.5, 0.01, 0.3],
                               "n_runs": [13, 13, 13], "press": [1.0, 13 * 0.35 ** 2, 13 * 0.05 ** 2]})
    runs = pd.DataFrame({"a": np.arange(7) / 10, "purpose": [CONFIRM, "fill", DECIDE, DECIDE, "fill", "x", CONFIRM]})
    criticism = {"level2": {"feasible": feasible}} if feasible is not None else {}
    ev = wave_evidence(spec, 2, None, plausible, statistics, criticism, previous, runs)
    assert (ev.wave, ev.max_waves, ev.plausible_pct) == (2, 3, 6.25)  # the scenario with the most observables
    assert ev.previous_pct == (None if previous is None else previous.get("plausible_fraction_of_omega_pct"))
    # the leave-one-out error sqrt(PRESS / n) against the band 0.05 x |target|: y1 0.05 / 0.25, y2 0.35 / 0.35
    assert ev.surrogates == {"y1": {"q2": 0.95, "lof_p": 0.3, "loo_band": pytest.approx(0.2)},
                             "y2": {"q2": 0.8, "lof_p": 0.01, "loo_band": pytest.approx(1.0)}}
    # level 2's "no parameter set meets every target" stops the waves only where the plausible set is empty too
    assert ev.model_limit is False
    empty = plausible.assign(robust_fraction_pct=[40.0, 40.0, 0.0, 0.0])
    assert wave_evidence(spec, 2, None, empty, statistics, criticism, previous, runs).model_limit is (feasible is False)
    assert (ev.proposed, ev.criticism_runs) == (7, 4)
    none = wave_evidence(spec, 1, None, plausible[plausible["scenario"] == "one"], statistics, {}, None, runs.iloc[0:0])
    assert (none.plausible_pct, none.proposed, none.criticism_runs) == (0.0, 0, 0)  # the refocus set has no row
    assert waves_max(spec) == 3 and stops_early(spec) is True


def test_a_waves_material_entry_is_the_table_over_omega_and_after_a_box_a_custom_design():
    material = {"data": "old.csv", "simulation": {"command": "x"}, "design": {"type": "ccd", "alpha": 1.41421},
                "responses": {"y": {"target": 1.0, "published": {"r2": 0.9}}}, "confirmed_values": {"x": 1},
                "waves": {"max": 2, "next_runs": {"count": 9, "scenario": "s"}}}
    first = wave_material(material, "waves/1.csv")
    assert first["data"] == "waves/1.csv" and first["next_runs"] == {"count": 9, "scenario": "s"}
    assert "simulation" not in first and "waves" not in first and first["design"]["type"] == "ccd"
    assert first["responses"]["y"]["published"] == {"r2": 0.9} and first["confirmed_values"] == {"x": 1}
    later = wave_material(material, "waves/2.csv", pd.DataFrame({"factor": ["a"], "lower": [0.1], "upper": [0.2]}))
    assert later["design"] == {"type": "custom"} and "published" not in later["responses"]["y"]
    assert "confirmed_values" not in later
    assert material["responses"]["y"]["published"] == {"r2": 0.9} and "waves" in material  # the input is kept



@given(waves=st.integers(1, 3), seed=st.integers(0, 10_000), log_b=st.booleans())
@settings(max_examples=10, deadline=None, derandomize=True)
def test_the_wave_history_reads_each_waves_sets_runs_and_box(waves, seed, log_b):
    """Per wave, scenario and factor: the set's fraction and span as the wave's scenarios table gives them, the
    runs simulated and analysed, the box the wave's runs were placed in (Ω for wave 1) and its share of Ω in
    search units (log10 for a log factor)."""
    from demid.waves import HISTORY_COLUMNS, wave_history

    rng = np.random.default_rng(seed)
    material = {"data": "x.csv", "design": {"type": "ccd", "alpha": 1.41421, "center_runs": 3},
                "factors": {"a": {"lower": -2.0, "upper": 6.0},
                            "b": {"lower": 0.1, "upper": 100.0, **({"scale": "log"} if log_b else {})}},
                "responses": {"y": {"target": 5.0}, "z": {"target": -3.0}},
                "scenarios": {"s": {"observables": ["y"], "tolerance": 0.05},
                              "t": {"observables": ["y", "z"], "tolerance": 0.1}}}
    spec = MaterialSpec.from_material("m", material)
    given_waves, expected = [], []
    for number in range(1, waves + 1):
        scenarios = pd.DataFrame([{"scenario": sc, "factor": f, "feasible_fraction_pct": frac,
                                   "lower": lo, "upper": lo + w, "width": w}
                                  for sc, frac in (("s", rng.uniform(0, 50)), ("t", rng.uniform(0, 50)))
                                  for f, lo, w in (("a", rng.uniform(-2, 2), rng.uniform(0, 4)),
                                                   ("b", rng.uniform(0.1, 1), rng.uniform(0, 99)))])
        if number == 1:
            domain, box, share = None, {"a": (-2.0, 6.0), "b": (0.1, 100.0)}, 1.0
        else:
            a0, b0 = rng.uniform(-2, 2), rng.uniform(0.1, 10)
            box = {"a": (a0, a0 + rng.uniform(0.5, 4)), "b": (b0, b0 * rng.uniform(1.5, 9))}
            domain = pd.DataFrame([{"factor": f, "lower": lo, "upper": hi} for f, (lo, hi) in box.items()])
            share_b = (np.log10(box["b"][1] / box["b"][0]) / 3.0 if log_b else
                       (box["b"][1] - box["b"][0]) / 99.9)
            share = (box["a"][1] - box["a"][0]) / 8.0 * share_b
        simulated, analysed = 11 + 9 * (number - 1), 11 + rng.integers(0, 9 * number)
        given_waves.append({"scenarios": scenarios, "domain": domain, "simulated": simulated, "analysed": analysed})
        for row in scenarios.itertuples():
            expected.append(["m", number, simulated, analysed, row.scenario, row.feasible_fraction_pct, row.factor,
                             row.lower, row.upper, row.width, box[row.factor][0], box[row.factor][1], 100 * share,
                             np.nan, np.nan, np.nan])  # no plausible frames given: none made up
    history = wave_history(spec, given_waves)
    assert list(history.columns) == HISTORY_COLUMNS
    assert len(history) == len(expected)
    for got, want in zip(history.itertuples(index=False), expected):
        assert list(got[:5]) == want[:5] and got[6] == want[6]
        assert np.allclose([got[5], *got[7:]], [want[5], *want[7:]], rtol=1e-12, atol=0.0, equal_nan=True)

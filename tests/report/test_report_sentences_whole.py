"""The report's sentences read back number by number: the summary's recommended point and its intervals, which
factors it calls wide or not pinned down, a curved band's values, the criticism's level-2 and reference-point
lines, the ranking's gains and the waves table, each against values computed here from the results tree written
for the test (two to four factors, gains and losses, errors above and below their targets)."""

from __future__ import annotations

import html
import json
import math
import re

import numpy as np
import pandas as pd
import pytest

from demid.report.context import ReportContext
from demid.report.model_criticism import criticism_lines, _reference_point_lines
from demid.report.plausible import ranking_display
from demid.report.summary import combination_lines
from demid.spec import MaterialSpec

LABELS = ["Alpha", "Beta", "Gamma", "Delta"]  # no "_": a label's subscript is typeset
VERDICTS = ["identified", "bounded", "unresolved", "cut by the search range (upper bound)"]


def _material(d: int, observables=("y", "z")) -> dict:
    factors = {k: {"lower": 0.0, "upper": 1.0 + i, "label": LABELS[i]} for i, k in enumerate("abcd"[:d])}
    responses = {o: {"target": 0.5 + i, "label": f"{o.upper()}obs"} for i, o in enumerate(observables)}
    return {"data": "x.csv", "design": {"type": "ccd", "alpha": 1.41421, "center_runs": 3},
            "factors": factors, "responses": responses,
            "scenarios": {"s": {"observables": list(observables), "tolerance": 0.02, "label": "Both"},
                          "t": {"observables": [observables[0]], "tolerance": 0.05, "label": "First alone"}}}


def _spec(material: dict) -> MaterialSpec:
    return MaterialSpec.from_material("m", material, grid_points=21)


def _text(parts) -> str:
    return html.unescape(re.sub(r"<[^>]+>", "", "".join(p.data for p in parts)))


def _assert_fraction_change_first_to_last(text: str, scenarios: list[str], fractions: dict) -> None:
    """The uncertainty section's line on the change from the first scenario to the last, each percentage (strict,
    plausible) parsed back against ``fractions[scenario] = (strict, plausible)``, to the 0.1 % it is printed to."""
    labels = {"s": "Both", "t": "First alone", "u": "Second alone"}
    m = re.search(rf"From {labels[scenarios[0]]} to {labels[scenarios[-1]]} the feasible fraction changes by (\S+) % "
                  r"\(strict\) and (\S+) % \(plausible\)\.", text)
    assert m, text
    for quoted, k in zip(m.groups(), (0, 1)):
        first, last = fractions[scenarios[0]][k], fractions[scenarios[-1]][k]
        assert _number(quoted) == pytest.approx(100 * (last - first) / first, abs=0.05 + 1e-9)


def _cells(parts) -> list[list[str]]:
    """The body rows of the tables in rendered report parts, each a list of cell texts."""
    page = "".join(p.data for p in parts)
    rows = re.findall(r"<tr>(.*?)</tr>", page, re.S)
    return [[html.unescape(re.sub(r"<[^>]+>", "", c)).strip() for c in re.findall(r"<td[^>]*>(.*?)</td>", r, re.S)]
            for r in rows if "<td" in r]


def _write(root, rel: str, content) -> None:
    path = root / rel
    path.parent.mkdir(parents=True, exist_ok=True)
    if isinstance(content, pd.DataFrame):
        content.to_csv(path, index=False)
    else:
        path.write_text(json.dumps(content), encoding="utf-8")


def _number(text: str) -> float:
    return float(text.replace("−", "-"))  # the report writes a minus sign, not a hyphen


def _decimals(text: str) -> int:
    return len(text.split(".")[1]) if "." in text else 0


# --------------------------------------------------------------------------- the summary's recommended point
@pytest.mark.parametrize("seed", range(6))
def test_the_recommended_point_is_quoted_with_its_intervals_and_the_factors_it_does_not_pin_down(tmp_path, seed):
    from demid.report.summary import summary

    rng = np.random.default_rng(seed)
    d = 2 + seed % 3
    material = _material(d)
    spec = _spec(material)
    names = spec.factor_names
    verdicts = [VERDICTS[int(k)] for k in rng.integers(0, 4, d)]
    if seed >= 4:  # several factors not pinned down, one bounded among them
        verdicts = ["unresolved"] * d
        verdicts[1] = "bounded"
    rows, point = [], {}
    for i, f in enumerate(names):
        upper = 1.0 + i
        lo, hi = np.sort(rng.uniform(0, upper, 2))
        lo, hi = (0.0, upper) if verdicts[i] == "unresolved" else (lo, hi)
        point[f] = float(rng.uniform(lo, hi))
        strict = (np.nan, np.nan) if seed == 3 else (lo, hi)  # one study whose strict set is empty
        rows.append({"material": "m", "scenario": "s", "factor": f, "strict_lower": strict[0], "strict_upper": strict[1],
                     "plausible_lower": lo, "plausible_upper": hi, "verdict": verdicts[i], "reason": "why"})
    implausibility = float(rng.uniform(0.05, 0.99))
    _write(tmp_path, "tables/verdicts.csv", pd.DataFrame(rows))
    advice = [("widen", "Widen the upper end.", seed % 2 == 0), ("add_observable", "Measure a new kind.", seed % 2 == 1),
              ("measurement_order", "Measure Y first.", False)]
    _write(tmp_path, "tables/advice.csv", pd.DataFrame([{"material": "m", "kind": k, "factor": "", "bound": "",
                                                         "observable": "", "text": t, "decision": d}
                                                        for k, t, d in advice]))
    _write(tmp_path, "uncertainty/m.json", {"recommended": {"scenario": "s", "plausible": True, "point": point,
                                                            "implausibility": implausibility},
                                            "uninformative": {"z": f"its band covers {seed} of its range"}})
    combination = f"a band along {names[-1]} {seed}."  # the combinations step's own text, shown as written
    _write(tmp_path, "combinations/m.json", {"sets": [{"scenario": "t", "set": "strict", "text": combination}]})
    text = _text(summary(ReportContext(str(tmp_path), {"materials": {"m": material}})))
    assert "How to read it. Per factor and observable scenario the plausible interval is judged" in text
    assert f"First alone, strict set: a band along {names[-1]} {seed}." in text
    found = re.search(r"Recommended parameter set \(the point of the plausible set of Both with the largest margin "
                      r"to every band, implausibility (\S+)\): (.+?)\.(?: |$)", text, re.M)
    assert found, text
    assert float(found.group(1)) == pytest.approx(implausibility, abs=0.005 + 1e-12)
    quoted = found.group(2).split("; ")
    assert len(quoted) == d
    for row, shown, label in zip(rows, quoted, LABELS):
        m = re.fullmatch(rf"{label} = (\S+) \(plausible (\S+)–(\S+)\)", shown)
        assert m, shown
        width = row["plausible_upper"] - row["plausible_lower"]
        places = max(0, 1 - math.floor(math.log10(width)))  # a tenth of the interval's width
        for value, exact in zip(m.groups(), (point[row["factor"]], row["plausible_lower"], row["plausible_upper"])):
            assert _decimals(value) == places and abs(float(value) - exact) <= 0.5 * 10 ** -places + 1e-12
    wide = [LABELS[i] for i in range(d) if verdicts[i] != "identified"]
    if wide:
        assert f"The plausible set is wide in {', '.join(wide)}: any point" in text
    else:
        assert "The plausible set is wide" not in text
    loose = [LABELS[i] for i in range(d) if verdicts[i] == "unresolved"]
    if loose:
        listed = loose[0] if len(loose) == 1 else ", ".join(loose[:-1]) + " and " + loose[-1]
        assert (f"*Both* does not pin down {listed}: its plausible set spans (almost) the whole search range of "
                f"{'it' if len(loose) == 1 else 'each'}.").replace("*", "") in text
    else:
        assert "does not pin down" not in text
    # the answer line: scenario "s" has the most observables
    identified = [LABELS[i] for i in range(d) if verdicts[i] == "identified"]
    others = [f"{LABELS[i]} {verdicts[i]}" for i in range(d) if verdicts[i] != "identified"]
    assert (f"{spec.label}, with Both: identified: {', '.join(identified) or 'none'}; not identified: "
            f"{', '.join(others) or 'none'}.") in text
    decision, also = ("Widen the upper end.", "Measure a new kind.")[:: 1 if seed % 2 == 0 else -1]
    lines = text.split("\n")
    assert f"Next step: {decision}" in text and lines[lines.index("Next step:") + 2] == decision
    assert lines[lines.index("Also:") + 2] == also and "Measure Y first." not in text
    assert f"Zobs is an uninformative observable: its band covers {seed} of its range." in text
    empty = "With every observable of Both no point of the search range is admissible, so there are no admissible " \
            "intervals."
    assert (empty in text) == (seed == 3)


def test_with_no_plausible_point_the_summary_names_the_closest_point_and_theobservables(tmp_path):
    from demid.report.summary import summary

    material = _material(3)
    best = {"a": 0.123456, "b": 1.98765, "c": 0.5}
    _write(tmp_path, "uncertainty/m.json", {"recommended": {"scenario": "s", "plausible": False, "point": best,
                                                            "implausibility": 3.14159}})
    _write(tmp_path, "criticism/m.json", {"level1": {}, "level2": {"observables": ["z", "y"], "best_point": best,
                                                                   "feasible": False, "tolerance": 0.02,
                                                                   "best_errors": {"y": 0.05, "z": -0.08},
                                                                   "best_max_error": 0.08}})
    text = _text(summary(ReportContext(str(tmp_path), {"materials": {"m": material}})))
    assert "(smallest implausibility 3.14 > 1)" in text
    assert ("The closest point (smallest largest relative error over Zobs, Yobs) is Alpha = 0.1235, Beta = 1.988, "
            "Gamma = 0.5;") in text


# --------------------------------------------------------------------------- a curved band's values
@pytest.mark.parametrize("seed", range(3))
def test_a_curved_band_prints_each_point_as_along_to_mid_with_lowest_and_highest(seed):
    rng = np.random.default_rng(seed)
    spec = _spec(_material(2 + seed))
    k = 3 + seed
    along = np.sort(rng.uniform(0, 1, k))
    lower = rng.uniform(0, 1, k)
    mid = lower + rng.uniform(0.01, 0.5, k)
    upper = mid + rng.uniform(0.01, 0.5, k)
    curve = {"along": "a", "across": spec.factor_names[-1], "along_actual": list(along), "lower": list(lower),
             "mid": list(mid), "upper": list(upper)}
    entries = [{"scenario": "t", "set": "plausible", "identified": True, "text": "a curved band.", "curve": curve},
               {"scenario": "s", "set": "strict", "identified": False, "text": "a curved band.", "curve": curve},
               {"scenario": "s", "set": "plausible", "identified": True, "text": "a straight band.", "curve": curve},
               {"scenario": "gone", "set": "strict", "identified": True, "text": "a curved band."}]
    first, second, third, fourth = combination_lines({"sets": entries}, spec)
    # the curve only where the set is identified and its text tells of a curved band
    assert (second, third, fourth) == ("*Both*, strict set: a curved band.", "*Both*, plausible set: a straight band.",
                                       "*gone*, strict set: a curved band.")
    head = f"*First alone*, plausible set: a curved band. Curve (Alpha → {LABELS[len(spec.factor_names) - 1]} mid " \
           "[lowest, highest]): "
    assert first.startswith(head) and first.endswith(".")
    pairs = first[len(head):-1].split("; ")
    assert len(pairs) == k
    for pair, values in zip(pairs, zip(along, mid, lower, upper)):
        m = re.fullmatch(r"(\S+) → (\S+) \[(\S+), (\S+)\]", pair)
        assert m and np.allclose([float(v) for v in m.groups()], values, rtol=5e-3)


# --------------------------------------------------------------------------- the criticism's level-2 lines
def _level2(rng, observables, own: bool, feasible: bool) -> dict:
    errors = {o: float(rng.uniform(0.001, 0.2) * rng.choice([-1, 1])) for o in observables}
    tolerances = {o: (float(rng.choice([0.004, 0.03, 0.1])) if own else 0.02) for o in observables}
    if own:
        tolerances[observables[0]] = 0.002
    ref = float(rng.uniform(0.001, 0.2))
    return {"tolerance": 0.02, "tolerances": tolerances, "observables": list(observables), "feasible": feasible,
            "best_errors": errors, "best_max_error": max(abs(e) for e in errors.values()),
            "bottleneck": None if feasible else observables[-1], "reference_max_error": ref,
            "reference_within": bool(rng.integers(0, 2)), "extrapolation": []}


@pytest.mark.parametrize("seed", range(8))
def test_level2_lines_quote_the_best_points_miss_and_the_reference_points_error(seed):
    from demid.precision import percent_text

    rng = np.random.default_rng(seed)
    observables = ["y", "z", "w"][: 2 + seed % 2]
    material = _material(2, tuple(observables))
    spec = _spec(material)
    own, feasible = bool(seed % 4 >= 2), bool(seed % 2)
    level2 = _level2(rng, observables, own, feasible)
    lines = criticism_lines({"level1": {}, "level2": level2}, spec)
    line = next(x for x in lines if x.startswith("Simulation vs experiment"))
    errors, tol = level2["best_errors"], level2["tolerances"]
    if own:
        worst = max(observables, key=lambda o: abs(errors[o]) / tol[o])
        ratio = abs(errors[worst]) / tol[worst]
        m = re.search(rf"misses {worst.upper()}obs by (\S+) % \((\S+) times its tolerance of (\S+) %\)", line)
        assert m, line
        assert float(m.group(1)) == pytest.approx(100 * abs(errors[worst]), rel=0.01)
        assert float(m.group(2)) == pytest.approx(ratio, rel=0.03)
        assert float(m.group(3)) == pytest.approx(100 * tol[worst])
    else:
        miss = "by at most " if feasible else "by "
        assert f"misses {miss}{percent_text(level2['best_max_error'])}" in line
        assert "within 2 %" in line
    assert ("every target can be met" in line) == feasible
    assert (f"limited by {observables[-1].upper()}obs." in line) == (not feasible)
    ref = next(x for x in lines if x.startswith("Reference point"))
    m = re.fullmatch(r"Reference point: largest error (\S+) % \((within|outside) (.+)\)\.", ref)
    assert m, ref
    assert float(m.group(1)) == pytest.approx(100 * level2["reference_max_error"], rel=0.01)
    assert m.group(2) == ("within" if level2["reference_within"] else "outside")
    # each own tolerance in the config's order, two decimals below 10 % and one from there
    listed = ", ".join(f"{o.upper()}obs {100 * tol[o]:.{2 if tol[o] < 0.1 else 1}f} %" for o in observables)
    assert m.group(3) == (f"their own tolerances: {listed}" if own else "the 2 % tolerance")


@pytest.mark.parametrize("seed", range(4))
def test_the_reference_point_lines_keep_each_errors_sign_and_the_distance(tmp_path, seed):
    rng = np.random.default_rng(seed)
    material = _material(2 + seed % 3)
    spec = _spec(material)
    positions = []
    for sc, inside in (("s", False), ("t", bool(seed % 2))):
        errors = {o: float(rng.uniform(0.0005, 0.3) * rng.choice([-1, 1])) for o in ("y", "z")}
        nearest = {f: float(rng.uniform(0, 2)) for f in spec.factor_names}
        positions.append({"scenario": sc, "inside": inside, "errors": errors, "nearest_admissible": nearest,
                          "distance_pct_of_range": float(rng.uniform(0.5, 40))})
    lines = _reference_point_lines(ReportContext(str(tmp_path), {"materials": {"m": material}}), "m", positions)
    assert len(lines) == 2
    for line, pos in zip(lines, positions):
        quoted = re.search(r"\(errors (.+)\)\.$", line).group(1).split(", ")
        for text, (o, e) in zip(quoted, pos["errors"].items()):
            m = re.fullmatch(rf"{o.upper()}obs ([+−]?\S+) %", text)
            assert m and _number(m.group(1)) == pytest.approx(100 * e, rel=0.01), text
        if pos["inside"]:
            assert "lies inside the admissible set" in line
        else:
            m = re.search(r"lies outside it, (\S+) % of the search range from the nearest admissible point \(([^()]+)\)",
                          line)
            assert m and float(m.group(1)) == pytest.approx(pos["distance_pct_of_range"], abs=0.05 + 1e-9)
            for shown, (f, v), label in zip(m.group(2).split(", "), pos["nearest_admissible"].items(), LABELS):
                name, value = shown.split(" = ")
                assert name == label and float(value) == pytest.approx(v, rel=5e-4)


# --------------------------------------------------------------------------- the observable ranking
@pytest.mark.parametrize("seed", range(3))
def test_the_ranking_quotes_an_uninformativeobservables_own_gain(seed):
    rng = np.random.default_rng(seed)
    sets = ["y", "z", "y+z", "w"][: 2 + seed]
    ranking = pd.DataFrame({"material": "m", "rank": range(1, len(sets) + 1), "observables": sets,
                            "information_gain_bits": rng.uniform(0.01, 4, len(sets)),
                            "gain_vs_best_subset_bits": rng.uniform(0.01, 4, len(sets)),
                            "best_subset": ["(none)"] * len(sets), "nobservables": [s.count("+") + 1 for s in sets]})
    quiet = {sets[-1]: "its band covers its whole simulated range"}
    shown = ranking_display(ranking, quiet)
    gains = shown["information gain [bit]"]
    for i, s in enumerate(sets):
        own = ranking["information_gain_bits"].iloc[i]
        if s in quiet:
            assert gains.iloc[i] == f"~0 ({own:.2f}; uninformative)"
        else:
            assert float(gains.iloc[i]) == pytest.approx(own)
    assert list(shown["best smaller set"]) == ["–"] * len(sets)


def _ranking(rng, sets, reachable) -> pd.DataFrame:
    n = len(sets)
    return pd.DataFrame({"material": "m", "rank": range(1, n + 1), "observables": sets,
                         "information_gain_bits": rng.uniform(0.1, 4, n), "gain_vs_best_subset_bits": rng.uniform(0, 2, n),
                         "best_subset": ["(none)"] * n, "n_observables": [s.count("+") + 1 for s in sets],
                         "feasible_fraction_pct": rng.uniform(1, 50, n), "targets_reachable": reachable})


@pytest.mark.parametrize("seed", range(4))
def test_the_uncertainty_section_quotes_the_change_from_first_to_last_scenario_and_the_ranking(tmp_path, seed):
    from demid.report.plausible import uncertainty

    rng = np.random.default_rng(seed)
    material = _material(2)
    material["scenarios"]["u"] = {"observables": ["z"], "tolerance": 0.1, "label": "Second alone"}
    scenarios = ["s", "t", "u"][: 2 + seed % 2]
    fractions = {sc: (float(rng.uniform(1, 60)), float(rng.uniform(1, 60))) for sc in scenarios}
    rows = [{"material": "m", "scenario": sc, "observables": "y", "tolerance": 0.02, "z": 2, "factor": f,
             "strict_fraction_pct": fractions[sc][0], "robust_fraction_pct": fractions[sc][1], "strict_width": 0.1,
             "robust_width": 0.2} for sc in scenarios for f in ("a", "b")]
    _write(tmp_path, "tables/robust_identifiability.csv", pd.DataFrame(rows))
    reachable = [True, True, seed % 2 == 0]
    _write(tmp_path, "tables/observable_ranking.csv", _ranking(rng, ["y", "z", "y+z"], reachable))
    walk = "Measure Y first, then Z."
    _write(tmp_path, "tables/advice.csv", pd.DataFrame([{"material": "m", "kind": "measurement_order", "factor": "",
                                                         "bound": "", "observable": "", "text": walk,
                                                         "decision": False}]))
    _write(tmp_path, "uncertainty/m.json", {"notes": ["a note on y"]})
    text = _text(uncertainty(ReportContext(str(tmp_path), {"materials": {"m": material}}), "m"))
    _assert_fraction_change_first_to_last(text, scenarios, fractions)
    assert ("sets whose targets cannot be met" in text) == (not all(reachable))
    assert ("targets reachable" in text) == (not all(reachable))
    assert "not information." in text or "beyond the best set without it." in text
    assert walk in text and "Yobs" in text and "a note on Yobs" in text
    assert "Strict vs plausible admissible sets. x is plausible when" in text


# --------------------------------------------------------------------------- the simulation loop
def test_the_next_wave_section_gives_the_reason_the_advice_and_each_run_in_labels(tmp_path):
    from demid.report.loop import next_wave

    material = _material(3)
    runs = pd.DataFrame({"material": ["m", "m", "other"], "proposal": [1, 2, 1], "a": [0.123456, 0.9, 0.5],
                         "b": [1.5, 0.25, 0.5], "c": [2.75, 0.0, 0.5], "purpose": ["decide", "cover", "x"]})
    _write(tmp_path, "tables/next_runs.csv", runs)
    _write(tmp_path, "next_wave/reasons.json", {"m": "The set is wide in b."})
    _write(tmp_path, "tables/advice.csv", pd.DataFrame([{"material": "m", "kind": "next_runs", "factor": "",
                                                         "bound": "", "observable": "", "text": "Run the 2 runs.",
                                                         "decision": True}]))
    parts = next_wave(ReportContext(str(tmp_path), {"materials": {"m": material}}), "m")
    text = _text(parts)
    assert "What to simulate next" in text and "The set is wide in Beta. Run the 2 runs." in text
    assert all(label in text for label in LABELS[:3]) and "other" not in text
    table = _cells(parts)
    assert len(table) == 2
    for cells, (_, run) in zip(table, runs[runs["material"] == "m"].iterrows()):
        assert int(cells[0]) == run["proposal"] and cells[-1] == run["purpose"]
        for cell, f in zip(cells[1:4], "abc"):  # each coordinate to the precision of its factor's range
            span = material["factors"][f]["upper"] - material["factors"][f]["lower"]
            assert abs(float(cell) - run[f]) <= 1e-3 * span


@pytest.mark.parametrize("seed", range(3))
def test_the_waves_table_has_each_waves_counts_q2_and_intervals(tmp_path, seed):
    from demid.report.loop import waves

    rng = np.random.default_rng(seed)
    material = _material(2 + seed)
    names = list(material["factors"])
    simulated = np.cumsum(rng.integers(5, 12, 2 + seed))
    failed = np.maximum.accumulate(rng.integers(0, 4, len(simulated)))  # counted up to each wave
    rows = []
    for w, (n, k) in enumerate(zip(simulated, failed), start=1):
        plausible = {f: sorted(rng.uniform(0, 1, 2).tolist()) for f in names}
        plausible[names[-1]] = [None, None] if w == 1 else plausible[names[-1]]
        rows.append({"wave": w, "scenario": "s", "simulated": int(n), "failed": int(k), "analysed": int(n - k),
                     "surrogate": "quadratic", "q2": {"y": float(rng.uniform(0.3, 0.99)), "z": float(rng.uniform(-1, 1))},
                     "plausible_fraction_of_omega_pct": float(rng.uniform(0.1, 30)), "plausible": plausible})
    _write(tmp_path, "waves/summary_m.json", {"waves": rows})
    parts = waves(ReportContext(str(tmp_path), {"materials": {"m": material}}), "m")
    assert (f"demid simulated {simulated[-1]} runs in {len(rows)} waves ({failed[-1]} failed)") in _text(parts)
    table = _cells(parts)
    assert len(table) == len(rows)
    for row, cells in zip(rows, table):
        counts = [row["wave"], row["simulated"], row["failed"], row["analysed"]]
        assert [int(c) for c in cells[:4]] == counts and cells[4] == "quadratic"
        assert cells[5] == ", ".join(f"{o.upper()}obs {q:.2f}" for o, q in row["q2"].items())
        assert float(cells[6]) == pytest.approx(row["plausible_fraction_of_omega_pct"], rel=5e-3)
        assert cells[7:] == [f"{lo:.4g}–{hi:.4g}" if lo is not None else "empty" for lo, hi in row["plausible"].values()]


def test_level1_lines_give_each_response_its_verdict_or_its_findings_in_config_order():
    spec = _spec(_material(2, ("y", "z", "w")))
    level1 = {"w": {"verdict": "adequate", "messages": [], "verdict_message": ""},
              "z": {"verdict": "defect", "messages": ["z: run 4 does not fit.", "z: a drift."], "verdict_message": ""},
              "y": {"verdict": "ambiguous", "messages": ["y: m1"], "verdict_message": "y: ambiguous — two causes."}}
    lines = criticism_lines({"level1": level1}, spec)
    assert lines == ["Surrogate of Yobs — **ambiguous cause**: two causes.",
                     "Surrogate of Zobs: Zobs: run 4 does not fit. Zobs: a drift.",
                     "Surrogate of Wobs: no defect found — the quadratic fits the simulation runs."]


@pytest.mark.parametrize("bad", [(), ("y",), ("z",), ("y", "z")])
def test_a_surrogate_that_does_not_predict_is_named_in_every_scenario_and_front_that_uses_it(bad):
    from demid.report.model_criticism import unreliable_surrogate_lines

    material = _material(2)
    material["pareto"] = {"error_of": "z", "minimise": "z", "max_error": 0.05}
    spec = _spec(material)
    level1 = {o: {"verdict": "does_not_predict" if o in bad else "adequate"} for o in ("y", "z")}
    lines = unreliable_surrogate_lines({"level1": level1}, spec)
    expected = []
    for label, observables in (("Both", ["y", "z"]), ("First alone", ["y"])):
        used = [o for o in observables if o in bad]
        if used:
            expected.append(f"⚠ Scenario *{label}* uses {', '.join(o.upper() + 'obs' for o in used)}, whose surrogate "
                            "does not predict left-out runs (Q² < 0): its admissible set should not be used to decide "
                            "admissibility.")
    if "z" in bad:
        expected.append("⚠ The Pareto front uses Zobs, whose surrogate does not predict left-out runs (Q² < 0): treat "
                        "the front as indicative only.")
    assert lines == expected


def test_the_criticism_section_tables_the_named_causes_of_its_material_only(tmp_path):
    from demid.report.model_criticism import criticism

    material = _material(2)
    _write(tmp_path, "criticism/m.json", {"level1": {"z": {"verdict": "defect", "messages": ["z: a drift."]},
                                                     "y": {"verdict": "adequate", "messages": []}}})
    findings = pd.DataFrame({"material": ["m", "m", "other"], "response": ["z", "y", "z"],
                             "cause": ["drift", "none", "missing_term;outlier"], "detail": ["run order", "", "x"],
                             "p_value": [0.0123, 1.0, 0.5], "loo_rmse_baseline": [2.5, 1.0, 1.0],
                             "loo_rmse_extended": [1.25, 1.0, 1.0], "delta_aicc": [-7.5, 0.0, 0.0]})
    _write(tmp_path, "tables/criticism.csv", findings)
    text = _text(criticism(ReportContext(str(tmp_path), {"materials": {"m": material}}), "m"))
    lines = [c.strip() for c in text.split("\n") if c.strip()]
    assert "Yobs: nothing found by the catalogue tests." in lines and "Zobs: Zobs: a drift." in lines
    assert text.index("Yobs: nothing found") < text.index("Zobs: Zobs: a drift.")  # the config's order
    assert "drift" in lines and "run order" in lines and "2.5" in lines and "1.25" in lines and "-7.5" in lines
    assert "missing term, outlier" not in text and "none" not in lines


def test_the_criticism_section_gives_level2_with_its_advice_and_the_run_order_line(tmp_path):
    from demid.report.model_criticism import criticism

    material = _material(2)
    run_order = {"drift_tested": False, "message": "the runs carry no run order."}
    level2 = {"finding": "z misses its target.", "tolerance": 0.02, "best_errors": {"y": 0.01}, "best_max_error": 0.01,
              "feasible": True}
    info = {"level1": {"y": {"verdict": "adequate", "messages": []}}, "run_order": run_order, "level2": level2}
    _write(tmp_path, "criticism/m.json", info)
    kinds = [("widen", "Widen b."), ("recalibrate", "Refit y."), ("next_runs", "Run more."), ("stop", "Stop.")]
    _write(tmp_path, "tables/advice.csv", pd.DataFrame([{"material": "m", "kind": k, "factor": "", "bound": "",
                                                         "observable": "", "text": t, "decision": False}
                                                        for k, t in kinds]))
    text = _text(criticism(ReportContext(str(tmp_path), {"materials": {"m": material}}), "m"))
    assert "Run order: the runs carry no run order." in text
    # level 2's finding (labelled), then the advice level 2 reads (widen, recalibrate) in the table's order, as the
    # advice table words it
    assert "Level 2 — calibrated simulation against the experiment. Zobs misses its target. Widen b. Refit y." in text
    assert "Run more." not in text and "Stop." not in text
    assert "Run order: the runs carry no run order." in criticism_lines(info, _spec(material))
    assert "missing figure residuals_m.png" in text
    (tmp_path / "figures").mkdir()
    (tmp_path / "figures" / "residuals_m.png").write_bytes(b"\x89PNG\r\n\x1a\n")  # the figure, once drawn
    drawn = "".join(p.data for p in criticism(ReportContext(str(tmp_path), {"materials": {"m": material}}), "m"))
    assert "missing figure" not in drawn and "<img" in drawn


@pytest.mark.parametrize("x", [0.0, 4.9e-5, 5e-5, 0.000123, -0.0123, 0.0999, 0.09999, 0.1, -0.1, 0.4567, 9.99, 10.5])
def test_a_percentage_has_two_decimals_below_ten_percent_and_one_above(x):
    from demid.criticism.messages import percent_text
    from demid.precision import FAR_RATIO
    from demid.precision import percent_text as policy

    text = percent_text(x)
    if abs(x) < 5e-5 or abs(x) > FAR_RATIO:
        assert text == policy(x)
        return
    number = text.removesuffix(" %")
    places = 2 if abs(x) < 0.1 else 1
    assert _decimals(number) == places and abs(_number(number) - 100 * x) <= 0.5 * 10 ** -places + 1e-12


@pytest.mark.parametrize("corner", [False, True])
def test_a_recommended_point_beyond_the_design_runs_is_said_to_be_outside_them(tmp_path, corner):
    from demid.report.summary import summary

    material = _material(2)
    coded = np.array([[-1, -1], [1, -1], [-1, 1], [1, 1], [-1.41421, 0], [1.41421, 0], [0, -1.41421], [0, 1.41421],
                      [0, 0]])
    runs = pd.DataFrame({"a": 0.5 + coded[:, 0] / 2.83, "b": 1.0 + coded[:, 1] / 1.415})  # inside [0, 1] x [0, 2]
    (tmp_path / "validated").mkdir()
    runs.to_parquet(tmp_path / "validated" / "m.parquet")
    point = {"a": 0.97, "b": 1.95} if corner else {"a": 0.5, "b": 1.0}  # past the factorial corner, or the centre
    rows = [{"material": "m", "scenario": "s", "factor": f, "strict_lower": 0.0, "strict_upper": hi,
             "plausible_lower": 0.0, "plausible_upper": hi, "verdict": "bounded", "reason": "why"}
            for f, hi in (("a", 1.0), ("b", 2.0))]
    _write(tmp_path, "tables/verdicts.csv", pd.DataFrame(rows))
    _write(tmp_path, "uncertainty/m.json", {"recommended": {"scenario": "s", "plausible": True, "point": point,
                                                            "implausibility": 0.5}})
    text = _text(summary(ReportContext(str(tmp_path), {"materials": {"m": material}})))
    assert ("outside the region the design runs cover" in text) == corner


def test_how_to_read_the_summary_gives_the_plausible_set_the_verdict_rule_and_the_uninformative_rule(tmp_path):
    """The key under the answers defines the plausible set, then states the verdict rule and the uninformative
    rule, in that order, each in full (they are what the verdict words of every line mean)."""
    from demid.report.summary import summary
    from demid.sampling.residuals import PLAUSIBLE_DEFINITION
    from demid.story.verdicts import UNINFORMATIVE_TEXT, VERDICT_TEXT

    material = _material(3)
    _write(tmp_path, "uncertainty/m.json", {})
    _write(tmp_path, "criticism/m.json", {"level1": {}, "level2": {}})
    context = ReportContext(str(tmp_path), {"materials": {"m": material}})
    text = " ".join(_text(summary(context)).split())
    pieces = [" ".join(_text([context.md(piece)]).split()) for piece in
              (PLAUSIBLE_DEFINITION, "Verdicts: " + VERDICT_TEXT, UNINFORMATIVE_TEXT)]
    at = [text.find(piece) for piece in pieces]
    assert all(i >= 0 for i in at), [p[:60] for p, i in zip(pieces, at) if i < 0]
    assert at == sorted(at)
    # and last, where every other term is explained
    assert pieces[-1] + " Other terms: Terms." in text
    assert 'Other terms: <a href="#Terms">Terms</a>.' in "".join(p.data for p in summary(context))

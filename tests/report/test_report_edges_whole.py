"""The report's sentences and cells at their edges, read back number by number: a recommended point on a search
bound with why no widening is advised (its interval's verdict) or that the advice widens it; the reference point
against a set that is empty, that holds it, or that lies apart, its nearest point named in the config's order
whatever the order of the stored JSON; the ranking's gain to the digits its numerical error supports; and the
next-wave columns' units; the answer line of the fullest scenario; a one-factor uncertainty section; the next
runs' coordinates to a thousandth of each factor's range, without other materials' columns; the waves table's
shares of Ω to three significant digits; level 1's verdicts in words.  Expected values are computed here from the
tables written for the test."""

from __future__ import annotations

import re

import numpy as np
import pandas as pd
import pytest

from demid.report.columns import columns_table
from demid.report.context import ReportContext
from demid.report.model_criticism import _reference_point_lines
from demid.report.plausible import ranking_display

from .test_report_sentences_whole import (LABELS, _assert_fraction_change_first_to_last, _cells, _level2, _material,
                                          _number, _text, _write)


# --------------------------------------------------------------------------- a recommended point on a bound
@pytest.mark.parametrize("seed", range(4))
def test_a_recommended_point_on_a_bound_says_whether_it_is_widened_and_else_why_not(tmp_path, seed):
    from demid.report.summary import summary

    rng = np.random.default_rng(seed)
    d = 2 + seed % 2
    material = _material(d)
    names = list(material["factors"])
    uppers = {f: material["factors"][f]["upper"] for f in names}
    on = names[seed % d]  # the factor on a bound
    side = ("lower", "upper")[seed // 2]
    verdict = ["unresolved", "bounded", "identified", "bounded"][seed]
    widened = seed == 3
    point = {f: float(rng.uniform(0.2, 0.8)) * uppers[f] for f in names}
    point[on] = 0.0 if side == "lower" else uppers[on]
    rows = [{"material": "m", "scenario": "s", "factor": f, "strict_lower": 0.0, "strict_upper": uppers[f],
             "plausible_lower": 0.0, "plausible_upper": uppers[f], "verdict": verdict if f == on else "bounded",
             "reason": "why"} for f in names]
    _write(tmp_path, "tables/verdicts.csv", pd.DataFrame(rows))
    advice = [{"material": "m", "kind": "widen", "factor": on, "bound": side, "observable": "",
               "text": "Widen it.", "decision": True}] if widened else []
    _write(tmp_path, "tables/advice.csv", pd.DataFrame(advice, columns=["material", "kind", "factor", "bound",
                                                                         "observable", "text", "decision"]))
    _write(tmp_path, "uncertainty/m.json", {"recommended": {"scenario": "s", "plausible": True, "point": point,
                                                            "implausibility": 0.4}})
    text = _text(summary(ReportContext(str(tmp_path), {"materials": {"m": material}})))
    label = LABELS[names.index(on)]
    if widened:
        assert f"⚠ {label} lies on its {side} search bound, which the advice below widens" in text
    else:
        assert (f"⚠ {label} lies on its {side} search bound; no widening is advised there (the plausible interval is "
                f"{verdict}: a wider range would not narrow it).") in text
    assert text.count(" lies on ") == 1  # the other factors lie inside


def test_without_verdicts_a_point_on_a_bound_is_told_without_a_reason(tmp_path):
    from demid.report.summary import summary

    material = _material(2)
    _write(tmp_path, "uncertainty/m.json", {"recommended": {"scenario": "s", "plausible": True,
                                                            "point": {"a": 1.0, "b": 1.2}, "implausibility": 0.4}})
    text = _text(summary(ReportContext(str(tmp_path), {"materials": {"m": material}})))
    assert "⚠ Alpha lies on its upper search bound; no widening is advised there." in text


# --------------------------------------------------------------------------- the reference point's lines
@pytest.mark.parametrize("seed", range(4))
def test_the_reference_point_against_an_empty_a_holding_and_a_distant_set(tmp_path, seed):
    rng = np.random.default_rng(seed)
    d = 2 + seed % 3
    material = _material(d)
    names = list(material["factors"])
    kinds = ["empty", "inside", "outside"]
    positions = []
    for kind in kinds:
        errors = {o: float(rng.uniform(0.0005, 0.3) * rng.choice([-1, 1])) for o in ("y", "z")}
        nearest = None if kind == "empty" else {f: float(rng.uniform(0, 3)) for f in sorted(names, reverse=True)}
        positions.append({"scenario": "s", "inside": kind == "inside", "errors": errors,
                          "nearest_admissible": nearest,
                          "distance_pct_of_range": None if kind == "empty" else float(rng.uniform(0.5, 40))})
    lines = _reference_point_lines(ReportContext(str(tmp_path), {"materials": {"m": material}}), "m", positions)
    assert len(lines) == 3
    for line, pos, kind in zip(lines, positions, kinds):
        m = re.fullmatch(r"- Reference point vs scenario \*Both\*: it (.+) \(errors (.+)\)\.", line)
        assert m, line
        for shown, o in zip(m.group(2).split(", "), ("y", "z")):
            value = re.fullmatch(rf"{o.upper()}obs ([+−]?\S+) %", shown)
            assert value and _number(value.group(1)) == pytest.approx(100 * pos["errors"][o], rel=0.01), shown
            assert value.group(1)[0] == ("+" if pos["errors"][o] > 0 else "−")
        if kind == "empty":
            assert m.group(1) == "cannot lie in it: the admissible set is empty"
        elif kind == "inside":
            assert m.group(1) == "lies inside the admissible set"
        else:
            far = re.fullmatch(r"lies outside it, (\S+) % of the search range from the nearest admissible point "
                               r"\((.+)\)", m.group(1))
            assert far and float(far.group(1)) == pytest.approx(pos["distance_pct_of_range"], abs=0.05 + 1e-9)
            shown = far.group(2).split(", ")
            assert [s.split(" = ")[0] for s in shown] == LABELS[:d]  # the config's order, not the JSON's
            for s, f in zip(shown, names):
                assert float(s.split(" = ")[1]) == pytest.approx(pos["nearest_admissible"][f], rel=5e-4)


# --------------------------------------------------------------------------- the ranking's gains and errors
def _decimals(text: str) -> int:
    return len(text.split(".")[1]) if "." in text else 0


def _place(x: float, digits: int) -> float:
    """10 to the power of x's last significant digit once x is rounded to ``digits`` of them."""
    rounded = abs(float(f"{x:.{digits}g}"))
    return 10.0 ** (int(np.floor(np.log10(rounded))) - digits + 1)


@pytest.mark.parametrize("seed", range(3))
def test_the_ranking_quotes_each_gain_to_the_digits_its_numerical_error_supports(seed):
    rng = np.random.default_rng(seed)
    sets = ["y", "z", "y+z", "w"][: 2 + seed]
    n = len(sets)
    gains = rng.uniform(0.01, 6, n)
    errors = 10 ** rng.uniform(-3.5, -0.3, n)
    gains[0] = errors[0] * rng.uniform(0.1, 0.45)  # no gain the error can tell from zero
    ranking = pd.DataFrame({"material": "m", "rank": range(1, n + 1), "observables": sets,
                            "information_gain_bits": gains, "information_gain_error_bits": errors,
                            "best_subset": ["(none)"] * n, "gain_vs_best_subset_bits": rng.uniform(0, 2, n),
                            "targets_reachable": [True] * n})
    quiet = {sets[-1]: "its band covers its whole range"} if seed else None
    shown = ranking_display(ranking, quiet)
    assert "targets reachable" not in shown
    for i, s in enumerate(sets):
        gain_cell, error_cell = shown["information gain [bit]"].iloc[i], shown["± numerical error [bit]"].iloc[i]
        error_place = _place(errors[i], 2)
        assert _decimals(error_cell) == max(0, -int(round(np.log10(error_place))))
        assert abs(float(error_cell) - errors[i]) <= error_place / 2 + 1e-12
        if quiet and s in quiet:
            assert gain_cell == f"~0 ({gains[i]:.2f}; uninformative)"
            continue
        place = max(error_place, _place(gains[i], 3))
        if gains[i] <= place / 2:
            assert gain_cell == "≈ 0"
            continue
        assert _decimals(gain_cell) == max(0, -int(round(np.log10(place)))), (gain_cell, gains[i], errors[i])
        assert abs(float(gain_cell) - gains[i]) <= place / 2 + 1e-12


def test_a_set_that_cannot_meet_its_targets_keeps_the_reachable_column():
    ranking = pd.DataFrame({"material": "m", "rank": [1, 2, 3], "observables": ["y", "z", "y+z"],
                            "information_gain_bits": [1.0, 0.5, 2.0], "targets_reachable": [True, False, True]})
    shown = ranking_display(ranking)
    assert shown["targets reachable"].tolist() == [True, False, True]


# --------------------------------------------------------------------------- the next-wave columns' units
def test_a_predicted_response_without_a_unit_reads_a_dash():
    units = {"aor": "deg", "si": "-", "d": "", "rho": "kg m^-3"}
    frame = columns_table({}, {"factors": [("a", "mm")], "responses": list(units.items())})
    runs = frame[frame["table"] == "next_runs.csv"].set_index("column")["unit"]
    for r, unit in units.items():
        assert runs[f"predicted_{r}"] == (unit if unit not in ("", "-") else "–")


# --------------------------------------------------------------------------- the summary's answer line
@pytest.mark.parametrize("seed", range(3))
def test_the_answer_line_sorts_the_fullest_scenarios_factors_and_says_when_no_point_meets_every_target(tmp_path,
                                                                                                        seed):
    from demid.report.summary import summary

    rng = np.random.default_rng(seed)
    d = 2 + seed
    material = _material(d)
    names = list(material["factors"])
    kinds = ["identified", "bounded", "unresolved", "in combination"]
    drawn = [kinds[i % 4] for i in range(d)]
    rng.shuffle(drawn)
    rows = []
    for i, (f, kind) in enumerate(zip(names, drawn)):
        partner = LABELS[(i + 1) % d]
        verdict = f"unresolved alone; identified in combination with {partner}" if kind == "in combination" else kind
        for scenario, v in (("t", "identified"), ("s", verdict)):  # the answer is given for s, the fullest
            rows.append({"material": "m", "scenario": scenario, "factor": f, "strict_lower": np.nan,
                         "strict_upper": np.nan, "plausible_lower": 0.1, "plausible_upper": 0.9, "verdict": v,
                         "reason": "why"})
    _write(tmp_path, "tables/verdicts.csv", pd.DataFrame(rows))
    _write(tmp_path, "tables/advice.csv", pd.DataFrame([{"material": "m", "kind": "widen", "factor": "", "bound": "",
                                                         "observable": "", "text": "Widen b.", "decision": True}]))
    judged = seed < 2  # the last study has no level 2 (its criticism not run yet): nothing says it failed
    if judged:
        _write(tmp_path, "criticism/m.json", {"level1": {}, "level2": _level2(rng, ["y", "z"], False, False)})
    point = {f: 0.5 for f in names}
    _write(tmp_path, "uncertainty/m.json", {"recommended": {"scenario": "s", "plausible": True, "point": point,
                                                            "implausibility": 0.25}})
    text = _text(summary(ReportContext(str(tmp_path), {"materials": {"m": material}})))
    label = dict(zip(names, LABELS))
    identified = [label[f] for f, k in zip(names, drawn) if k == "identified"]
    combined = [label[f] for f, k in zip(names, drawn) if k == "in combination"]
    others = [f"{label[f]} {k}" for f, k in zip(names, drawn) if k in ("bounded", "unresolved")]
    line = (f"m, with Both: identified: {', '.join(identified) or 'none'}"
            + (f"; in combination only: {', '.join(combined)}" if combined else "")
            + f"; not identified: {', '.join(others) or 'none'}. Next step: Widen b.")
    assert line in text, text
    # no point meets every target and the strict set is empty: the point is the most plausible one, not a match
    assert (("No parameter set meets every target within the tolerance; counting the surrogate's and the "
             "measurements' uncertainty, the most plausible point (the point of the plausible set of Both") in text) \
        == judged
    assert ("Recommended parameter set (the point of the plausible set of Both" in text) == (not judged)
    assert "With every observable of Both no point of the search range is admissible" in text


# --------------------------------------------------------------------------- one factor, the next wave, level 1
@pytest.mark.parametrize("seed", range(2))
def test_with_one_factor_the_uncertainty_section_quotes_the_change_from_first_to_last_scenario(tmp_path, seed):
    from demid.report.plausible import uncertainty

    rng = np.random.default_rng(seed)
    material = _material(1)
    material["scenarios"]["u"] = {"observables": ["z"], "tolerance": 0.1, "label": "Second alone"}
    scenarios = ["s", "t", "u"][: 2 + seed]
    fractions = {sc: (float(rng.uniform(1, 60)), float(rng.uniform(1, 60))) for sc in scenarios}
    rows = [{"material": "m", "scenario": sc, "observables": "y", "tolerance": 0.02, "z": 2, "factor": "a",
             "strict_fraction_pct": fractions[sc][0], "robust_fraction_pct": fractions[sc][1], "strict_width": 0.1,
             "robust_width": 0.2} for sc in scenarios]  # one row per scenario: its one factor
    _write(tmp_path, "tables/robust_identifiability.csv", pd.DataFrame(rows))
    _write(tmp_path, "uncertainty/m.json", {})
    text = _text(uncertainty(ReportContext(str(tmp_path), {"materials": {"m": material}}), "m"))
    _assert_fraction_change_first_to_last(text, scenarios, fractions)


def test_the_next_runs_coordinates_are_printed_to_a_thousandth_of_each_factors_range(tmp_path):
    from demid.report.loop import next_wave

    material = _material(3)
    ranges = {"a": (0.0, 1.0), "b": (10.0, 2000.0), "c": (-0.05, 0.05)}
    for f, (lo, hi) in ranges.items():
        material["factors"][f].update(lower=lo, upper=hi)
    rng = np.random.default_rng(3)
    runs = pd.DataFrame({"material": "m", "proposal": [1, 2, 3],
                         **{f: lo + rng.random(3) * (hi - lo) for f, (lo, hi) in ranges.items()}, "purpose": "decide"})
    _write(tmp_path, "tables/next_runs.csv", runs)
    _write(tmp_path, "next_wave/reasons.json", {"m": "Three runs."})
    _write(tmp_path, "tables/advice.csv", pd.DataFrame(columns=["material", "kind", "factor", "bound", "observable",
                                                                "text", "decision"]))
    table = _cells(next_wave(ReportContext(str(tmp_path), {"materials": {"m": material}}), "m"))
    assert len(table) == 3
    for cells, (_, run) in zip(table, runs.iterrows()):
        for cell, (f, (lo, hi)) in zip(cells[1:4], ranges.items()):
            place = 10.0 ** np.floor(np.log10(1e-3 * (hi - lo)))  # a thousandth of the range, down to a power of 10
            assert _decimals(cell) == max(0, -int(round(np.log10(place)))), (f, cell)
            assert abs(_number(cell) - run[f]) <= place / 2 + 1e-12


def test_the_criticism_section_gives_each_verdict_in_words_with_its_sentence(tmp_path):
    from demid.report.model_criticism import criticism

    material = _material(2, ("y", "z", "w"))
    level1 = {"w": {"verdict": "adequate", "messages": [], "verdict_message": ""},
              "z": {"verdict": "defect", "messages": ["z: run 4 does not fit."],
                    "verdict_message": "z: defect — run 4 does not fit z."},
              "y": {"verdict": "unexplained", "messages": [], "verdict_message": "y: the misfit is unexplained."},
              "v": {"verdict": "ambiguous", "messages": [],
                    "verdict_message": "v: ambiguous — two causes — a drift or a slip."}}
    material["responses"]["v"] = {"target": 2.0, "label": "Vobs"}
    _write(tmp_path, "criticism/m.json", {"level1": level1})
    findings = pd.DataFrame({"material": ["m", "m"], "response": ["z", "y"], "cause": ["missing_term;outlier", "none"],
                             "detail": ["b", np.nan], "p_value": [0.01, 1.0]})
    _write(tmp_path, "tables/criticism.csv", findings)
    parts = criticism(ReportContext(str(tmp_path), {"materials": {"m": material}}), "m")
    lines = [x.strip() for x in _text(parts).split("\n") if x.strip()]
    assert "Yobs — misfit unexplained: the misfit is unexplained." in lines
    assert "Zobs — defect named: run 4 does not fit Zobs." in lines
    assert "Wobs: nothing found by the catalogue tests." in lines
    assert "Vobs — ambiguous cause: two causes — a drift or a slip." in lines  # only the lead is cut
    # the named cause's row only, its cause in words and its detail labelled
    assert _cells(parts) == [["Zobs", "missing term, outlier", "Beta", "0.01"]]


def test_a_material_without_waves_or_a_recommended_point_has_no_such_lines(tmp_path):
    from demid.report.loop import waves
    from demid.report.summary import summary

    material = _material(2)
    context = ReportContext(str(tmp_path), {"materials": {"m": material}})
    assert waves(context, "m") == []
    _write(tmp_path, "waves/summary_m.json", {"waves": []})
    assert waves(context, "m") == []
    rows = [{"material": "m", "scenario": "s", "factor": f, "strict_lower": 0.1, "strict_upper": 0.2,
             "plausible_lower": 0.05, "plausible_upper": 0.3, "verdict": "identified", "reason": "narrow"}
            for f in ("a", "b")]
    _write(tmp_path, "tables/verdicts.csv", pd.DataFrame(rows))
    _write(tmp_path, "uncertainty/m.json", {"notes": []})
    text = _text(summary(ReportContext(str(tmp_path), {"materials": {"m": material}})))
    assert "m, with Both: identified: Alpha, Beta; not identified: none." in text
    assert "parameter set" not in text and "lies on" not in text


def test_the_waves_table_gives_each_share_of_omega_to_three_significant_digits(tmp_path):
    from demid.report.loop import waves

    rng = np.random.default_rng(7)
    material = _material(2)
    shares = 10 ** rng.uniform(-2, 1.9, 4)  # 0.01 % to 80 %
    rows = [{"wave": w, "scenario": "s", "simulated": 9 + 4 * w, "failed": 0, "analysed": 9 + 4 * w,
             "surrogate": "quadratic", "q2": {"y": 0.9}, "plausible_fraction_of_omega_pct": float(v),
             "plausible": {"a": [0.1, 0.2], "b": [0.3, 0.4]}} for w, v in enumerate(shares, start=1)]
    _write(tmp_path, "waves/summary_m.json", {"waves": rows})
    table = _cells(waves(ReportContext(str(tmp_path), {"materials": {"m": material}}), "m"))
    assert [float(cells[6]) for cells in table] == [float(f"{v:.3g}") for v in shares]


def test_the_next_runs_table_leaves_out_the_columns_of_other_materials_factors(tmp_path):
    from demid.report.loop import next_wave

    material = _material(2)
    runs = pd.DataFrame({"material": ["m", "other", "m"], "proposal": [1, 1, 2], "a": [0.25, np.nan, 0.75],
                         "b": [1.5, np.nan, 0.5], "q": [np.nan, 3.0, np.nan], "purpose": ["decide", "x", "cover"]})
    _write(tmp_path, "tables/next_runs.csv", runs)
    _write(tmp_path, "next_wave/reasons.json", {"m": "Two runs.", "other": "One run."})
    table = _cells(next_wave(ReportContext(str(tmp_path), {"materials": {"m": material}}), "m"))
    # a and b (ranges 1 and 2) to a thousandth of their range: three decimals
    assert table == [["1", "0.250", "1.500", "decide"], ["2", "0.750", "0.500", "cover"]]

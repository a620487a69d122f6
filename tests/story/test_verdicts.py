"""Known answers for the verdict table: hand-made strict and plausible intervals whose widths, verdicts and
reasons follow from the verdict thresholds by arithmetic done here (linear and log10 widths)."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from demid.story.verdicts import IDENTIFIED_MAX_WIDTH, UNRESOLVED_MIN_WIDTH
from demid.spec import MaterialSpec
from demid.story.verdicts import UNINFORMATIVE, VERDICT_COLUMNS, in_combination, verdict_display, verdict_frame


def _spec() -> MaterialSpec:
    material = {"data": "x.csv", "design": {"type": "custom"},
                "factors": {"a": {"lower": 0.0, "upper": 1.0, "label": "A"},
                            "b": {"lower": 1.0, "upper": 100.0, "scale": "log", "label": "B"}},
                "responses": {"y1": {"target": 1.0, "label": "Y one"}, "y2": {"target": 2.0, "label": "Y two"}},
                "scenarios": {"s1": {"observables": ["y1"], "tolerance": 0.05},
                              "s2": {"observables": ["y1", "y2"], "tolerance": 0.05, "label": "both"}}}
    return MaterialSpec.from_material("m", material, grid_points=21)


def _frames(rows):
    """(identifiability, plausible) from rows (scenario, factor, strict lo, strict hi, plausible lo, hi, fraction)."""
    strict = pd.DataFrame([{"scenario": s, "factor": f, "lower": lo, "upper": hi, "at_bound": None}
                           for s, f, lo, hi, *_ in rows])
    plaus = pd.DataFrame([{"scenario": s, "factor": f, "robust_lower": plo, "robust_upper": phi,
                           "robust_fraction_pct": frac} for s, f, _, _, plo, phi, frac in rows])
    return strict, plaus


def test_widths_verdicts_and_reasons_of_linear_and_log_factors():
    spec = _spec()
    rows = [("s1", "a", 0.31, 0.34, 0.30, 0.35, 3.0),                        # width 0.05: identified both ways
            ("s1", "b", 10 ** 0.8, 10 ** 0.9, 10 ** 0.5, 10 ** 1.2, 3.0),    # log10 widths 0.1/2, 0.7/2
            ("s2", "a", 0.40, 0.45, 0.05, 0.96, 40.0),                       # 0.91 of the range: unresolved
            ("s2", "b", np.nan, np.nan, 1.5, 90.0, 0.0)]                     # an empty plausible set
    frame = verdict_frame(spec, *_frames(rows))
    assert list(frame.columns) == VERDICT_COLUMNS and len(frame) == 4
    by = frame.set_index(["scenario", "factor"])
    a1, b1, a2, b2 = (by.loc[k] for k in [("s1", "a"), ("s1", "b"), ("s2", "a"), ("s2", "b")])
    assert a1["verdict"] == "identified" and 0.05 <= IDENTIFIED_MAX_WIDTH
    assert a1["reason"] == "the plausible interval is 5 % of the search range wide and clear of both bounds"
    assert (a1["strict_lower"], a1["strict_upper"], a1["plausible_lower"], a1["plausible_upper"]) == (
        0.31, 0.34, 0.30, 0.35)
    # b: log10 width (1.2 - 0.5) / (2 - 0) = 0.35 plausible, (0.9 - 0.8) / 2 = 0.05 strict
    assert b1["verdict"] == "bounded"
    assert b1["reason"] == (
        "the plausible interval is 35 % of the search range wide (identified needs at most 10 %) and clear of "
        f"both bounds; identified if surrogate and measurements were exact (strict interval "
        f"[{10 ** 0.8:.4g}, {10 ** 0.9:.4g}], 5 % of the search range)")
    assert 0.91 >= UNRESOLVED_MIN_WIDTH and a2["verdict"] == "unresolved"
    assert a2["reason"].startswith("the plausible interval covers 91 % of the search range: the observables say")
    # the strict interval is identified: said so, with its interval and width
    assert "identified if surrogate and measurements were exact (strict interval [0.4, 0.45], 5 %" in a2["reason"]
    # a zero plausible fraction empties the interval whatever its columns say; the strict set is empty too
    assert np.isnan(b2["plausible_lower"]) and np.isnan(b2["plausible_upper"])
    assert b2["verdict"] == "no admissible point"
    assert b2["reason"].startswith("no point of the search range is plausible: a discrepancy")
    assert "strictly" not in b2["reason"]


def test_a_strict_verdict_other_than_identified_is_named_with_its_interval():
    spec = _spec()
    # plausible 0.2 wide (bounded), strict 0.5 wide touching the upper bound of a
    frame = verdict_frame(spec, *_frames([("s1", "a", 0.5, 1.0, 0.4, 0.6, 10.0)]))
    row = frame.iloc[0]
    assert row["verdict"] == "bounded"
    assert row["reason"].endswith("; strictly (surrogate and measurements exact): cut by the search range "
                                  "(upper bound), [0.5, 1], 50 % of the search range")
    # a cut plausible interval names its side; a strictly empty set is said so
    frame = verdict_frame(spec, *_frames([("s1", "a", np.nan, np.nan, 0.0, 0.3, 10.0)]))
    row = frame.iloc[0]
    assert row["verdict"] == "cut by the search range (lower bound)"
    assert row["reason"] == ("the plausible interval (30 % of the search range) reaches the lower bound: the set "
                             "may extend beyond the search range; strictly (surrogate and measurements exact) no "
                             "point meets every target")


def test_uninformative_and_implausible_observables_and_missing_rows():
    spec = _spec()
    rows = [("s1", "a", 0.3, 0.35, 0.3, 0.35, 5.0), ("s2", "a", np.nan, np.nan, np.nan, np.nan, 0.0)]
    strict, plaus = _frames(rows)
    # s1's only observable is uninformative: that verdict, with the label and the reason
    frame = verdict_frame(spec, strict, plaus, uninformative={"y1": "flat"}, implausible={"y2"})
    by = frame.set_index(["scenario", "factor"])
    assert len(frame) == 2  # b has no rows: skipped
    assert by.loc[("s1", "a"), "verdict"] == UNINFORMATIVE and by.loc[("s1", "a"), "reason"] == "Y one: flat"
    # s2 has an informative observable; its empty set is put down to the implausible target of y2
    assert by.loc[("s2", "a"), "verdict"] == "no admissible point"
    assert by.loc[("s2", "a"), "reason"] == ("no point of the search range is plausible: the target of Y two lies "
                                            "far outside every simulated value (check it: see the next step)")
    frame = verdict_frame(spec, strict, plaus, uninformative={"y1": "flat", "y2": "flat too"})
    assert frame.set_index("scenario").loc["s2", "reason"] == "Y one: flat; Y two: flat too"


def test_in_combination_and_the_display_table():
    spec = _spec()
    rows = [("s1", "a", 0.05, 0.97, 0.02, 0.98, 90.0), ("s1", "b", 1.2, 95.0, 1.1, 99.0, 90.0),
            ("s2", "a", 0.31, 0.34, 0.30, 0.35, 3.0)]
    verdicts = verdict_frame(spec, *_frames(rows))
    combined = in_combination(verdicts, spec, {"in_combination_plausible": {"s1": {"a": ["b"]}},
                                               "in_combination": {"s1": {"b": ["a"]}}})
    by = combined.set_index(["scenario", "factor"])
    assert by.loc[("s1", "a"), "verdict"] == "unresolved alone; identified in combination with B"
    assert by.loc[("s1", "a"), "reason"].endswith("; the plausible set is narrow along a combination of it with B "
                                                 "(tables/combinations.csv)")
    assert by.loc[("s1", "b"), "verdict"] == "unresolved"
    assert by.loc[("s1", "b"), "reason"].endswith(
        "; identified in combination with A if surrogate and measurements were exact (the strict set; the "
        "plausible set is not narrow along it)")
    assert by.loc[("s2", "a"), "verdict"] == "identified"
    assert in_combination(verdicts, spec, {}) is verdicts
    shown = verdict_display(combined, spec)
    assert list(shown["scenario"]) == ["s1", "s1", "both"] and list(shown["factor"]) == ["A", "B", "A"]
    # widths in % of the range: linear (0.98 - 0.02) / 1, log10 (log 99 - log 1.1) / (log 100 - log 1)
    expected = [96.0, 100 * (np.log10(99) - np.log10(1.1)) / 2, 5.0]
    assert shown["plausible width [% of range]"].to_numpy() == pytest.approx(expected)
    assert list(shown["plausible interval"]) == ["[0.02, 0.98]", "[1.1, 99]", "[0.3, 0.35]"]
    assert list(shown["strict interval"]) == ["[0.05, 0.97]", "[1.2, 95]", "[0.31, 0.34]"]
    empty = verdict_display(verdict_frame(spec, *_frames([("s1", "a", np.nan, np.nan, np.nan, np.nan, 0.0)])), spec)
    assert empty["plausible interval"].iloc[0] == "–" and np.isnan(empty["plausible width [% of range]"].iloc[0])


def test_display_widths_of_ranges_that_do_not_start_at_zero_and_rows_missing_from_one_table():
    material = {"data": "x.csv", "design": {"type": "custom"},
                "factors": {"a": {"lower": 2.0, "upper": 4.0}, "b": {"lower": 10.0, "upper": 1000.0, "scale": "log"}},
                "responses": {"y1": {"target": 1.0}}, "scenarios": {"s1": {"observables": ["y1"], "tolerance": 0.05}}}
    spec = MaterialSpec.from_material("m", material, grid_points=21)
    strict, plaus = _frames([("s1", "a", 2.5, 3.0, 2.4, 3.1, 20.0), ("s1", "b", 20.0, 50.0, 20.0, 200.0, 20.0)])
    frame = verdict_frame(spec, strict, plaus)
    # widths: (3.1 - 2.4) / (4 - 2) = 0.35; (log 200 - log 20) / (log 1000 - log 10) = 1 / 2
    assert list(frame["verdict"]) == ["bounded", "bounded"]
    shown = verdict_display(frame, spec)
    assert shown["plausible width [% of range]"].to_numpy() == pytest.approx([35.0, 50.0])
    # a factor with a plausible row but no strict row (or the other way round) is left out
    assert list(verdict_frame(spec, strict.iloc[:1], plaus)["factor"]) == ["a"]
    assert list(verdict_frame(spec, strict, plaus.iloc[1:])["factor"]) == ["b"]


def test_the_verdict_width_thresholds_are_written_once():
    """"identified" and "identified in combination" mean the same width: each threshold is a number written in one
    module, which the verdicts and the combinations both import."""
    import ast
    from pathlib import Path

    import demid
    from demid.combinations import axes

    written = {}
    for path in sorted(Path(demid.__file__).parent.rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Assign) and isinstance(node.value, ast.Constant):
                for target in node.targets:
                    if isinstance(target, ast.Name) and target.id.endswith(("_MAX_WIDTH", "_MIN_WIDTH")):
                        written.setdefault(node.value.value, []).append(f"{path.name}:{target.id}")
    assert written == {0.10: ["domain.py:IDENTIFIED_MAX_WIDTH"], 0.90: ["domain.py:UNRESOLVED_MIN_WIDTH"]}, written
    assert (axes.IDENTIFIED_MAX_WIDTH, axes.FREE_MIN_WIDTH) == (IDENTIFIED_MAX_WIDTH, UNRESOLVED_MIN_WIDTH)

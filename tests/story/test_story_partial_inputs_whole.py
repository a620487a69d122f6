"""Story functions on inputs the pipeline's own files hold only in part: a combinations dict with one of its two
keys (as the tests and older results give it), and the words and advice each reads from it."""

from __future__ import annotations

import numpy as np
import pandas as pd

from demid.spec import MaterialSpec
from demid.story.verdicts import in_combination, verdict_frame


def _spec() -> MaterialSpec:
    material = {"data": "x.csv", "design": {"type": "custom"},
                "factors": {"a": {"lower": 0.0, "upper": 1.0, "label": "A"},
                            "b": {"lower": 0.0, "upper": 1.0, "label": "B"},
                            "c": {"lower": 0.0, "upper": 1.0, "label": "C"}},
                "responses": {"y1": {"target": 1.0, "label": "Y one"}},
                "scenarios": {"s1": {"observables": ["y1"], "tolerance": 0.05}}}
    return MaterialSpec.from_material("m", material, grid_points=21)


def _unresolved_frame(spec) -> pd.DataFrame:
    strict = pd.DataFrame([{"scenario": "s1", "factor": f, "lower": 0.02, "upper": 0.98, "at_bound": None}
                           for f in "abc"])
    plaus = pd.DataFrame([{"scenario": "s1", "factor": f, "robust_lower": 0.01, "robust_upper": 0.99,
                           "robust_fraction_pct": 90.0} for f in "abc"])
    return verdict_frame(spec, strict, plaus)


def test_a_plausible_combination_alone_leaves_the_other_unresolved_factors_as_they_are():
    spec = _spec()
    verdicts = _unresolved_frame(spec)
    assert list(verdicts["verdict"]) == ["unresolved"] * 3
    combined = in_combination(verdicts, spec, {"in_combination_plausible": {"s1": {"a": ["b"], "b": ["a"]}}})
    assert list(combined["verdict"]) == ["unresolved alone; identified in combination with B",
                                         "unresolved alone; identified in combination with A", "unresolved"]
    assert combined["reason"].iloc[2] == verdicts["reason"].iloc[2]


def test_a_strict_combination_alone_only_adds_its_reason():
    spec = _spec()
    verdicts = _unresolved_frame(spec)
    combined = in_combination(verdicts, spec, {"in_combination": {"s1": {"a": ["b", "c"]}}})
    assert list(combined["verdict"]) == ["unresolved"] * 3
    assert combined["reason"].iloc[0] == (
        verdicts["reason"].iloc[0] + "; identified in combination with B and C if surrogate and measurements were "
        "exact (the strict set; the plausible set is not narrow along it)")
    assert list(combined["reason"].iloc[1:]) == list(verdicts["reason"].iloc[1:])


def test_the_display_shows_an_interval_with_one_end_unknown_as_a_dash():
    """An interval is printed only with both ends finite: a frame with one end missing (a table cut or edited by
    hand) shows "–" for it, never "[nan, 0.5]"; its width is NaN as well."""
    from demid.story.verdicts import verdict_display

    spec = _spec()
    verdicts = _unresolved_frame(spec)
    verdicts.loc[0, ["strict_lower", "plausible_lower"]] = float("nan")
    verdicts.loc[1, ["strict_upper", "plausible_upper"]] = float("nan")
    shown = verdict_display(verdicts, spec)
    assert list(shown["strict interval"]) == ["–", "–", "[0.02, 0.98]"]
    assert list(shown["plausible interval"]) == ["–", "–", "[0.01, 0.99]"]
    width = shown["plausible width [% of range]"].to_numpy()
    assert np.isnan(width[:2]).all() and width[2] == 100 * (0.99 - 0.01)

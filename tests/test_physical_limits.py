"""A factor's physical limits (``factors.<f>.limits``): advice never widens a range beyond them, an end of the range
at a limit does not cut a set, and a target the surrogate reaches only beyond a limit is out of reach.  Closed-form
responses on [0, 1] (as in tests/criticism/test_reach.py)."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from demid.criticism import calibration_check
from demid.criticism.edges import widen_advice
from demid.design import quadratic_terms
from demid.story.verdicts import factor_verdict
from demid.sampling.domain import Domain
from demid.spec import MaterialSpec
from demid.story import material_advice
from demid.story.verdicts import verdict_frame
from demid.surrogate import Surrogate

TOL = 0.02


def _line(b0: float, b1: float) -> Surrogate:
    """y = b0 + b1 x (w does nothing)."""
    terms = quadratic_terms(2)
    coef = np.zeros(len(terms))
    coef[0], coef[1] = b0, b1
    return Surrogate("y", ["x", "w"], terms, coef, np.zeros((len(terms), len(terms))), 0.0, 7)


def _spec(limits_x: dict | None, target: float = 20.0) -> MaterialSpec:
    x = {"lower": 0.0, "upper": 1.0, **({"limits": limits_x} if limits_x else {})}
    return MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "custom"},
        "factors": {"x": x, "w": {"lower": 0.0, "upper": 1.0}},
        "responses": {"y": {"target": target, "unit": "mm"}},
        "scenarios": {"s": {"observables": ["y"], "tolerance": TOL}}}, grid_points=21)


@pytest.mark.parametrize("limit,widen", [(None, True), (1.2, True), (1.1, False), (1.0, False)])
def test_a_target_reached_only_beyond_the_physical_limit_is_out_of_reach(limit, widen):
    # y = 10 + 8x: 18 at the bound x = 1; the band edge 19 is reached at x = 1.125 (1/8 of the range beyond it)
    spec = _spec({"upper": limit} if limit is not None else None, target=19.0 / (1 - TOL))
    result = calibration_check({"y": _line(10, 8)}, spec.domain, {"y": spec.responses[0].target}, TOL, 21)
    (reach,) = result.reach
    assert reach.quadratic_factor_value == pytest.approx(1.125, rel=1e-6)
    room = np.inf if limit is None else limit - 1.0
    assert reach.limit_extension == pytest.approx(room) and reach.widen is widen
    assert reach.beyond_limit is (not widen)
    advice = material_advice(spec, pd.DataFrame(columns=["scenario", "factor", "verdict"]),
                             criticism={"level2": result.to_json()})
    kinds = {(i.kind, i.factor) for i in advice}
    assert (("widen", "x") in kinds) is widen and (("recalibrate", "x") in kinds) is (not widen)
    if limit == 1.1:
        assert "only at x ≈ 1.125, beyond the physical limit of x (1.1)" in result.finding
        (item,) = [i for i in advice if i.factor == "x"]
        assert "beyond its physical limit 1.1" in item.text
    if limit == 1.0:
        assert "The range of x already ends at its physical limit 1" in result.finding
        assert "Widen the range of x" not in result.message


def test_an_end_of_the_range_at_a_physical_limit_does_not_cut_the_set():
    # [0.92, 1.0] on [0.2, 1.0]: 10 % of the range, reaching the upper bound
    assert factor_verdict(0.92, 1.0, 0.2, 1.0)[0] == "cut by the search range (upper bound)"
    assert factor_verdict(0.92, 1.0, 0.2, 1.0, limits=(None, 1.5))[0] == "cut by the search range (upper bound)"
    assert factor_verdict(0.92, 1.0, 0.2, 1.0, limits=(None, 1.0)) == pytest.approx(("identified", 0.1))
    assert factor_verdict(0.2, 1.0, 0.2, 1.0, limits=(0.0, 1.0))[0] == "unresolved"
    assert factor_verdict(0.2, 0.5, 0.2, 1.0, limits=(0.2, None))[0] == "bounded"  # 37.5 %, clear of the top
    assert factor_verdict(0.2, 1.0 - 1e-9, 0.0, 1.0, at_bound="both", limits=(0.0, None))[0] == \
        "cut by the search range (upper bound)"


def test_the_verdict_says_the_interval_ends_at_the_physical_limit():
    spec = _spec({"lower": 0.0, "upper": 1.0})
    strict = pd.DataFrame([{"scenario": "s", "factor": "x", "lower": 0.93, "upper": 1.0, "at_bound": "upper"},
                           {"scenario": "s", "factor": "w", "lower": 0.4, "upper": 0.45, "at_bound": "none"}])
    plausible = pd.DataFrame([{"scenario": "s", "factor": "x", "robust_lower": 0.92, "robust_upper": 1.0,
                            "robust_fraction_pct": 5.0},
                           {"scenario": "s", "factor": "w", "robust_lower": 0.4, "robust_upper": 0.46,
                            "robust_fraction_pct": 5.0}])
    frame = verdict_frame(spec, strict, plausible).set_index("factor")
    assert frame.loc["x", "verdict"] == "identified"
    assert frame.loc["x", "reason"].startswith("the plausible interval is 8 % of the search range wide and clear of "
                                               "the lower bound, ending at the physical upper limit (1), beyond which "
                                               "no value lies")
    assert "physical" not in frame.loc["w", "reason"]
    assert not [i for i in material_advice(spec, frame.reset_index()) if i.kind == "widen"]
    # without the limit the same interval is cut, and the range is widened there
    plain = verdict_frame(_spec(None), strict, plausible)
    assert plain.set_index("factor").loc["x", "verdict"] == "cut by the search range (upper bound)"
    assert [(i.kind, i.factor, i.bound) for i in material_advice(_spec(None), plain) if i.kind == "widen"] == [
        ("widen", "x", "upper")]


def test_widening_stops_at_the_physical_limit():
    spec = _spec({"lower": 0.0, "upper": 1.5})
    cut = pd.DataFrame([{"scenario": "s", "factor": "x", "verdict": "cut by the search range (upper bound)"}])
    (item,) = [i for i in material_advice(spec, cut) if i.kind == "widen"]
    assert "beyond its upper bound (1), up to its physical limit 1.5, and simulate" in item.text
    domain = Domain(("x", "w"), (0.2, 0.0), (1.0, 1.0), limits=((0.0, 1.0), (None, None)))
    sentences = widen_advice(domain, {"x": ("upper",)}, {"x": ("lower", "upper"), "w": ("upper",)})
    assert sentences[0] == ("Widen the range of x: the admissible set reaches its lower bound and may extend beyond "
                            "it. Simulate runs below 0.2 (down to its physical limit 0) and search there.")
    assert sentences[1].startswith("Widen the range of w") and "physical" not in sentences[1]
    assert len(sentences) == 2
    assert domain.room_beyond("x", "lower") == pytest.approx(0.25) and domain.room_beyond("x", "upper") == 0.0
    assert domain.room_beyond("w", "upper") == np.inf


def test_limits_must_contain_the_search_range():
    from demid.spec import limits_problem

    assert limits_problem(0.1, 0.9, None) is None and limits_problem(0.1, 0.9, {"lower": 0.1, "upper": 0.9}) is None
    assert limits_problem(0.1, 0.9, {"lower": 0.2}).startswith("limits.lower: 0.2 is above the search range's lower "
                                                              "bound 0.1")
    assert limits_problem(0.1, 0.9, {"upper": 0.8}).startswith("limits.upper: 0.8 is below the search range's upper "
                                                              "bound 0.9")
    # a bound written rounded to 6 digits (a next wave's box) is still within, and still at, the limit
    assert limits_problem(0.0, 0.707107, {"upper": 0.7071068}) is None
    from demid.sampling.domain import sides_at_limit
    assert sides_at_limit((0.0, 0.707107), (None, 0.7071068)) == ["upper"]
    assert sides_at_limit((0.0, 0.7071), (None, 0.7071068)) == []


def test_a_response_levelling_off_beyond_the_limit_is_said_to_stay_short_up_to_the_limit():
    # y = 10 + 12x - 4x²: 18 at the bound x = 1, levels off at x = 1.5 (19) short of the band edge 24.5; the
    # straight line reaches it at x = 2.625.  With the limit 1.2 neither value can be simulated.
    from demid.surrogate import Surrogate as S

    terms = quadratic_terms(2)
    coef = np.zeros(len(terms))
    coef[0], coef[1], coef[4] = 10, 12, -4
    spec = _spec({"upper": 1.2}, target=24.5 / (1 - TOL))
    surrogate = S("y", ["x", "w"], terms, coef, np.zeros((len(terms), len(terms))), 0.0, 7)
    result = calibration_check({"y": surrogate}, spec.domain, {"y": spec.responses[0].target}, TOL, 21)
    (reach,) = result.reach
    assert reach.levels_off and not reach.widen and not reach.beyond_limit
    assert "stays short of its target 25 up to the physical limit of x (1.2)" in result.finding
    assert "x ≈ 1.5" not in result.finding
    (item,) = [i for i in material_advice(spec, pd.DataFrame(columns=["scenario", "factor", "verdict"]),
                                          criticism={"level2": result.to_json()}) if i.factor == "x"]
    assert item.kind == "recalibrate" and "straight line" not in item.text

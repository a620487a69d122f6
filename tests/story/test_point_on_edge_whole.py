"""Where the recommended point stands (demid/story/recommended.py), its whole sentence against the rule written out
here, over generated placements of 1-4 factors (linear and log ranges away from the origin, some bounds at a
physical limit): per factor on a bound, a physical limit ("beyond which no value lies"), a bound the advice
widens, or a bound kept (with the plausible interval's verdict when it is unresolved, bounded or identified);
factors with the same words named together in config order ("a, b and c"), singular and plural; then the
extrapolation warning when the point lies outside the design runs' hull (a box of runs, its inner half or none)."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import Phase, given, settings, strategies as st

from demid.spec import MaterialSpec
from demid.story.recommended import point_on_edge_text

_OUTSIDE = ("The point lies outside the region the design runs cover (their convex hull): its predictions are the "
            "quadratic's extrapolation, backed by no simulation, so simulate it before relying on it.")
_VERDICTS = ["unresolved", "bounded", "identified", "cut by the search range (lower bound)", ""]


def _spec(k: int, logs: list[bool], limits: list[tuple[bool, bool]]):
    factors = {}
    for i in range(k):
        lo, hi = (10.0 ** (i - 2), 10.0 ** (i - 2) * 50) if logs[i] else (-3.0 + 2 * i, 4.5 + 3 * i)
        block = {"lower": lo, "upper": hi, "label": f"F{i}"}
        if logs[i]:
            block["scale"] = "log"
        at_lo, at_hi = limits[i]
        if at_lo or at_hi:
            block["limits"] = {**({"lower": lo} if at_lo else {}), **({"upper": hi} if at_hi else {})}
        factors[f"f{i}"] = block
    return MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "custom"}, "factors": factors, "responses": {"y": {"target": -2.0}},
        "scenarios": {"s": {"observables": ["y"], "tolerance": 0.05}}}, grid_points=11)


def _names(labels: list[str]) -> str:
    return ", ".join(labels[:-1]) + " and " + labels[-1] if len(labels) > 1 else labels[0]


def _expected(spec, places, limits, widened, verdicts, outside) -> str:
    groups: dict = {}
    for i, f in enumerate(spec.factors):
        side = places[i]
        if side == "middle":
            continue
        if limits[i][0 if side == "lower" else 1]:
            key = ("limit", side, "")
        elif (f.name, side) in widened:
            key = ("widened", side, "")
        else:
            why = verdicts[f.name]
            key = ("kept", side, why if why in ("unresolved", "bounded", "identified") else "")
        groups.setdefault(key, []).append(f.label)
    clauses = []
    for (kind, side, why), labels in groups.items():
        many = len(labels) > 1
        if kind == "limit":
            clauses.append(f"{_names(labels)} {'are at their' if many else 'is at its'} physical {side} "
                           f"limit{'s' if many else ''}, beyond which no value lies")
        elif kind == "widened":
            clauses.append(f"{_names(labels)} {'lie on their' if many else 'lies on its'} {side} search "
                           f"bound{'s' if many else ''}, which the advice below widens: the plausible set may "
                           "continue beyond it, and the recommended value with it")
        else:
            text = (f"{_names(labels)} {'lie on their' if many else 'lies on its'} {side} search "
                    f"bound{'s' if many else ''}; no widening is advised there")
            if why:
                text += (f" (the plausible interval{'s are' if many else ' is'} {why}: a wider range would not "
                         f"narrow {'them' if many else 'it'})")
            clauses.append(text)
    if not clauses and not outside:
        return ""
    text = "⚠ " + "; ".join(clauses) + ("." if clauses else "")
    return text + ((" " if clauses else "") + _OUTSIDE if outside else "")


@settings(max_examples=40, deadline=None, derandomize=True, phases=(Phase.explicit, Phase.generate))
@given(k=st.integers(1, 4), data=st.data())
def test_the_point_on_edge_sentence_is_the_rule_written_out(k, data):
    logs = data.draw(st.lists(st.booleans(), min_size=k, max_size=k))
    limits = data.draw(st.lists(st.tuples(st.booleans(), st.booleans()), min_size=k, max_size=k))
    places = data.draw(st.lists(st.sampled_from(["lower", "upper", "middle"]), min_size=k, max_size=k))
    runs_kind = data.draw(st.sampled_from(["box", "inner", "none"]))
    spec = _spec(k, logs, limits)
    widened = {(f.name, s) for f in spec.factors for s in ("lower", "upper") if data.draw(st.booleans())}
    verdicts = {f.name: data.draw(st.sampled_from(_VERDICTS)) for f in spec.factors}

    lo, hi = spec.domain.search_bounds()
    unit = np.array([{"lower": 0.0, "upper": 1.0, "middle": 0.5}[p] for p in places])
    point = dict(zip(spec.factor_names, spec.domain.to_actual(lo + unit * (hi - lo))[0]))
    corners = np.array(np.meshgrid(*[[0.0, 1.0]] * k, indexing="ij")).reshape(k, -1).T
    runs_unit = {"box": corners, "inner": 0.25 + 0.5 * corners, "none": None}[runs_kind]
    runs = None if runs_unit is None else spec.domain.to_actual(lo + runs_unit * (hi - lo))
    # the inner half of the box covers a point only where every coordinate is in [0.25, 0.75]
    outside = runs_kind == "inner" and any(p != "middle" for p in places)

    text = point_on_edge_text(spec, point, runs, verdicts, widened)
    assert text == _expected(spec, places, limits, widened, verdicts, outside)


def test_three_factors_kept_on_one_bound_are_named_together_in_config_order():
    spec = _spec(4, [False, True, False, False], [(False, False)] * 4)
    lo, hi = spec.domain.search_bounds()
    unit = np.array([1.0, 1.0, 0.5, 1.0])
    point = dict(zip(spec.factor_names, spec.domain.to_actual(lo + unit * (hi - lo))[0]))
    verdicts = {f: "bounded" for f in spec.factor_names}
    assert point_on_edge_text(spec, point, None, verdicts, set()) == (
        "⚠ F0, F1 and F3 lie on their upper search bounds; no widening is advised there (the plausible intervals "
        "are bounded: a wider range would not narrow them).")
    assert point_on_edge_text(spec, point, None, verdicts, {("f1", "upper")}) == (
        "⚠ F0 and F3 lie on their upper search bounds; no widening is advised there (the plausible intervals are "
        "bounded: a wider range would not narrow them); F1 lies on its upper search bound, which the advice below "
        "widens: the plausible set may continue beyond it, and the recommended value with it.")
    middle = dict(zip(spec.factor_names, spec.domain.to_actual(lo + 0.5 * (hi - lo))[0]))
    assert point_on_edge_text(spec, middle, np.zeros((0, 4)), verdicts, set()) == ""


@pytest.mark.parametrize("past, outside", [(0.5, False), (3.0, True)])
def test_the_hull_slack_is_a_share_of_each_factors_range_on_ranges_away_from_zero(past, outside):
    """Runs on the triangle u + v <= 0.8 of the unit square over a = [100, 101], b = [-5, -3] (one range far from
    zero, one below it): a point past the long side by ``past`` times the slack, in fractions of each range, is covered
    below the slack and outside above it, and no bound is touched."""
    from demid.story.recommended import HULL_TOLERANCE

    spec = MaterialSpec.from_material("m", {
        "data": "x.csv", "design": {"type": "custom"},
        "factors": {"a": {"lower": 100.0, "upper": 101.0, "label": "A"}, "b": {"lower": -5.0, "upper": -3.0,
                                                                                "label": "B"}},
        "responses": {"y": {"target": 1.0}}, "scenarios": {"s": {"observables": ["y"], "tolerance": 0.05}}},
        grid_points=11)
    lo, hi = spec.domain.search_bounds()
    corners = np.array([[0.1, 0.1], [0.7, 0.1], [0.1, 0.7]])
    runs = lo + corners * (hi - lo)
    step = 0.4 + past * HULL_TOLERANCE
    point = dict(zip(spec.factor_names, lo + np.array([step, step]) * (hi - lo)))
    text = point_on_edge_text(spec, point, runs, {}, set())
    assert text == (f"⚠ {_OUTSIDE}" if outside else "")

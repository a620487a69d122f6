"""The verdict table, its summary display and a material's one-line answer against the rule written out here
(the width in search units, the 10 % and 90 % thresholds inclusive, a touch within half a percent of the range, a
bound at a physical limit cutting nothing), over generated studies: 2-4 factors on linear and log ranges of either
sign, 1-3 scenarios of different sizes, intervals of every kind (empty, a plausible set of no fraction, touching
either bound, at a limit), the strict table's own ``at_bound``, uninformative observables and implausible targets.
Every number a reason or the display quotes is read back; the thresholds are checked on widths exactly 10 % and 90 %."""

from __future__ import annotations

import math
import re

import numpy as np
import pandas as pd
import pytest
from hypothesis import Phase, given, settings, strategies as st

from demid.sampling.domain import AT_BOUND
from demid.spec import MaterialSpec
from demid.story.verdicts import (IN_COMBINATION, UNINFORMATIVE, factor_verdict, in_combination, material_answer,
                                  verdict_display, verdict_frame)


def _search(value, log):
    return math.log10(value) if log else value


def _touches(lo, hi, blo, bhi, log):
    span = _search(bhi, log) - _search(blo, log)
    tol = 0.005 * span
    return [side for side, hit in (("lower", _search(lo, log) <= _search(blo, log) + tol),
                                   ("upper", _search(hi, log) >= _search(bhi, log) - tol)) if hit]


def _at_limit(blo, bhi, limits):
    slack = 1e-6 * abs(bhi - blo)
    out = []
    if limits[0] is not None and limits[0] - blo >= -slack:
        out.append("lower")
    if limits[1] is not None and bhi - limits[1] >= -slack:
        out.append("upper")
    return out


def _rule(lo, hi, blo, bhi, log, limits, sides=None):
    """(verdict, width) by the documented rule; ``sides``: the bounds reached, when the table gives them."""
    if not (np.isfinite(lo) and np.isfinite(hi)):
        return "no admissible point", math.nan
    width = (_search(hi, log) - _search(lo, log)) / (_search(bhi, log) - _search(blo, log))
    if width >= 0.9:
        return "unresolved", width
    sides = _touches(lo, hi, blo, bhi, log) if sides is None else sides
    cut = [s for s in sides if s not in _at_limit(blo, bhi, limits)]
    if cut:
        return f"cut by the search range ({' and '.join(cut)} bound)", width
    return ("identified" if width <= 0.1 else "bounded"), width


@pytest.mark.parametrize("lower, upper, bounds, log, expected", [
    (3.0, 4.0, (0.0, 10.0), False, ("identified", 0.1)),
    (-4.0, -3.0, (-10.0, 0.0), False, ("identified", 0.1)),
    (1e3, 1e4, (1.0, 1e10), True, ("identified", 0.1)),
    (3.0, 4.0000001, (0.0, 10.0), False, ("bounded", 0.10000001)),
    (0.5, 9.5, (0.0, 10.0), False, ("unresolved", 0.9)),
    (10.0, 1e10, (1.0, 1e10), True, ("unresolved", 0.9)),      # touching the upper bound: unresolved first
    (0.5, 9.4999, (0.0, 10.0), False, ("bounded", 0.89999)),
    (0.05, 1.0, (0.0, 10.0), False, ("cut by the search range (lower bound)", 0.095)),   # 0.5 % of the range
    (0.0501, 1.0, (0.0, 10.0), False, ("identified", 0.09499)),
    (9.0, 9.95, (0.0, 10.0), False, ("cut by the search range (upper bound)", 0.095)),
    (0.0, 10.0 - 1.5, (0.0, 10.0), False, ("cut by the search range (lower bound)", 0.85)),
    (math.nan, 1.0, (0.0, 10.0), False, ("no admissible point", math.nan)),
])
def test_the_thresholds_are_inclusive_and_the_touch_is_half_a_percent(lower, upper, bounds, log, expected):
    verdict, width = factor_verdict(lower, upper, *bounds, log)
    assert verdict == expected[0]
    if math.isnan(expected[1]):
        assert math.isnan(width)
    else:
        assert width == pytest.approx(expected[1], rel=1e-12)
    assert _rule(lower, upper, *bounds, log, (None, None))[0] == verdict  # the rule written out agrees


def test_an_end_at_a_physical_limit_cuts_nothing_and_the_other_end_still_does():
    assert factor_verdict(0.0, 0.5, 0.0, 10.0, limits=(0.0, None)) == ("identified", 0.05)
    assert factor_verdict(9.5, 10.0, 0.0, 10.0, limits=(None, 10.0)) == ("identified", 0.05)
    assert factor_verdict(9.5, 10.0, 0.0, 10.0, limits=(0.0, None))[0] == "cut by the search range (upper bound)"
    assert factor_verdict(0.0, 8.0, 0.0, 10.0, limits=(0.0, 10.0)) == ("bounded", 0.8)
    assert factor_verdict(0.0, 8.0, 0.0, 10.0, limits=(None, 10.0))[0] == "cut by the search range (lower bound)"
    # the table's at_bound is read as given; "both" names both ends
    assert factor_verdict(4.0, 5.0, 0.0, 10.0, at_bound="both")[0] == "cut by the search range (lower and upper bound)"
    assert factor_verdict(0.0, 1.0, 0.0, 10.0, at_bound="none") == ("identified", 0.1)


def _interval(rng, blo, bhi, log):
    """An interval of a random kind inside [blo, bhi] (actual units)."""
    a, b = _search(blo, log), _search(bhi, log)
    kind = rng.integers(0, 6)
    share = [rng.uniform(0.01, 0.09), rng.uniform(0.12, 0.85), rng.uniform(0.91, 1.0)][rng.integers(0, 3)]
    if kind == 0:
        start = 0.0
    elif kind == 1:
        start = 1.0 - share
    else:
        start = rng.uniform(0.01, 0.99 - share) if share < 0.98 else 0.0
    lo, hi = a + start * (b - a), a + (start + share) * (b - a)
    to_actual = (lambda v: 10.0 ** v) if log else (lambda v: v)
    if kind == 5:
        return math.nan, math.nan
    return to_actual(lo), to_actual(hi)


@settings(max_examples=12, deadline=None, derandomize=True, phases=(Phase.explicit, Phase.generate))
@given(seed=st.integers(0, 100_000), k=st.integers(2, 4), n_obs=st.integers(1, 3), n_scen=st.integers(1, 3))
def test_the_verdict_table_its_display_and_the_answer_follow_the_rule(seed, k, n_obs, n_scen):
    rng = np.random.default_rng(seed)
    factors, bounds = {}, {}
    for i in range(k):
        log = bool(rng.integers(0, 2))
        if log:
            lo = 10.0 ** rng.uniform(-6, 3)
            hi = lo * 10.0 ** rng.uniform(0.5, 4)
        else:
            lo = rng.uniform(-1e3, 1e3) * 10.0 ** rng.integers(-3, 3)
            hi = lo + rng.uniform(0.1, 10) * 10.0 ** rng.integers(-2, 3)
        block = {"lower": float(lo), "upper": float(hi), "label": f"F{i}", "unit": "Pa" if i % 2 else None}
        if log:
            block["scale"] = "log"
        side = rng.integers(0, 4)
        if side == 1:
            block["limits"] = {"lower": float(lo)}
        elif side == 2:
            block["limits"] = {"upper": float(hi)}
        factors[f"f{i}"] = block
        bounds[f"f{i}"] = (float(lo), float(hi), log, (float(lo) if side == 1 else None, float(hi) if side == 2 else None))
    observables = [f"y{j}" for j in range(n_obs)]
    responses = {o: {"target": float(rng.choice([-1, 1]) * rng.uniform(1, 100)), "label": f"Y{o}"} for o in observables}
    scenarios = {}
    for s in range(n_scen):
        size = int(rng.integers(1, n_obs + 1))
        chosen = sorted(rng.choice(observables, size, replace=False), key=observables.index)
        scenarios[f"s{s}"] = {"observables": chosen, "tolerance": 0.05, "label": f"Scenario {s}"}
    spec = MaterialSpec.from_material("m", {"data": "x.csv", "design": {"type": "custom"}, "factors": factors,
                                            "responses": responses, "scenarios": scenarios}, grid_points=21)
    uninformative = {o: f"band covers {o}" for o in observables if rng.uniform() < 0.3}
    implausible = tuple(o for o in observables if rng.uniform() < 0.3)

    strict_rows, plausible_rows, expected = [], [], {}
    for sc in spec.scenarios:
        for f in spec.factors:
            blo, bhi, log, limits = bounds[f.name]
            s_lo, s_hi = _interval(rng, blo, bhi, log)
            at_bound = str(rng.choice(AT_BOUND))
            p_lo, p_hi = _interval(rng, blo, bhi, log)
            fraction = 0.0 if rng.uniform() < 0.15 else float(rng.uniform(0.1, 50))
            strict_rows.append({"scenario": sc.name, "factor": f.name, "lower": s_lo, "upper": s_hi,
                                "at_bound": at_bound})
            plausible_rows.append({"scenario": sc.name, "factor": f.name, "robust_lower": p_lo, "robust_upper": p_hi,
                                   "robust_fraction_pct": fraction})
            if fraction == 0:
                p_lo = p_hi = math.nan
            given_sides = {"none": [], "lower": ["lower"], "upper": ["upper"], "both": ["lower", "upper"]}[at_bound]
            expected[(sc.name, f.name)] = (_rule(s_lo, s_hi, blo, bhi, log, limits, given_sides),
                                           _rule(p_lo, p_hi, blo, bhi, log, limits), (s_lo, s_hi), (p_lo, p_hi))
    frame = verdict_frame(spec, pd.DataFrame(strict_rows), pd.DataFrame(plausible_rows), uninformative, implausible)
    assert list(frame.columns) == ["material", "scenario", "factor", "strict_lower", "strict_upper", "plausible_lower",
                                   "plausible_upper", "verdict", "reason"]
    assert [(r.scenario, r.factor) for r in frame.itertuples()] == list(expected)
    for row in frame.itertuples():
        sc = next(s for s in spec.scenarios if s.name == row.scenario)
        (s_verdict, s_width), (p_verdict, p_width), strict, plaus = expected[(row.scenario, row.factor)]
        assert row.material == "m"
        assert (row.strict_lower, row.strict_upper) == pytest.approx(strict, nan_ok=True)
        assert (row.plausible_lower, row.plausible_upper) == pytest.approx(plaus, nan_ok=True)
        if all(o in uninformative for o in sc.observables):
            assert row.verdict == UNINFORMATIVE
            assert row.reason == "; ".join(f"Y{o}: {uninformative[o]}" for o in sc.observables)
            continue
        assert row.verdict == p_verdict, (row, expected[(row.scenario, row.factor)])
        slipped = [f"Y{o}" for o in sc.observables if o in implausible]
        if p_verdict == "no admissible point":
            if slipped:
                assert row.reason.startswith(f"no point of the search range is plausible: the target of "
                                             f"{', '.join(slipped)} lies far outside every simulated value")
                continue
            assert row.reason.startswith("no point of the search range is plausible")
        else:
            quoted = re.search(r"([\d.e+-]+) % of the search range", row.reason)
            assert float(quoted.group(1)) == pytest.approx(100 * p_width, rel=5.1e-3, abs=1e-9), row.reason
        if s_verdict == p_verdict:
            assert "strictly" not in row.reason and "if surrogate and measurements were exact" not in row.reason
        elif s_verdict == "no admissible point":
            assert row.reason.endswith("; strictly (surrogate and measurements exact) no point meets every target")
        else:
            said = re.search(r"\[([-\d.e+]+), ([-\d.e+]+)\], ([\d.e+-]+) % of the search range\)?\Z", row.reason)
            assert said, row.reason
            assert float(said.group(1)) == pytest.approx(strict[0], rel=5e-4)
            assert float(said.group(2)) == pytest.approx(strict[1], rel=5e-4)
            assert float(said.group(3)) == pytest.approx(100 * s_width, rel=5.1e-3, abs=1e-9)
            assert ("identified if surrogate and measurements were exact" in row.reason) == (s_verdict == "identified")
            if s_verdict != "identified":
                assert f"; strictly (surrogate and measurements exact): {s_verdict}, [" in row.reason

    display = verdict_display(frame, spec)
    assert len(display) == len(frame)
    for shown, row in zip(display.itertuples(index=False), frame.itertuples()):
        f = spec.factor(row.factor)
        blo, bhi, log, _ = bounds[row.factor]
        assert shown[0] == f"Scenario {row.scenario[1:]}" and shown[1] == f.label
        for text, lo, hi in ((shown[3], row.strict_lower, row.strict_upper),
                             (shown[4], row.plausible_lower, row.plausible_upper)):
            if np.isfinite(lo) and np.isfinite(hi):
                a, b = re.fullmatch(r"\[(\S+), (\S+)\]", text).groups()
                assert float(a) == pytest.approx(lo, rel=5e-4) and float(b) == pytest.approx(hi, rel=5e-4)
            else:
                assert text == "–"
        if np.isfinite(row.plausible_lower):
            width = (_search(row.plausible_upper, log) - _search(row.plausible_lower, log)) / (
                _search(bhi, log) - _search(blo, log))
            assert shown[5] == pytest.approx(100 * width, rel=1e-9)
        else:
            assert math.isnan(shown[5])
        assert shown[6] == row.verdict and shown[7] == row.reason

    answer = material_answer(frame, spec)
    fullest = max(spec.scenarios, key=lambda sc: len(sc.observables))
    assert answer.scenario.name == fullest.name
    rows = frame[frame["scenario"] == fullest.name]
    assert answer.identified == [f for f, v in zip(rows["factor"], rows["verdict"]) if v == "identified"]
    assert answer.not_identified == [(f, v) for f, v in zip(rows["factor"], rows["verdict"]) if v != "identified"]
    assert answer.in_combination == []

    # unresolved factors with partners: the plausible set's combination changes the verdict, the strict one the reason
    unresolved = frame[frame["verdict"] == "unresolved"]
    plausible_partners, strict_partners = {}, {}
    for i, row in enumerate(unresolved.itertuples()):
        others = [f.name for f in spec.factors if f.name != row.factor][:1 + i % 2]
        (plausible_partners if i % 2 == 0 else strict_partners).setdefault(row.scenario, {})[row.factor] = others
    combined = in_combination(frame, spec, {"in_combination_plausible": plausible_partners,
                                            "in_combination": strict_partners})
    for before, after in zip(frame.itertuples(), combined.itertuples()):
        p = plausible_partners.get(before.scenario, {}).get(before.factor)
        s = strict_partners.get(before.scenario, {}).get(before.factor)
        if p:
            labels = " and ".join(spec.factor(o).label for o in p)
            assert after.verdict == f"unresolved alone; {IN_COMBINATION} with {labels}"
            assert after.reason == (f"{before.reason}; the plausible set is narrow along a combination of it with "
                                    f"{labels} (tables/combinations.csv)")
        elif s:
            labels = " and ".join(spec.factor(o).label for o in s)
            assert after.verdict == "unresolved"
            assert after.reason == (f"{before.reason}; identified in combination with {labels} if surrogate and "
                                    "measurements were exact (the strict set; the plausible set is not narrow along it)")
        else:
            assert (after.verdict, after.reason) == (before.verdict, before.reason)
    answer = material_answer(combined, spec)
    rows = combined[combined["scenario"] == fullest.name]
    assert answer.in_combination == [f for f, v in zip(rows["factor"], rows["verdict"]) if IN_COMBINATION in v]

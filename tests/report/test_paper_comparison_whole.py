"""The whole comparison table (demid.paper.paper_comparison) over generated published files and study tables:
one or two materials, one to three scenarios, two or three factors, every section of the published file (Table 2,
tolerances, Table 3, contractions of a fraction or a width, intervals, scenario sets with bounds and unresolved
factors, Pareto intervals), some of them naming a scenario, factor or response the study lacks.  Each row (in the
order of the sections, then of the file) is built here from the tables by hand, and every field is checked: the
quantity's text, material, published and reproduced numbers, the differences, the tolerance text, the pass flag
and whether the reproduction rounds to the printed digits (the rules of the module docstring, written out)."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest
from hypothesis import Phase, given, settings
from hypothesis import strategies as st

from demid.paper import COLUMNS, paper_comparison

SCENARIOS = ["simple", "rich", "full"]
RULES = {"r2": ("±0.0005", "abs", 0.0005), "rmse": ("±0.1 % rel", "rel", 0.001),
         "fraction": ("±0.1 % rel", "rel", 0.001), "contraction": ("±0.1 point", "abs", 0.1),
         "tolerance": ("equal", "abs", 1e-12), "unresolved": ("≥ 99.5 % of the search range", "abs", 0.5)}


def _expected_fields(kind, published, reproduced):
    """abs_diff, rel_diff, tolerance text, pass, printed_agrees of one row, by the documented rules."""
    if kind == "width":
        text, which, limit = (("±0.001 abs (value < 0.25)", "abs", 0.001) if abs(published) < 0.25 else
                              ("±0.5 % rel", "rel", 0.005))
    else:
        text, which, limit = RULES[kind]
    if not np.isfinite(reproduced):
        return math.nan, math.nan, text, False, False
    diff = max(0.0, published - reproduced) if kind == "unresolved" else abs(reproduced - published)
    rel = diff / abs(published) if published != 0 else math.nan
    judged = rel if which == "rel" and published != 0 else diff
    if kind == "unresolved":
        printed = reproduced >= published - 0.5
    else:
        shown = repr(float(published))
        decimals = len(shown.split(".")[1]) if "." in shown and "e" not in shown else 0
        printed = abs(reproduced - published) <= 0.5 * 10.0 ** -decimals * (1 + 1e-9)
    return diff, rel, text, judged <= limit, printed


def _study(rng, materials, scenarios, factors):
    ident = pd.DataFrame([{"material": m, "scenario": s, "tolerance": float(rng.choice([0.01, 0.05, 0.1])),
                           "feasible_fraction_pct": float(rng.uniform(0.1, 60)), "factor": f,
                           "lower": lo, "upper": lo + width, "width": width}
                          for m in materials for s in scenarios for f in factors
                          for lo, width in [(float(rng.uniform(-5, 5)), float(rng.uniform(0.01, 3)))]])
    # one fraction per scenario, as the study writes it on every factor row
    ident["feasible_fraction_pct"] = ident.groupby(["material", "scenario"])["feasible_fraction_pct"].transform("first")
    ident["tolerance"] = ident.groupby(["material", "scenario"])["tolerance"].transform("first")
    fit = pd.DataFrame([{"material": m, "response": r, "r2": float(rng.uniform(0.8, 1)),
                         "rmse": float(rng.uniform(0.01, 5))} for m in materials for r in ("y1", "y2")])
    pareto = {m: pd.DataFrame([{"factor": f, "lower": float(rng.uniform(-1, 0)), "upper": float(rng.uniform(0, 1)),
                                "n_points": 5} for f in factors]) for m in materials}
    return fit, ident, pareto


def _near(rng, value, decimals):
    """A published number: the reproduction off by a little (or a lot), printed to some decimals."""
    return round(float(value) * float(rng.choice([1.0, 1.0004, 0.99, 1.2])) + float(rng.choice([0, 1e-4])),
                 decimals)


def _cell(ident, material, scenario, factor, column):
    rows = ident.attrs["by_key"]
    return float(rows[(material, scenario, factor)][column]) if (material, scenario, factor) in rows else math.nan


def _fraction(ident, material, scenario):
    rows = [r for (m, s, _), r in ident.attrs["by_key"].items() if (m, s) == (material, scenario)]
    return float(rows[0]["feasible_fraction_pct"]) if rows else math.nan


@given(seed=st.integers(0, 10_000), n_materials=st.integers(1, 2), n_scenarios=st.integers(1, 3),
       n_factors=st.integers(2, 3), decimals=st.integers(1, 5))
@settings(max_examples=5, deadline=None, derandomize=True, phases=[Phase.explicit, Phase.generate])
def test_every_row_and_field_of_the_comparison(seed, n_materials, n_scenarios, n_factors, decimals):
    rng = np.random.default_rng(seed)
    materials = ["m", "n"][:n_materials]
    scenarios = SCENARIOS[:n_scenarios]
    factors = ["x", "y", "z"][:n_factors]
    fit, ident, pareto = _study(rng, materials, scenarios, factors)
    ident.attrs["by_key"] = {(r["material"], r["scenario"], r["factor"]): r for r in ident.to_dict("records")}
    asked_scenarios = scenarios + ["absent"]
    asked_factors = factors + ["w"]
    rows, published = [], {}

    def expect(quantity, material, pub, rep, kind):
        rows.append((quantity, material, float(pub), rep, kind))

    # Table 2
    fit_rows = {(row["material"], row["response"]): row for row in fit.to_dict("records")}
    published["table2"] = {}
    for m in materials + ["other"]:
        published["table2"][m] = {}
        for r in ("y1", "y3"):
            stats = {s: _near(rng, rng.uniform(0.5, 2), decimals) for s in ("r2", "rmse") if rng.random() < 0.8}
            published["table2"][m][r] = stats
            fitted = fit_rows.get((m, r))
            for stat in ("r2", "rmse"):
                if stat in stats:
                    expect(f"Table 2 {'RMSE' if stat == 'rmse' else 'R²'} {r}", m, stats[stat],
                           float(fitted[stat]) if fitted else math.nan, stat)
    # tolerances
    published["tolerances"] = {m: {s: float(rng.choice([0.01, 0.05])) for s in asked_scenarios} for m in materials}
    for m in materials:
        for s in asked_scenarios:
            expect(f"tolerance ε {s}", m, published["tolerances"][m][s],
                   _cell(ident, m, s, factors[0], "tolerance"), "tolerance")
    # Table 3
    published["table3"] = {m: {} for m in materials}
    for m in materials:
        for s in asked_scenarios:
            entry = {"feasible_fraction_pct": _near(rng, _fraction(ident, m, s) if s in scenarios else 5.0, decimals),
                     "width": {f: _near(rng, rng.uniform(0.05, 2), decimals) for f in asked_factors[::2]}}
            published["table3"][m][s] = entry
            expect(f"Table 3 feasible fraction [%] {s}", m, entry["feasible_fraction_pct"], _fraction(ident, m, s),
                   "fraction")
            for f, width in entry["width"].items():
                expect(f"Table 3 width {f} {s}", m, width, _cell(ident, m, s, f, "width"), "width")
    # contractions (from the first scenario to the last)
    simple, rich = scenarios[0], scenarios[-1]
    published["contractions"] = []
    for m in materials:
        for quantity, factor in (("fraction", None), ("width", factors[-1])):
            item = {"material": m, "from": simple, "to": rich, "quantity": quantity,
                    "value": round(float(rng.uniform(-90, -5)), 1)}
            if factor:
                item["factor"] = factor
                before, after = (_cell(ident, m, s, factor, "width") for s in (simple, rich))
                what = f"width {factor}"
            else:
                before, after = (_fraction(ident, m, s) for s in (simple, rich))
                what = "feasible fraction"
            published["contractions"].append(item)
            expect(f"contraction [%] {what}, {simple} → {rich}", m, item["value"], 100.0 * (after / before - 1.0),
                   "contraction")
    # intervals
    published["intervals"] = {m: {rich: {f: [_near(rng, _cell(ident, m, rich, f, "lower"), decimals),
                                             _near(rng, _cell(ident, m, rich, f, "upper"), decimals)]
                                         for f in factors}} for m in materials}
    for m in materials:
        for f in factors:
            low, high = published["intervals"][m][rich][f]
            expect(f"interval {f} lower end, {rich}", m, low, _cell(ident, m, rich, f, "lower"), "width")
            expect(f"interval {f} upper end, {rich}", m, high, _cell(ident, m, rich, f, "upper"), "width")
    # scenario sets: a fraction, bounds (upper first), unresolved factors as a share of the search range
    published["scenario_sets"] = {}
    published["search_domain"] = {}
    for m in materials:
        domain = {f: [-6.0, float(rng.choice([3.0, 6.0]))] for f in factors}
        published["search_domain"][m] = domain
        entry = {"feasible_fraction_pct": _near(rng, _fraction(ident, m, simple), decimals),
                 "lower": {factors[0]: _near(rng, _cell(ident, m, simple, factors[0], "lower"), decimals)},
                 "upper": {factors[1]: _near(rng, _cell(ident, m, simple, factors[1], "upper"), decimals)},
                 "unresolved": factors[::-1]}
        published["scenario_sets"][m] = {simple: entry}
        expect(f"feasible fraction [%] {simple}", m, entry["feasible_fraction_pct"], _fraction(ident, m, simple),
               "fraction")
        expect(f"upper bound {factors[1]} (≲), {simple}", m, entry["upper"][factors[1]],
               _cell(ident, m, simple, factors[1], "upper"), "width")
        expect(f"lower bound {factors[0]} (≳), {simple}", m, entry["lower"][factors[0]],
               _cell(ident, m, simple, factors[0], "lower"), "width")
        for f in factors[::-1]:
            low, high = domain[f]
            expect(f"{f} unresolved: width [% of search range], {simple}", m, 100.0,
                   100.0 * _cell(ident, m, simple, f, "width") / (high - low), "unresolved")
    # Pareto intervals: a material without a Pareto table and a factor it lacks are NaN
    cap = float(rng.choice([0.02, 0.05]))
    published["pareto"] = {}
    for m in materials + ["other"]:
        table = pareto.get(m)
        published["pareto"][m] = {"max_error": cap, "intervals": {}}
        for f in asked_factors:
            values = [float(table.set_index("factor").loc[f, end]) if table is not None and f in factors
                      else math.nan for end in ("lower", "upper")]
            printed = [_near(rng, v, decimals) if np.isfinite(v) else 0.5 for v in values]
            published["pareto"][m]["intervals"][f] = printed
            for end, pub, rep in zip(("lower", "upper"), printed, values):
                expect(f"Pareto interval {f} {end} end (error < {cap:g})", m, pub, rep, "width")

    got = paper_comparison(published, fit, ident, pareto)
    assert list(got.columns) == COLUMNS
    assert len(got) == len(rows)
    for (quantity, material, pub, rep, kind), (_, row) in zip(rows, got.iterrows()):
        assert (row["quantity"], row["material"]) == (quantity, material)
        assert row["published"] == pub
        if np.isfinite(rep):
            assert row["reproduced"] == pytest.approx(rep, rel=1e-12, abs=1e-12), quantity
        else:
            assert np.isnan(row["reproduced"]), quantity
        diff, rel, text, passes, printed = _expected_fields(kind, pub, row["reproduced"])
        for name, want in (("abs_diff", diff), ("rel_diff", rel)):
            if np.isnan(want):
                assert np.isnan(row[name]), (quantity, name)
            else:
                assert row[name] == pytest.approx(want, rel=1e-12, abs=1e-15), (quantity, name)
        assert row["tolerance"] == text, quantity
        assert bool(row["pass"]) is bool(passes), quantity
        assert bool(row["printed_agrees"]) is bool(printed), quantity


@pytest.mark.parametrize("decimals", [0, 1, 3, 6])
@pytest.mark.parametrize("published", [0.0, "0.0"])
def test_a_reproduction_at_the_slack_s_edge_still_rounds_to_the_print(decimals, published):
    """Half a unit of the last printed digit with its slack for binary representation (1 + 1e-9) is inside;
    the next float beyond is not.  Published 0, so the difference is the reproduced value itself, exactly."""
    from demid.paper import rounds_to

    edge = 0.5 * 10.0 ** -decimals * (1 + 1e-9)
    assert rounds_to(edge, published, decimals) and rounds_to(-edge, published, decimals)
    assert not rounds_to(np.nextafter(edge, 1.0), published, decimals)

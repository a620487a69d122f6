"""Every number a paper published, held against the pipeline's reproduction of it.

:func:`paper_comparison` reads the published numbers (``data/published.yaml``, see its
comments for the layout) and the pipeline's tables -- Table 2 (``surrogate_fit``),
Table 3 in long form (``identifiability``) and the Pareto intervals -- and returns one row
per published number with the reproduced value, the difference, a pass flag and
``printed_agrees``: whether the reproduction rounds to the printed value at the printed
decimals (quoted numbers in ``published.yaml`` keep their trailing zeros).

Tolerances: the smallest round bound that the demonstration meets with a margin, so a
drift in any reproduced number shows (``printed_agrees`` says, in addition, whether the
reproduction rounds to the printed digits):

* R²: within 0.0005 (absolute; half a unit of the printed third decimal);
* RMSE: within 0.1 % (relative);
* feasible fractions: within 0.1 % (relative);
* widths, interval ends and bounds: within 0.5 % (relative), or 0.001 (absolute) when the
  published value is below 0.25 (the paper's small bounds come from grids of about that step);
* contractions: within 0.1 percentage point, recomputed from the *reproduced* fractions or
  widths as 100 (richer / simpler - 1);
* tolerances epsilon of the scenarios: equal;
* "unresolved over the full search interval": the admissible width is at least 99.5 % of the
  search range.
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd

COLUMNS = ["quantity", "material", "published", "reproduced", "abs_diff", "rel_diff", "tolerance", "pass",
           "printed_agrees"]


def _num(value) -> float:
    return float(value) if value is not None else math.nan


def printed_decimals(value) -> int:
    """Decimals as printed: quoted numbers keep their trailing zeros ("3.980" -> 3); a YAML
    float's shortest repr is what was printed otherwise (0.0397 -> 4)."""
    text = str(value).strip()
    if "e" in text.lower():
        text = f"{float(text):f}".rstrip("0")
    return len(text.split(".", 1)[1]) if "." in text else 0


def rounds_to(reproduced: float, published, decimals: int) -> bool:
    """Whether ``reproduced`` rounds to ``published`` at ``decimals`` (within half a unit of
    the last printed digit, with a little slack for binary representation)."""
    if not np.isfinite(reproduced):
        return False
    half = 0.5 * 10.0 ** -decimals
    return bool(abs(reproduced - _num(published)) <= half * (1 + 1e-9))


def _rule(kind: str, published: float) -> tuple[str, callable]:
    """Readable tolerance and the test it stands for, by kind of number."""
    if kind == "r2":
        return "±0.0005", lambda d, r: d <= 0.0005
    if kind == "rmse":
        return "±0.1 % rel", lambda d, r: r <= 0.001
    if kind == "fraction":
        return "±0.1 % rel", lambda d, r: r <= 0.001
    if kind == "width":
        if abs(published) < 0.25:
            return "±0.001 abs (value < 0.25)", lambda d, r: d <= 0.001
        return "±0.5 % rel", lambda d, r: r <= 0.005
    if kind == "contraction":
        return "±0.1 point", lambda d, r: d <= 0.1
    if kind == "tolerance":
        return "equal", lambda d, r: d <= 1e-12
    if kind == "unresolved":
        return "≥ 99.5 % of the search range", lambda d, r: d <= 0.5
    raise ValueError(f"unknown kind of published number '{kind}'")


class _Rows:
    def __init__(self):
        self.rows = []

    def add(self, quantity: str, material: str, published, reproduced, kind: str,
            decimals: int | None = None) -> None:
        pub, rep = _num(published), _num(reproduced)
        text, test = _rule(kind, pub)
        if kind == "unresolved":           # published 100 % of the range; only falling short counts
            abs_diff = max(0.0, pub - rep) if np.isfinite(rep) else math.nan
        else:
            abs_diff = abs(rep - pub) if np.isfinite(rep) else math.nan
        rel_diff = abs_diff / abs(pub) if pub != 0 and np.isfinite(abs_diff) else math.nan
        ok = bool(np.isfinite(abs_diff) and test(abs_diff, rel_diff if np.isfinite(rel_diff) else abs_diff))
        if kind == "unresolved":           # "the full search range": the width is 100 % to 0 decimals
            printed = bool(np.isfinite(rep) and rep >= pub - 0.5)
        else:
            printed = rounds_to(rep, published, printed_decimals(published) if decimals is None else decimals)
        self.rows.append({"quantity": quantity, "material": material, "published": pub, "reproduced": rep,
                          "abs_diff": abs_diff, "rel_diff": rel_diff, "tolerance": text, "pass": ok,
                          "printed_agrees": printed})


def _scenario_rows(identifiability: pd.DataFrame, material: str, scenario: str) -> pd.DataFrame:
    sel = identifiability[(identifiability["material"] == material) & (identifiability["scenario"] == scenario)]
    return sel.set_index("factor")


def _fraction(identifiability, material, scenario) -> float:
    sel = _scenario_rows(identifiability, material, scenario)
    return float(sel["feasible_fraction_pct"].iloc[0]) if len(sel) else math.nan


def _column(identifiability, material, scenario, factor, column) -> float:
    sel = _scenario_rows(identifiability, material, scenario)
    return float(sel.loc[factor, column]) if factor in sel.index else math.nan


def _scenario_set_rows(out: _Rows, identifiability: pd.DataFrame, material: str, scenario: str, entry: dict,
                       domain: dict) -> None:
    """Rows of one ``scenario_sets`` entry: fraction, bounds, factors unresolved over their search range."""
    if "feasible_fraction_pct" in entry:
        out.add(f"feasible fraction [%] {scenario}", material, entry["feasible_fraction_pct"],
                _fraction(identifiability, material, scenario), "fraction")
    for end, sign in (("upper", "≲"), ("lower", "≳")):
        for factor, value in (entry.get(end) or {}).items():
            out.add(f"{end} bound {factor} ({sign}), {scenario}", material, value,
                    _column(identifiability, material, scenario, factor, end), "width")
    for factor in entry.get("unresolved") or []:
        low, high = domain[factor]
        width = _column(identifiability, material, scenario, factor, "width")
        out.add(f"{factor} unresolved: width [% of search range], {scenario}", material, 100.0,
                100.0 * width / (float(high) - float(low)), "unresolved")


def paper_comparison(published: dict, surrogate_fit: pd.DataFrame, identifiability: pd.DataFrame,
                     pareto_intervals: dict[str, pd.DataFrame]) -> pd.DataFrame:
    """One row per published number: ``quantity, material, published, reproduced, abs_diff,
    rel_diff, tolerance, pass, printed_agrees``.

    ``surrogate_fit`` has ``material, response, r2, rmse, ...``; ``identifiability`` has
    ``material, scenario, tolerance, feasible_fraction_pct, factor, lower, upper, width``;
    ``pareto_intervals[material]`` has ``factor, lower, upper, n_points``.  A number whose
    reproduction is missing gets NaN and fails.  Verified against hand-made tables in
    ``tests/report/test_paper.py``.
    """
    out = _Rows()
    fits = surrogate_fit.set_index(["material", "response"])

    for material, responses in (published.get("table2") or {}).items():
        for response, stats in responses.items():
            for stat, kind in (("r2", "r2"), ("rmse", "rmse")):
                if stat in stats:
                    key = (material, response)
                    rep = fits.loc[key, stat] if key in fits.index else math.nan
                    out.add(f"Table 2 {stat.upper() if stat == 'rmse' else 'R²'} {response}", material,
                            stats[stat], rep, kind)

    for material, scenarios in (published.get("tolerances") or {}).items():
        for scenario, eps in scenarios.items():
            sel = _scenario_rows(identifiability, material, scenario)
            rep = float(sel["tolerance"].iloc[0]) if len(sel) else math.nan
            out.add(f"tolerance ε {scenario}", material, eps, rep, "tolerance")

    for material, scenarios in (published.get("table3") or {}).items():
        for scenario, entry in scenarios.items():
            out.add(f"Table 3 feasible fraction [%] {scenario}", material, entry["feasible_fraction_pct"],
                    _fraction(identifiability, material, scenario), "fraction")
            for factor, width in (entry.get("width") or {}).items():
                out.add(f"Table 3 width {factor} {scenario}", material, width,
                        _column(identifiability, material, scenario, factor, "width"), "width")

    for item in published.get("contractions") or []:
        material, simple, rich = item["material"], item["from"], item["to"]
        if item["quantity"] == "fraction":
            before, after = (_fraction(identifiability, material, s) for s in (simple, rich))
            what = "feasible fraction"
        else:
            before, after = (_column(identifiability, material, s, item["factor"], "width") for s in (simple, rich))
            what = f"width {item['factor']}"
        rep = 100.0 * (after / before - 1.0) if before else math.nan
        out.add(f"contraction [%] {what}, {simple} → {rich}", material, item["value"], rep, "contraction")

    for material, scenarios in (published.get("intervals") or {}).items():
        for scenario, factors in scenarios.items():
            for factor, (low, high) in factors.items():
                out.add(f"interval {factor} lower end, {scenario}", material, low,
                        _column(identifiability, material, scenario, factor, "lower"), "width")
                out.add(f"interval {factor} upper end, {scenario}", material, high,
                        _column(identifiability, material, scenario, factor, "upper"), "width")

    for material, scenarios in (published.get("scenario_sets") or {}).items():
        domain = (published.get("search_domain") or {}).get(material, {})
        for scenario, entry in scenarios.items():
            _scenario_set_rows(out, identifiability, material, scenario, entry, domain)

    for material, entry in (published.get("pareto") or {}).items():
        table = pareto_intervals.get(material)
        summary = table.set_index("factor") if table is not None else pd.DataFrame()
        for factor, (low, high) in entry["intervals"].items():
            for end, value in (("lower", low), ("upper", high)):
                rep = float(summary.loc[factor, end]) if factor in summary.index else math.nan
                out.add(f"Pareto interval {factor} {end} end (error < {entry['max_error']:g})", material, value,
                        rep, "width")

    return pd.DataFrame(out.rows, columns=COLUMNS)

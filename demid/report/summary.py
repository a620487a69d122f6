"""The report's first section: per material, the answer a researcher acts on.

A recommended parameter set, the admissible interval and a verdict per factor and scenario,
the criticism verdicts in one line each and the next step.  Every number is read from the
results tree; nothing is recomputed here.  The verdicts on the plausible interval and the advice
are :mod:`demid.story`'s (``tables/verdicts.csv``, ``tables/advice.csv``, the verdict rule in
:mod:`demid.story.verdicts`, where the recommended point stands in :mod:`demid.story.recommended`); the
criticism in a line per response is :mod:`.model_criticism`'s.  This module writes the combination lines and
lays the section out.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import pandas as pd

from ..io import read_parquet
from ..story.words import in_order
from .glossary import term
from .markdown import markdown_table
from .model_criticism import criticism_lines

if TYPE_CHECKING:
    from .context import ReportContext

def combination_lines(combinations: dict, spec) -> list[str]:
    """One line per scenario and set: what the set identifies in combination (its text in
    ``combinations/{material}.json``), and a band's curve as a table row of values."""
    lines = []
    labels = {sc.name: sc.label for sc in spec.scenarios}
    for entry in combinations.get("sets", []):
        line = f"*{labels.get(entry['scenario'], entry['scenario'])}*, {entry['set']} set: {entry['text']}"
        curve = entry.get("curve")
        if curve and entry.get("identified") and "curved band" in entry["text"]:
            along, across = spec.factor(curve["along"]), spec.factor(curve["across"])
            pairs = "; ".join(f"{a:.3g} → {m:.3g} [{lo:.3g}, {hi:.3g}]" for a, lo, m, hi in
                              zip(curve["along_actual"], curve["lower"], curve["mid"], curve["upper"]))
            line += f" Curve ({along.label} → {across.label} mid [lowest, highest]): {pairs}."
        lines.append(line)
    return lines


def summary(report: ReportContext) -> list:
    """Per material: recommended set, verdict per factor and scenario, criticism, next step.

    Verdicts and advice are read from ``tables/verdicts.csv`` and ``tables/advice.csv`` (rule
    ``story``): the same rows level 2 and the next-wave section show."""
    from ..sampling.residuals import PLAUSIBLE_DEFINITION
    from ..story import StudyAdvice, verdict_display
    from ..story.verdicts import UNINFORMATIVE_TEXT, VERDICT_TEXT

    verdicts_all = report.csv("verdicts.csv")
    advice = StudyAdvice.from_frame(report.csv("advice.csv"))
    answers = [_answer_line(report, m, verdicts_all, advice) for m in report.materials]
    parts = [report.md("## Summary\n\n" + "\n".join(f"- {a}" for a in answers if a) + "\n\n"
                       "**How to read it.** Per factor and observable scenario the "
                       f"{term('plausible interval', 'plausible-set')} is judged; the strict interval (the set if "
                       "surrogate and measurements were exact: section "
                       f"*Admissible sets*{report.paper('Table 3')}) stands beside it. "
                       f"{term('Plausible set', 'plausible-set')}: "
                       + PLAUSIBLE_DEFINITION + " Verdicts: " + VERDICT_TEXT + " " + UNINFORMATIVE_TEXT
                       + " Other terms: [Terms](#Terms).")]
    for m in report.materials:
        spec = report.specs()[m]
        lines = [f"### {spec.label}", ""]
        info = report.json(report.root / "criticism" / f"{m}.json")
        unc = report.json(report.root / "uncertainty" / f"{m}.json")
        level2 = info.get("level2") or {}
        verdicts = (verdicts_all[verdicts_all["material"] == m] if verdicts_all is not None
                    else pd.DataFrame(columns=["scenario", "factor", "verdict"]))
        widened = {(i.factor, i.bound) for i in advice.items if i.material == m and i.kind == "widen"}
        lines += _recommended_lines(report, spec, unc.get("recommended"), verdicts, level2, widened)
        for o, why in in_order(unc.get("uninformative") or {}, spec.response_names):
            lines.append(f"{spec.response_labels.get(o, o)} is an **uninformative observable**: {why}.")
        if len(verdicts):
            lines += ["", markdown_table(verdict_display(verdicts, spec), 3)]
        combos = report.json(report.root / "combinations" / f"{m}.json")
        combo_lines = combination_lines(combos, spec)
        if combo_lines:
            lines += ["", f"**What is identified in {term('combination', 'combination')}** (principal axes of each "
                      "set in coded units; "
                      "tables/combinations.csv):", ""] + [f"- {c}" for c in combo_lines]
        crit = criticism_lines(info, spec)
        if crit:
            lines += ["", "**What the models get wrong:**", ""] + [f"- {c}" for c in crit]
        decision, also = advice.next_step(m)
        if decision:
            lines += ["", "**Next step:**", "", f"- {decision}"]
        if also:
            lines += ["", "**Also:**", ""] + [f"- {s}" for s in also]
        parts.append(report.md("\n".join(lines)))
    return parts


def _answer_line(report: ReportContext, m: str, verdicts_all: pd.DataFrame | None, advice) -> str:
    """One material's answer in a line (:func:`~demid.story.verdicts.material_answer`: with its fullest scenario,
    the factors identified, those not with their verdict) and the next step."""
    from ..story.verdicts import material_answer

    spec = report.specs()[m]
    answer = material_answer(None if verdicts_all is None else verdicts_all[verdicts_all["material"] == m], spec)
    if answer is None:
        return ""
    label = {f.name: f.label for f in spec.factors}
    combined = ", ".join(label[f] for f in answer.in_combination)
    text = (f"**{spec.label}**, with *{answer.scenario.label}*: identified: "
            f"{', '.join(label[f] for f in answer.identified) or 'none'}"
            + (f"; in {term('combination', 'combination')} only: {combined}" if combined else "")
            + f"; not identified: {', '.join(f'{label[f]} {v}' for f, v in answer.not_identified) or 'none'}.")
    decision, _ = advice.next_step(m)
    return text + (f" **Next step:** {decision}" if decision else "")


def _recommended_lines(report: ReportContext, spec, recommended: dict | None, verdicts: pd.DataFrame, level2: dict,
                       widened: set = frozenset()) -> list[str]:
    """The most robust plausible point with each factor's plausible interval beside it, to the digits that
    interval supports; plainly said when the set is wide, or when no point meets every target, or when the
    point sits on a search bound or outside the runs (``widened``: the (factor, side) pairs advised wider)."""
    import numpy as np

    from ..uncertainty.recommended import digits_for
    from ..story.words import unit_text
    from ..story.recommended import point_on_edge_text

    if not recommended:
        return []
    scenario = next((sc for sc in spec.scenarios if sc.name == recommended["scenario"]), None)
    label = scenario.label if scenario else recommended["scenario"]
    rows = verdicts[verdicts["scenario"] == recommended["scenario"]].set_index("factor") if len(verdicts) else None
    lines = []
    strict_empty = rows is not None and len(rows) and rows["strict_lower"].isna().all()
    if strict_empty:
        lines.append(f"With every observable of *{label}* no point of the search range is admissible, so there "
                     "are no admissible intervals.")
    if not recommended["plausible"]:
        over = ", ".join(spec.response_labels.get(o, o) for o in level2.get("observables", []))
        text = (f"**No parameter set meets every target.** No point is plausible for *{label}* either: at every "
                f"point some observable lies outside its plausible band (smallest implausibility "
                f"{recommended['implausibility']:.3g} > 1).")
        if level2.get("best_point"):
            best = level2["best_point"]
            point = ", ".join(f"{spec.factor(f).label} = {best[f]:.4g}" for f in spec.factor_names if f in best)
            text += (f" The closest point (smallest largest relative error over {over}) is {point}; see the "
                     "level-2 criticism and the next step below.")
        return [text] + lines
    shown, wide, unresolved = [], [], []
    for f in spec.factors:
        value = recommended["point"][f.name]
        lo = hi = float("nan")
        if rows is not None and f.name in rows.index:
            lo, hi = float(rows.loc[f.name, "plausible_lower"]), float(rows.loc[f.name, "plausible_upper"])
            verdict = str(rows.loc[f.name, "verdict"])
            if verdict != "identified":
                wide.append(f.label)
            if verdict == "unresolved":
                unresolved.append(f.label)
        digits = digits_for(hi - lo)
        unit = f" {unit_text(f.unit)}" if f.unit != "-" else ""
        interval = f" (plausible {lo:.{digits}f}–{hi:.{digits}f})" if np.isfinite(lo) else ""
        shown.append(f"{f.label} = {value:.{digits}f}{unit}{interval}")
    head = ("**Recommended parameter set**" if level2.get("feasible", True) or not strict_empty else
            "**No parameter set meets every target** within the tolerance; counting the surrogate's and the "
            "measurements' uncertainty, the most plausible point")
    text = (f"{head} (the point of the plausible set of *{label}* with the largest margin to every band, "
            f"{term('implausibility', 'implausibility')} {recommended['implausibility']:.2f}): "
            + "; ".join(shown) + ".")
    if unresolved:
        names = ", ".join(unresolved[:-1]) + " and " + unresolved[-1] if len(unresolved) > 1 else unresolved[0]
        them = "it" if len(unresolved) == 1 else "each"
        text += (f" *{label}* does not pin down {names}: its plausible set spans (almost) the whole search range "
                 f"of {them}.")
    if wide:
        text += (f" The plausible set is wide in {', '.join(wide)}: any point of those intervals matches the "
                 "measurements as well, so this point is one choice among many.")
    edge = point_on_edge_text(spec, recommended["point"], _design_runs(report, spec),
                              {} if rows is None else rows["verdict"].astype(str).to_dict(), widened)
    return [text] + (["", edge, ""] if edge else []) + lines


def _design_runs(report: ReportContext, spec):
    """The material's design runs (factor columns, actual units), or None before validation."""
    path = report.root / "validated" / f"{spec.name}.parquet"
    return read_parquet(path)[spec.factor_names].to_numpy(dtype=float) if path.is_file() else None

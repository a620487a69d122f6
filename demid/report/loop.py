"""The report's sections of the simulation loop: the waves simulated so far and why the loop stopped, and what to
simulate next."""

from __future__ import annotations

from typing import TYPE_CHECKING

import pandas as pd

from ..precision import counted, q2_text
from .markdown import keys_labelled, markdown_table

if TYPE_CHECKING:
    from .context import ReportContext


def waves(report: ReportContext, m: str) -> list:
    """A simulated material's waves (``waves/summary_{m}.json``): per wave the runs simulated, failed and
    analysed, the surrogate and its Q², the plausible share of Omega and each factor's plausible interval; the
    runs-per-wave figure; and why the loop stopped, in the words of the study's advice."""
    from ..story import StudyAdvice

    summary = report.json(report.root / "waves" / f"summary_{m}.json")
    if not summary.get("waves"):
        return []
    spec = report.specs()[m]
    rows = []
    for w in summary["waves"]:
        row = {"wave": w["wave"], "runs simulated": w["simulated"], "failed": w["failed"],
               "analysed": w["analysed"], "surrogate": w["surrogate"],
               "Q²": ", ".join(f"{spec.response_labels.get(r, r)} " + q2_text(q)
                               for r, q in w["q2"].items()),
               "plausible % of Ω": w["plausible_fraction_of_omega_pct"]}
        for f in spec.factors:
            lo, hi = w["plausible"].get(f.name, [None, None])
            row[f"plausible {f.label}"] = "empty" if lo is None else f"{lo:.4g}–{hi:.4g}"
        rows.append(row)
    scenarios = {sc.name: sc.label for sc in spec.scenarios}
    used = ", ".join(dict.fromkeys(f"*{scenarios.get(w['scenario'], w['scenario'])}*" for w in summary["waves"]))
    last = summary["waves"][-1]
    lines = ["### Waves", "",
             f"demid simulated {last['simulated']} runs in {counted(len(summary['waves']), 'wave')} ({last['failed']} "
             f"failed); wave 1 is the declared design, each later wave the runs the one before proposed. Per "
             f"wave: the runs simulated up to it, the failed ones among them, the runs its analysis used, its "
             f"surrogate and the surrogate's leave-one-out Q², and the plausible set of {used} as a share of the "
             "search range Ω with each factor's plausible interval.", "",
             markdown_table(pd.DataFrame(rows), 3)]
    told = StudyAdvice.from_frame(report.csv("advice.csv")).texts(m, ("stop", "next_runs", "recalibrate"))
    decision = summary.get("decision")
    if decision:
        stop_line = next((t for t in told if decision["reason"] in t), decision["reason"])
        lines += ["", f"**{decision_heading(decision, last['wave'])}:** {stop_line}"]
    parts = [report.md("\n".join(lines))]
    parts.append(report.image(report.root / "figures" / f"waves_{m}.png",
                              f"The plausible share of Ω (solid: the table's; dashed: strict) against the runs "
                              f"simulated, and per factor each wave's plausible interval (thick; strict: thin) beside "
                              f"the runs that wave simulated (dots), over the last wave's plausible interval (band), "
                              f"of {report.label(m)}"))
    return parts


def next_wave(report: ReportContext, m: str) -> list:
    """The proposed next wave (only for materials with ``next_runs``)."""
    reasons = report.root / "next_wave" / "reasons.json"
    runs = report.csv("next_runs.csv")
    if runs is None or not reasons.is_file() or not len(runs[runs["material"] == m]):
        return []
    from ..story import NEXT_WAVE_KINDS, StudyAdvice

    reason = report.json(reasons).get(m, "")
    advice = " ".join(StudyAdvice.from_frame(report.csv("advice.csv")).texts(m, NEXT_WAVE_KINDS))
    sub = runs[runs["material"] == m].dropna(axis=1, how="all")
    spec = report.specs()[m]
    sub = keys_labelled(sub, spec)
    from ..precision import coordinate_text

    for f in spec.factors:
        if f.name in sub:
            sub[f.name] = [coordinate_text(float(v), f.lower, f.upper) for v in sub[f.name]]
    sub = sub.rename(columns={f.name: f.label for f in spec.factors})
    return [report.md("### What to simulate next\n\n" + report.speak(reason, m) + (" " + advice if advice else "")
                      + " Once simulated, they are studied in the next domain (tables/next_domain.csv) with the "
                      "earlier runs inside it (`design: {type: custom}`).\n\n"
                      + markdown_table(sub.drop(columns="material")))]


def decision_heading(decision: dict, wave: int) -> str:
    """The words before the last wave's decision: why the loop stopped where its advice is to stop, else (it ended
    with its budget spent, or at the model's limit, advising more runs or a recalibration) that the line is advice."""
    if decision.get("action") == "stop":
        return f"Why the loop stopped after wave {wave}"
    return f"The loop ended after wave {wave}; what it advises"

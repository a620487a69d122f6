"""The report's section "What the model gets wrong": level 1 (each surrogate against the simulation runs), level
2 (the calibrated simulation against the experiment) and the reference point, as the criticism step wrote them."""

from __future__ import annotations

from typing import TYPE_CHECKING

from .glossary import term
from .markdown import keys_labelled, markdown_table

if TYPE_CHECKING:
    from .context import ReportContext


def criticism(report: ReportContext, m: str) -> list:
    """What the surrogate and the calibrated simulation get wrong, the named cause and the gain."""
    summary = report.root / "criticism" / f"{m}.json"
    if not summary.is_file():
        return []
    import json

    info = json.loads(summary.read_text(encoding="utf-8"))
    lines = ["### What the model gets wrong", "",
             "**Level 1 — surrogate against the simulation runs.** Each quadratic is tested against a fixed "
             "catalogue of causes (a missing cubic or mixed term, a response transform, an outlying run, "
             "run-order drift, non-constant variance) with family-wise error control; a finding is kept only "
             f"with its extension and the measured gain (leave-one-out RMSE, {term('AICc', 'aicc')}); a "
             f"surrogate whose {term('Q²', 'q2')} is below 0 does not predict."]
    from ..precision import percent_text
    from ..story.words import in_order, labelled
    from .summary import VERDICT_WORDS, unreliable_surrogate_lines, verdict_sentence

    spec = report.specs()[m]
    for response, res in in_order(info["level1"], spec.response_names):
        name = spec.response_labels.get(response, response)
        if res.get("verdict_message"):
            lines += [f"- {name} — **{VERDICT_WORDS.get(res['verdict'], res['verdict'])}**: "
                      + labelled(verdict_sentence(response, res), spec)]
        elif res["messages"]:
            lines += [f"- {name}: " + labelled(" ".join(res["messages"]), spec)]
        else:
            lines += [f"- {name}: nothing found by the catalogue tests."]
    run_order = info.get("run_order") or {}
    if run_order.get("drift_tested") is False:
        lines += [f"- Run order: {labelled(run_order['message'], spec)}"]
    lines += [f"- {w}" for w in unreliable_surrogate_lines(info, spec)]
    findings = report.csv("criticism.csv")
    if findings is not None and "cause" in findings.columns:
        findings = findings[findings["cause"] != "none"]
    if findings is not None and "response" in findings.columns and len(findings[findings["material"] == m]):
        cols = [c for c in ["response", "cause", "detail", "p_value", "loo_rmse_baseline", "loo_rmse_extended",
                            "delta_aicc"] if c in findings.columns]
        shown = keys_labelled(findings[findings["material"] == m][cols], spec)
        shown["cause"] = shown["cause"].astype(str).str.replace(";", ", ").str.replace("_", " ")
        if "detail" in shown:
            shown["detail"] = shown["detail"].fillna("").astype(str).map(lambda t: report.speak(t, m))
        lines += ["", markdown_table(shown)]
    level2 = info.get("level2")
    if level2:
        from ..story import LEVEL2_KINDS, StudyAdvice

        advice = StudyAdvice.from_frame(report.csv("advice.csv")).texts(m, LEVEL2_KINDS)
        lines += ["", "**Level 2 — calibrated simulation against the experiment.** "
                  + " ".join([labelled(level2.get("finding", ""), spec), *advice])]
    for pos in info.get("reference_point") or []:
        errs = ", ".join(f"{spec.response_labels.get(o, o)} {'+' if e > 0 else ''}{percent_text(e)}"
                         for o, e in in_order(pos["errors"]))
        if pos["inside"]:
            where = "lies inside the admissible set"
        elif pos["nearest_admissible"] is None:
            where = "cannot lie in it: the admissible set is empty"
        else:
            near = ", ".join(f"{spec.factor(f).label} = {v:.4g}" for f, v in in_order(pos["nearest_admissible"],
                                                                                     spec.factor_names))
            where = (f"lies outside it, {pos['distance_pct_of_range']:.1f} % of the search range from the "
                     f"nearest admissible point ({near})")
        scenario = report.speak(pos["scenario"], m)
        lines.append(f"- Reference point vs scenario *{scenario}*: it {where} (errors {errs}).")
    parts = [report.md("\n".join(lines))]
    parts.append(report.image(report.root / "figures" / f"residuals_{m}.png",
                             f"Residuals of each response surface of {report.label(m)} against fitted value, run order and normal quantiles"))
    return parts


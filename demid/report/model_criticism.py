"""The report's section "What the model gets wrong": level 1 (each surrogate against the simulation runs), level
2 (the calibrated simulation against the experiment) and the reference point, as the criticism step wrote them;
and the same in a line per response for the summary (:func:`criticism_lines`)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..story.verdicts import reference_within, unpredictive_responses
from ..story.words import in_order, labelled, level2_own_tolerances, level2_within
from .glossary import term
from .markdown import keys_labelled, markdown_table

if TYPE_CHECKING:
    from .context import ReportContext


#: The criticism verdicts in the report's words.
VERDICT_WORDS = {"adequate": "adequate (within the tests' power)", "defect": "defect named",
                 "unexplained": "misfit unexplained", "does_not_predict": "does not predict",
                 "ambiguous": "ambiguous cause"}


def verdict_sentence(response: str, res: dict) -> str:
    """The verdict message without its leading "<response>: <verdict> — " (the report names both)."""
    text = res.get("verdict_message", "")
    head = f"{response}: "
    if text.startswith(head) and " — " in text:
        return text.split(" — ", 1)[1]
    return text[len(head):] if text.startswith(head) else text


def unreliable_surrogate_lines(info: dict, spec) -> list[str]:
    """One warning per scenario (and the Pareto front) that relies on a surrogate that does not predict."""
    bad = unpredictive_responses(info.get("level1") or {})
    lines = []
    for sc in spec.scenarios:
        used = [r for r in sc.observables if r in bad]
        if used:
            names = ", ".join(spec.response_labels.get(r, r) for r in used)
            lines.append(f"⚠ Scenario *{sc.label}* uses {names}, whose surrogate does not predict left-out runs "
                         f"(Q² < 0): its admissible set should not be used to decide admissibility.")
    pareto = spec.pareto
    used = [r for r in (pareto.error_of, pareto.minimise) if r in bad] if pareto is not None else []
    if used:
        names = ", ".join(spec.response_labels.get(r, r) for r in dict.fromkeys(used))
        lines.append(f"⚠ The Pareto front uses {names}, whose surrogate does not predict left-out runs (Q² < 0): "
                     f"treat the front as indicative only.")
    return lines


def criticism_lines(info: dict, spec) -> list[str]:
    """One line per response (surrogate vs runs) and one for simulation vs experiment."""
    lines = []
    level1 = info.get("level1", {})
    for response in [r for r in spec.response_names if r in level1]:
        res = level1[response]
        label = spec.response_labels.get(response, response)
        if res.get("verdict_message"):
            lines.append(f"Surrogate of {label} — **{VERDICT_WORDS.get(res['verdict'], res['verdict'])}**: "
                         + labelled(verdict_sentence(response, res), spec))
        elif res["messages"]:
            lines.append(f"Surrogate of {label}: " + labelled(" ".join(res["messages"]), spec))
        else:
            lines.append(f"Surrogate of {label}: no defect found — the quadratic fits the simulation runs.")
    run_order = info.get("run_order") or {}
    if run_order.get("drift_tested") is False:
        lines.append(f"Run order: {run_order['message']}")
    lines += unreliable_surrogate_lines(info, spec)
    level2 = info.get("level2")
    if level2:
        from ..criticism.messages import level2_miss_text
        from ..precision import percent_text

        tol = 100 * level2["tolerance"]
        own = level2_own_tolerances(level2)
        uniform = own is None
        within = level2_within(level2, spec)
        best = percent_text(level2["best_max_error"])
        own_miss = labelled(level2_miss_text(level2["best_errors"], level2["tolerance"], own), spec) if not uniform else ""
        if level2["feasible"]:
            lines.append(f"Simulation vs experiment: every target can be met within {within} "
                         f"(best point misses {f'by at most {best}' if uniform else own_miss}).")
        else:
            lines.append(f"Simulation vs experiment: the targets cannot all be met within {within}; the best point "
                         f"misses {f'by {best}' if uniform else own_miss}"
                         + (f", limited by {spec.response_labels.get(limit, limit)}"
                            if (limit := level2.get("bottleneck")) else "") + ".")
        if level2.get("reference_max_error") is not None:
            lines.append(f"Reference point: largest error {percent_text(level2['reference_max_error'])} "
                         f"({'within' if reference_within(level2) else 'outside'} "
                         + (f"the {tol:g} % tolerance)." if uniform else
                            level2_within(level2, spec, brackets=False) + ")."))
        # a best point on a bound is told by the advice (demid.story), where widening can reach something
        lines += list(level2.get("extrapolation") or [])
    return lines


def criticism(report: ReportContext, m: str) -> list:
    """What the surrogate and the calibrated simulation get wrong, the named cause and the gain."""
    summary = report.root / "criticism" / f"{m}.json"
    if not summary.is_file():
        return []
    info = report.json(summary)
    lines = ["### What the model gets wrong", "",
             "**Level 1 — surrogate against the simulation runs.** Each quadratic is tested against a fixed "
             "catalogue of causes (a missing cubic or mixed term, a response transform, an outlying run, "
             "run-order drift, non-constant variance) with family-wise error control; a finding is kept only "
             f"with its extension and the measured gain (leave-one-out RMSE, {term('AICc', 'aicc')}); a "
             f"surrogate whose {term('Q²', 'q2')} is below 0 does not predict."]
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
    lines += _findings_table(report, m)
    level2 = info.get("level2")
    if level2:
        from ..story import LEVEL2_KINDS, StudyAdvice

        advice = StudyAdvice.from_frame(report.csv("advice.csv")).texts(m, LEVEL2_KINDS)
        lines += ["", "**Level 2 — calibrated simulation against the experiment.** "
                  + " ".join([labelled(level2.get("finding", ""), spec), *advice])]
    lines += _reference_point_lines(report, m, info.get("reference_point") or [])
    parts = [report.md("\n".join(lines))]
    parts.append(report.image(report.root / "figures" / f"residuals_{m}.png",
                              f"Residuals of each response surface of {report.label(m)} against fitted value, run order and normal quantiles"))
    return parts


def _findings_table(report: ReportContext, m: str) -> list[str]:
    """The named causes of ``m`` (tables/criticism.csv, rows with a cause) as a table, or nothing."""
    findings = report.csv("criticism.csv")
    if findings is not None and "cause" in findings.columns:
        findings = findings[findings["cause"] != "none"]
    if findings is None or "response" not in findings.columns or not len(findings[findings["material"] == m]):
        return []
    cols = [c for c in ["response", "cause", "detail", "p_value", "loo_rmse_baseline", "loo_rmse_extended",
                        "delta_aicc"] if c in findings.columns]
    shown = keys_labelled(findings[findings["material"] == m][cols], report.specs()[m])
    shown["cause"] = shown["cause"].astype(str).str.replace(";", ", ").str.replace("_", " ")
    if "detail" in shown:
        shown["detail"] = shown["detail"].fillna("").astype(str).map(lambda t: report.speak(t, m))
    return ["", markdown_table(shown)]


def _reference_point_lines(report: ReportContext, m: str, positions: list[dict]) -> list[str]:
    """Per scenario, where the reference point lies against the admissible set, with its errors."""
    from ..precision import percent_text

    spec = report.specs()[m]
    lines = []
    for pos in positions:
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
        lines.append(f"- Reference point vs scenario *{report.speak(pos['scenario'], m)}*: it {where} "
                     f"(errors {errs}).")
    return lines

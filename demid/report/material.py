"""The report's sections of one material that stand before the analyses: its table check (with the
transcription check), the admissible sets and response surfaces drawn, and the Pareto trade-off."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..precision import counted
from .markdown import keys_labelled, markdown_table, short_number

if TYPE_CHECKING:
    from .context import ReportContext


def table_check(report: ReportContext, m: str) -> list:
    """What the table check found (``validated/{m}.json``), the transcription check beside it."""
    summary = report.root / "validated" / f"{m}.json"
    if not summary.is_file():
        return []
    info = report.json(summary)
    types = ", ".join(f"{v} {k}" for k, v in info["point_types"].items())
    text = f"**Table check.** {info['n_runs']} runs ({types}); every factor value sits on a level of the declared design and inside the search bounds."
    waves = report.json(report.root / "waves" / f"summary_{m}.json").get("waves")
    if waves:  # a simulated material: every run demid simulated counts, not only the last wave's
        last = waves[-1]
        text = (f"**Table check.** {last['simulated']} runs simulated in {counted(len(waves), 'wave')}, "
                f"{last['failed']} of them failed; the last wave's analysis takes its table's "
                f"{info['n_runs']} runs over the whole search range, every factor value "
                "inside the search bounds (section *Waves*).")
    if info["warnings"]:
        text += "\n\n" + "\n".join(f"- ⚠ {w}" for w in info["warnings"])
    return [report.md(text)] + transcription(report, info.get("transcription") or {},
                                             report.specs()[m].response_labels)


def figures(report: ReportContext, m: str) -> list:
    """The admissible sets and the response surfaces drawn, each with a line on how to read it."""
    cfg = report.config["materials"][m]
    star = "; ★ = reference point" if cfg.get("reference_point") else ""
    projected = ("; with more than two factors each panel is the set's projection onto a pair of factors "
                 "(a point is coloured when some value of the other factors is admissible)"
                 if len(cfg.get("factors", {})) > 2 else "")
    return [report.md(f"**Admissible sets by scenario** (cells drawn without smoothing{star}{projected})."),
            report.image(report.root / "figures" / f"sets_{m}.png",
                         f"Admissible sets of {report.label(m)} per observable scenario over the search range"),
            report.md("**Response surfaces** with design runs (○) and the target contour (dashed, where the target "
                      "lies in the plotted range); with more than two factors, a slice through the centre of the "
                      "others, showing only the runs on that slice."),
            report.image(report.root / "figures" / f"surface_{m}.png",
                         f"Fitted response surfaces of {report.label(m)} with design runs and target contours")]


def pareto(report: ReportContext, m: str) -> list:
    """The Pareto trade-off (materials with ``pareto``): its figure and the intervals over its points, with a
    warning where it relies on a surrogate that does not predict."""
    par = report.config["materials"][m].get("pareto")
    if not par:
        return []
    said = report.specs()[m].response_labels
    text = (f"**Pareto trade-off**: relative error of {said.get(par['error_of'], par['error_of'])} vs "
            f"predicted {said.get(par['minimise'], par['minimise'])}.")
    crit_path = report.root / "criticism" / f"{m}.json"
    if crit_path.is_file():
        from ..story.verdicts import unpredictive_responses

        level1 = report.json(crit_path).get("level1") or {}
        bad = [r for r in dict.fromkeys((par["error_of"], par["minimise"])) if r in unpredictive_responses(level1)]
        if bad:
            text += (f" ⚠ It relies on the surrogate of {', '.join(said.get(r, r) for r in bad)}, which "
                     "does not predict left-out "
                     f"runs (Q² < 0): treat the front as indicative only.")
    parts = [report.md(text),
             report.image(report.root / "figures" / f"pareto_{m}.png",
                          f"Pareto trade-off of {report.label(m)}: target error against the minimised response")]
    intervals = report.csv(f"pareto_{m}.csv")
    if intervals is not None:
        iv = intervals[intervals["kind"] == "interval"][["factor", "lower", "upper", "n_points"]]
        parts.append(report.md(f"Intervals over Pareto points with error < {100 * par['max_error']:g} %:\n\n"
                               + markdown_table(keys_labelled(iv, report.specs()[m]))))
    return parts


def transcription(report: ReportContext, checks: dict, labels: dict | None = None) -> list:
    """Per response: does the refit reproduce the statistics the source published?  ``labels``: response
    key -> label."""
    if not checks:
        return []
    labels = labels or {}
    from ..story.words import in_order

    lines = ["**Transcription check** against the statistics the source published:"]
    for response, res in in_order(checks):
        stats = ", ".join(f"{k} {res['printed'].get(k, res['published'][k])} → "
                          f"{short_number(res['reproduced'][k])}{'' if res['agrees'][k] else ' ✗'}"
                          for k in res["published"])
        verdict = "agrees" if res["consistent"] else "**disagrees**"
        lines.append(f"- {labels.get(response, response)} {verdict} ({stats}).")
        if not res["consistent"]:
            lines.append(f"  {res['message']}")
            for s in res["suspects"][:5]:
                lines.append(f"  - run {s['run']}, column `{s['column']}`: found {s['found']}, "
                             f"suggested {s['suggested']} ({s['kind'].replace('_', ' ')}; restores "
                             f"{s['restores']} of {res['n_published']} statistics)")
    return [report.md("\n".join(lines))]


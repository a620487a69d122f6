"""The report's section "Beyond deterministic admissibility": strict against plausible sets, the tolerance
sweep, and the observable ranking with its posteriors (which experiment next)."""

from __future__ import annotations

from typing import TYPE_CHECKING

import pandas as pd

from .markdown import RANKING_HEADERS, change_text, keys_labelled, markdown_table

if TYPE_CHECKING:
    from .context import ReportContext


def ranking_display(ranking: pd.DataFrame, uninformative: dict | None = None) -> pd.DataFrame:
    """observable_ranking.csv rows for a reader: plain headers with units, '–' where there is no smaller set;
    an uninformative observable's own gain reads '~0' with its value beside it."""
    columns = [c for c in RANKING_HEADERS if c in ranking.columns]
    if "targets_reachable" in columns and ranking["targets_reachable"].astype(str).str.lower().eq("true").all():
        columns.remove("targets_reachable")  # a column of "True" only says something when one is False
    shown = ranking[columns].rename(columns=RANKING_HEADERS)
    if "best smaller set" in shown:
        shown["best smaller set"] = shown["best smaller set"].replace({"(none)": "–"})
    gain = RANKING_HEADERS["information_gain_bits"]
    error = RANKING_HEADERS["information_gain_error_bits"]
    if error in shown:
        from ..precision import uncertainty_text, value_text

        shown[error] = shown[error].astype(object)
        shown[gain] = shown[gain].astype(object)
        for i in ranking.index:
            err = float(ranking.loc[i, "information_gain_error_bits"])
            shown.loc[i, gain] = value_text(float(ranking.loc[i, "information_gain_bits"]), err, max_digits=3)
            shown.loc[i, error] = uncertainty_text(err)
    if uninformative and gain in shown:
        shown[gain] = shown[gain].astype(object)
        for i in ranking.index[ranking["observables"].isin(list(uninformative))]:
            shown.loc[i, gain] = f"~0 ({float(ranking.loc[i, 'information_gain_bits']):.2f}; uninformative)"
    return shown


def uncertainty(report: ReportContext, m: str) -> list:
    """Strict vs plausible sets, tolerance sweep, posteriors and the next-experiment advice."""
    summary = report.root / "uncertainty" / f"{m}.json"
    if not summary.is_file():
        return []
    info = report.json(summary)
    spec = report.specs()[m]
    parts = [report.md("### Beyond deterministic admissibility")]
    plausible = report.csv("robust_identifiability.csv")
    if plausible is not None and len(plausible[plausible["material"] == m]):
        sub = plausible[plausible["material"] == m]
        cols = ["scenario", "observables", "tolerance", "z", "factor", "strict_fraction_pct",
                "robust_fraction_pct", "strict_width", "robust_width"]
        from ..sampling.residuals import PLAUSIBLE_DEFINITION

        lines = ["**Strict vs plausible admissible sets.** " + PLAUSIBLE_DEFINITION, "",
                 markdown_table(keys_labelled(sub[cols], spec))]
        scen = list(dict.fromkeys(sub["scenario"]))
        shown = {sc.name: sc.label for sc in spec.scenarios}
        if len(scen) >= 2:
            first = sub[sub["scenario"] == scen[0]].iloc[0]
            last = sub[sub["scenario"] == scen[-1]].iloc[0]
            lines += ["", f"From {shown.get(scen[0], scen[0])} to {shown.get(scen[-1], scen[-1])} the feasible "
                      "fraction changes by "
                      f"{change_text(first['strict_fraction_pct'], last['strict_fraction_pct'])} (strict) and "
                      f"{change_text(first['robust_fraction_pct'], last['robust_fraction_pct'])} (plausible)."]
        parts.append(report.md("\n".join(lines)))
    parts.append(report.md("**Tolerance sweep** — conclusions should not hang on one ε."))
    parts.append(report.image(report.root / "figures" / f"sweep_{m}.png",
                              f"Feasible fraction and admissible widths of {report.label(m)} against the tolerance"))
    ranking = report.csv("observable_ranking.csv")
    if ranking is not None and len(ranking[ranking["material"] == m]):
        from ..story import RANKING_KINDS, StudyAdvice

        sub = ranking[ranking["material"] == m]
        walk = StudyAdvice.from_frame(report.csv("advice.csv")).texts(m, RANKING_KINDS)
        out_of_reach = ("targets_reachable" in sub.columns
                        and not sub["targets_reachable"].astype(str).str.lower().eq("true").all())
        parts.append(report.md("**Which experiment next.** Every observable set ranked by the information it "
                               "adds: how far it narrows the parameters, in bits (1 bit = the plausible region "
                               "halves; the Kullback–Leibler divergence from the uniform prior on Ω to the "
                               "posterior). *Added to the best smaller set* is what the last observable brings "
                               "beyond the best set without it"
                               + ("; sets whose targets cannot be met (one alone or all together) come "
                                  "last, without a gain: their "
                                  "posterior measures a discrepancy between simulation and experiment, not "
                                  "information" if out_of_reach else "") + ".\n\n"
                               + markdown_table(keys_labelled(ranking_display(sub, info.get("uninformative")), spec))
                               + ("\n\n" + "\n".join(walk) if walk else "")))
    parts.append(report.image(report.root / "figures" / f"posterior_{m}.png",
                              f"Marginal posterior densities of the factors of {report.label(m)}, one curve per observable set"))
    if info.get("notes"):
        parts.append(report.md("\n".join(f"- {report.speak(n, m)}" for n in info["notes"])))
    return parts


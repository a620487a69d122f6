"""The study-wide sections of the report: the header, surrogate fidelity, the admissible sets of every
material, extending the model, and the reproduction of the published numbers."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from ..io import read_parquet
from ..precision import ROUND_OFF
from .glossary import term
from .markdown import change_text, markdown_table, study_keys_labelled
from .tables import IDENTIFIABILITY_COLUMNS

if TYPE_CHECKING:
    from .context import ReportContext


def header(report: ReportContext) -> list:
    """The report's title, its question, the materials and, where published numbers are declared, their
    provenance."""
    text = ["# demid — identifiability report", "",
            "Which measured observables identify the DEM micro-parameters within the design domain? "
            "For every material, quadratic response surfaces are fitted to the designed simulation runs, "
            "and the *admissible set* — parameter points whose predicted observables all lie within a "
            "relative tolerance of the measured targets — is compared across observable scenarios "
            f"(feasible fraction {term('Φ', 'phi')} of the domain and per-parameter span W).", "",
            f"Materials: {', '.join(report.label(m) for m in report.materials)}."]
    published = report.config.get("published")
    if published and Path(published).is_file():
        import yaml

        with open(published, encoding="utf-8") as fh:
            pub = yaml.safe_load(fh) or {}
        provenance = pub.get("provenance")
        if provenance:
            text += ["", "> **Data provenance.** " + " ".join(str(provenance).split())]
    return [report.md("\n".join(text))]


def surrogate_fit(report: ReportContext) -> list:
    """Surrogate fidelity of every response (tables/surrogate_fit.csv), its statistics defined."""
    table = report.csv("surrogate_fit.csv")
    if table is None:
        return []
    return [report.md(f"## Surrogate fidelity{report.paper('Table 2')}\n\nrmse = √(SSE/n); resid_std = √(SSE/(n−p)); "
                      "q2 = 1 − PRESS/SST (leave-one-out); lack of fit is tested against pure error from "
                      "replicated runs.\n\n" + markdown_table(study_keys_labelled(table, report.specs())))]


def identifiability(report: ReportContext) -> list:
    """The admissible sets of every material (tables/identifiability.csv), with a line per scenario no point
    meets and per scenario against the first: how Φ and each width change."""
    table = report.csv("identifiability.csv")
    if table is None:
        return []
    lines = [f"## Admissible sets{report.paper('Table 3')}", "",
             markdown_table(study_keys_labelled(table[IDENTIFIABILITY_COLUMNS], report.specs())), ""]
    for m in report.materials:
        lines += _empty_set_lines(report, m)
    for m in report.materials:
        lines += _scenario_change_lines(report, m, table[table["material"] == m])
    return [report.md("\n".join(lines))]


def _empty_set_lines(report: ReportContext, m: str) -> list[str]:
    """Per scenario of ``m`` that no point meets: by how much the closest point misses (scenarios/{m}.parquet)."""
    path = report.root / "scenarios" / f"{m}.parquet"
    if not path.is_file():
        return []
    from ..precision import percent_text
    from ..tolerance import has_own_tolerance

    scen = read_parquet(path).drop_duplicates("scenario")
    own = has_own_tolerance(report.specs()[m])
    error = ("largest relative error, each observable's against its own tolerance, expressed at the "
             "scenario's" if own else "largest relative error")
    scenario_label = {sc.name: sc.label for sc in report.specs()[m].scenarios}
    return [f"- **{report.label(m)}**, {scenario_label.get(row['scenario'], row['scenario'])}: no point of the domain "
            f"meets every target within {100 * row['tolerance']:g} %{' (or its own tolerance)' if own else ''}; the "
            f"closest point misses by {percent_text(row['best_max_rel_error'])} ({error})."
            for _, row in scen[scen["feasible_fraction_pct"] == 0].iterrows()]


def _scenario_change_lines(report: ReportContext, m: str, sub) -> list[str]:
    """Per later scenario of ``m`` against its first (``sub``: its rows of the table): Φ and each width."""
    scen = list(dict.fromkeys(sub["scenario"]))
    if len(scen) < 2:
        return []
    base = sub[sub["scenario"] == scen[0]]
    spec = report.specs()[m]
    scenario_label = {sc.name: sc.label for sc in spec.scenarios}
    factor_label = {f.name: f.label for f in spec.factors}
    lines = []
    for s in scen[1:]:
        other = sub[sub["scenario"] == s]
        f0 = base["feasible_fraction_pct"].iloc[0]
        f1 = other["feasible_fraction_pct"].iloc[0]
        widths = []
        for fac in base["factor"]:
            w0 = base.loc[base["factor"] == fac, "width"].iloc[0]
            w1 = other.loc[other["factor"] == fac, "width"].iloc[0]
            if w0 > 0 and w1 == w1:
                widths.append(f"W({factor_label.get(fac, fac)}) {change_text(w0, w1)}")
        lines.append(f"- **{report.label(m)}**: {scenario_label.get(s, s)} vs "
                     f"{scenario_label.get(scen[0], scen[0])}: Φ {f0:.4g} % → {f1:.4g} % "
                     f"({change_text(f0, f1)}); " + ", ".join(widths))
    return lines


def model_extensions(report: ReportContext) -> list:
    """Extending the model: a material that extends another against it (tables/model_extensions.csv)."""
    from ..story.extensions import extension_sentence

    table = report.csv("model_extensions.csv")
    if table is None or not len(table):
        return []
    lines = ["## Extending the model", ""]
    for row in table.fillna("").to_dict("records"):
        spec = report.specs()[row["material"]]
        scenario = next((sc.label for sc in spec.scenarios if sc.name == row["scenario"]), row["scenario"])
        labels = {m: report.label(m) for m in (row["material"], row["extends"])}
        lines.append("- " + extension_sentence(row, labels, {f.name: f.label for f in spec.factors}, scenario))
    return [report.md("\n".join(lines))]


def paper_comparison(report: ReportContext) -> list:
    """Appendix: every published number against its reproduction (tables/paper_comparison.csv)."""
    table = report.csv("paper_comparison.csv")
    if table is None:
        return []
    passed = table["pass"].astype(str).str.lower().eq("true")
    printed = table["printed_agrees"].astype(str).str.lower().eq("true")
    text = (f"## Appendix: reproduction of the published numbers\n\n{int(passed.sum())} of {len(table)} published "
            f"numbers are reproduced within their tolerance.")
    off = table[passed & ~printed]
    if len(off):
        text += (f" On {len(off)} of them (`printed_agrees` no) the reproduction lies within the stated "
                 "tolerance but does not round to every digit the paper printed (a table rebuilt from published "
                 "summaries, or transcribed from rounded values, meets a tolerance without matching the last "
                 "printed digit): " + "; ".join(f"{report.speak(row.quantity, row.material)} "
                                                f"({report.label(row.material)}): printed {row.published:g}, "
                                                f"reproduced {beyond_printed(row.published, row.reproduced)}"
                                                for row in off.itertuples())
                 + ".")
    shown = table.copy()
    # a difference at floating-point round-off of the value is no difference (1.4e-14 of 100)
    noise = shown["abs_diff"].abs() <= ROUND_OFF * shown["published"].abs().clip(lower=1e-300)
    shown.loc[noise, ["abs_diff", "rel_diff"]] = 0.0
    known = shown["material"].isin(report.materials)
    shown.loc[known, "quantity"] = [report.speak(q, m) for q, m in zip(shown.loc[known, "quantity"],
                                                                       shown.loc[known, "material"])]
    shown.loc[known, "material"] = shown.loc[known, "material"].map(report.label)
    for column in ("pass", "printed_agrees"):  # the CSV's booleans read as words
        shown[column] = shown[column].astype(str).str.lower().map({"true": "yes", "false": "no"}).fillna("–")
    return [report.md(text + "\n\n" + markdown_table(shown))]


def beyond_printed(published: float, reproduced: float) -> str:
    """The reproduction to two decimals more than the published value prints (0.017 → "0.01705", 0.1127 →
    "0.112784"): enough to see why it does not round to the printed digits, not more."""
    printed = f"{published:g}"
    if "e" in printed:
        return f"{reproduced:.6g}"
    decimals = len(printed.partition(".")[2])
    return f"{reproduced:.{decimals + 2}f}"


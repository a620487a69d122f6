"""The text of the HTML report: one method per section, read from the results tree."""

from __future__ import annotations

from functools import cached_property
from pathlib import Path

import pandas as pd

from ..io import FIGURE_DPI, read_parquet
from .tables import IDENTIFIABILITY_COLUMNS


# --------------------------------------------------------------------------- report text
def _fmt(value, digits: int = 4) -> str:
    if isinstance(value, (float, int)) and not isinstance(value, bool):
        if value != value:  # NaN
            return "–"
        return f"{value:.{digits}g}"
    return str(value)


#: Report headers of the CSV columns the report shows: what the column says, with its unit.  The CSV files
#: keep their names (tables/columns.csv documents both).
REPORT_HEADERS = {
    "feasible_fraction_pct": "Φ [% of Ω]", "strict_fraction_pct": "strict Φ [% of Ω]",
    "robust_fraction_pct": "plausible Φ [% of Ω]", "strict_width": "strict width", "robust_width": "plausible width",
    "at_bound": "at search bound", "n_runs": "runs", "n_points": "points", "adj_r2": "adj. R²", "r2": "R²",
    "q2": "Q² (leave-one-out)", "rmse": "RMSE", "resid_std": "residual SD", "lof_f": "lack-of-fit F",
    "lof_p": "lack-of-fit p", "abs_diff": "|difference|", "rel_diff": "relative difference",
    "printed_agrees": "agrees to printed digits", "pass": "within tolerance", "sum_sq": "sum of squares",
    "mean_sq": "mean square", "p_value": "p", "std_error": "standard error", "max_vif": "max VIF",
    "max_cooks_d": "max Cook's D", "max_abs_student_resid": "max |studentised residual|",
    "breusch_pagan_lm": "Breusch–Pagan LM", "breusch_pagan_p": "Breusch–Pagan p", "reset_f": "RESET F",
    "reset_p": "RESET p", "shapiro_w": "Shapiro–Wilk W", "shapiro_p": "Shapiro–Wilk p",
    "loo_rmse_baseline": "leave-one-out RMSE, quadratic", "loo_rmse_extended": "leave-one-out RMSE, extended",
    "delta_aicc": "ΔAICc (extended − quadratic)",
}


#: Columns of p-values: printed by :func:`~demid.precision.p_text` (2 digits, "< 0.0001" below it).
P_COLUMNS = frozenset({"p_value", "lof_p", "breusch_pagan_p", "reset_p", "shapiro_p", "PR(>F)"})


def markdown_table(frame: pd.DataFrame, digits: int = 4) -> str:
    """A GitHub-style Markdown table (no extra dependency), numbers to ``digits`` significant digits;
    headers in words (:data:`REPORT_HEADERS`)."""
    if frame.empty:
        return "_(empty)_"
    from ..precision import p_text

    frame = frame.copy()
    for c in [c for c in frame.columns if c in P_COLUMNS]:
        frame[c] = [p_text(v) if isinstance(v, (int, float)) and not isinstance(v, bool) else v for v in frame[c]]
    cols = list(frame.columns)
    heads = [_cell(REPORT_HEADERS.get(c, c)) for c in cols]
    lines = ["| " + " | ".join(heads) + " |", "|" + "|".join("---" for _ in cols) + "|"]
    for _, row in frame.iterrows():
        lines.append("| " + " | ".join(_cell(_fmt(row[c], digits)) for c in cols) + " |")
    return "\n".join(lines)


def _cell(text: str) -> str:
    """A table cell's text as Markdown: a bar inside it (``|studentised residual|``) would end the cell and
    leave the whole table as raw text, so it is escaped; a line break would end the row."""
    return str(text).replace("|", "\\|").replace("\n", " ")


# Report headers of observable_ranking.csv: what the column says, with its unit.
RANKING_HEADERS = {
    "rank": "rank",
    "observables": "observables",
    "information_gain_bits": "information gain [bit]",
    "information_gain_error_bits": "± numerical error [bit]",
    "best_subset": "best smaller set",
    "gain_vs_best_subset_bits": "added to the best smaller set [bit]",
    "feasible_fraction_pct": "admissible share of Ω [%]",
    "targets_reachable": "targets reachable",
}


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


def keys_labelled(frame: pd.DataFrame, spec) -> pd.DataFrame:
    """A table's scenario, factor and observable keys shown as their configured labels (``aor+shape`` as
    ``θ_Po + S_Po``); the CSV keeps the keys."""
    scenarios = {sc.name: sc.label for sc in spec.scenarios}
    factors = {f.name: f.label for f in spec.factors}

    def observables(value):
        if not isinstance(value, str) or value in ("–", "(none)"):
            return value
        return " + ".join(spec.response_labels.get(o, o) for o in value.split("+"))

    out = frame.copy()
    for column in out.columns:
        if column == "scenario":
            out[column] = out[column].map(lambda v: scenarios.get(v, v))
        elif column == "factor":
            out[column] = out[column].map(lambda v: factors.get(v, v))
        elif column in ("observables", "best_subset", RANKING_HEADERS["best_subset"]):
            out[column] = out[column].map(observables)
        elif column == "response":
            out[column] = out[column].map(lambda v: spec.response_labels.get(v, v))
    return out


def study_keys_labelled(frame: pd.DataFrame, specs: dict) -> pd.DataFrame:
    """A study-wide table (one row per material and ...) shown in labels: each row's scenario, factor,
    observables and response keys through its own material's spec, the material as its label."""
    parts = []
    for material, rows in frame.groupby("material", sort=False):
        spec = specs.get(material)
        if spec is None:
            parts.append(rows)
            continue
        shown = keys_labelled(rows, spec)
        shown["material"] = spec.label
        parts.append(shown)
    return pd.concat(parts).loc[frame.index] if parts else frame


def coefficients_shown(coef: pd.DataFrame) -> pd.DataFrame:
    """A coefficient table as printed: each estimate to the digits its standard error supports (≈ 0 where it
    cannot be told from zero), the standard error to two digits, t to two and p by :func:`~demid.precision.p_text`."""
    from ..precision import ZERO, uncertainty_text, value_text

    out = coef.copy().astype({c: object for c in ("estimate", "std_error", "t") if c in coef})
    for i in coef.index:
        est, se = float(coef.loc[i, "estimate"]), float(coef.loc[i, "std_error"])
        out.loc[i, "estimate"] = value_text(est, se)
        out.loc[i, "std_error"] = uncertainty_text(se)
        out.loc[i, "t"] = ZERO if out.loc[i, "estimate"] == ZERO else value_text(float(coef.loc[i, "t"]), max_digits=3)
    return out


def _symbol_of(term: str, letters: dict[str, str]) -> str:
    from .rsm import _symbol

    return "–" if term == "Intercept" else _symbol(term, letters).replace(":", "·")


def typeset_labels(text: str, labels: list[str]) -> str:
    """Configured labels written with ``_`` and ``^`` (``μ_r,Po``, ``J m^-2``) shown with HTML sub- and
    superscripts in the report's prose and tables; code spans and other text are left alone."""
    import html
    import re

    pretty = {}
    for label in labels:
        if "_" not in label and "^" not in label or "$" in label:
            continue
        base, _, sub = label.partition("_")
        shown = html.escape(base) + (f"<sub>{html.escape(sub.replace('_', ','))}</sub>" if sub else "")
        pretty[label] = re.sub(r"\^\{?(-?[0-9.]+)\}?", r"<sup>\1</sup>", shown)
    if not pretty:
        return text
    # a label stands alone, or before a square or cube (a coefficient's term: e_Po²)
    pattern = re.compile(r"(?<!\w)(?:" + "|".join(re.escape(k) for k in pretty) + r")(?![^\W²³])")
    # Odd-numbered pieces of a split on backticks are code spans: keep them verbatim.
    pieces = text.split("`")
    for k in range(0, len(pieces), 2):
        pieces[k] = pattern.sub(lambda m: pretty[m.group(0)], pieces[k])
    return "`".join(pieces)


#: The report's terms, each with the anchor the text links to (:func:`term`): key, name, definition.
GLOSSARY = (
    ("omega", "Ω (search range)", "the box of factor values between the configured bounds (the design's ±α levels)."),
    ("tolerance", "ε (tolerance)", "relative distance from the measured target within which a prediction counts as "
     "a match; a fraction in the tables (0.02 = 2 %)."),
    ("phi", "Φ (feasible fraction)", "share of Ω, in %, whose predictions match every target within ε."),
    ("plausible-set", "plausible set", "the points whose every predicted observable lies within z combined standard "
     "deviations (surrogate, measurement, discrepancy) of its target; the span of the set per factor is the "
     "plausible interval, on which the verdicts are judged."),
    ("implausibility", "implausibility", "at a point, the largest over the observables of |prediction − target| "
     "divided by the plausible band's half-width: below 1 the point is plausible; the recommended point has the "
     "smallest."),
    ("z", "z", "the half-width of the plausible band in standard deviations (z = 2 covers about 95 %)."),
    ("sigma", "σ, σ_rel", "measurement uncertainty of a target, absolute or relative; when a response declares "
     "none, the tolerance is the measurement band (σ = ε·|y*|/z), never added to it."),
    ("delta", "δ", "optional model-discrepancy standard deviation of a response (`discrepancy`)."),
    ("q2", "Q²", "1 − PRESS/SST: how well the quadratic predicts each run left out of its fit; 1 is perfect, below "
     "0 it predicts worse than the runs' mean (the surrogate does not predict)."),
    ("aicc", "AICc", "Akaike's information criterion corrected for small samples: a lower value means a better "
     "trade of fit against the number of terms; a drop of 2 or more favours the extended model."),
    ("ridge", "ridge", "a direction along which a fitted surface hardly changes (a near-zero eigenvalue of its "
     "quadratic part): along it different factor values give the same response, so the observable cannot tell "
     "them apart."),
    ("combination", "combination", "a weighted sum of factors the data pin down while each factor alone is free "
     "(the narrow axis of the set: a ridge of the observables); tables/combinations.csv."),
    ("bits", "bits / information gain", "Kullback–Leibler divergence from the uniform prior on Ω to the posterior, "
     "in bits; one bit halves the plausible volume."),
    ("se", "se", "standard error of the surrogate's mean prediction."),
)


def term(words: str, key: str) -> str:
    """``words`` linked to their entry of the report's glossary (:data:`GLOSSARY`)."""
    return f"[{words}](#term-{key})"


class ReportSections:
    """Builds the report's displayable parts from the results folder; optional parts are skipped."""

    def __init__(self, results_dir: str, config: dict):
        self.root = Path(results_dir)
        self.config = config
        self.materials = list(config.get("materials", {}))

    # helpers
    def _md(self, text: str):
        """Report text (Markdown, labels typeset) as sanitised HTML: whatever a config puts in it is shown,
        never run."""
        from IPython.display import HTML

        from .safe_html import markdown_html

        return HTML(self._unique_anchors(markdown_html(typeset_labels(text, self._plain_labels))))

    def _unique_anchors(self, html: str) -> str:
        """Heading anchors made unique over the whole report: the second "What the model gets wrong" becomes
        ``…-2`` (its link with it), so an in-page link never lands on the first material's heading."""
        import re

        used = self.__dict__.setdefault("_anchors", {})

        def renamed(match: re.Match) -> str:
            anchor = match.group(2)
            used[anchor] = used.get(anchor, 0) + 1
            if used[anchor] == 1:
                return match.group(0)
            new = f"{anchor}-{used[anchor]}"
            return match.group(0).replace(f'id="{anchor}"', f'id="{new}"').replace(f'href="#{anchor}"', f'href="#{new}"')

        return re.sub(r'<(h[1-6]) id="([^"]+)">.*?</\1>', renamed, html, flags=re.S)

    @cached_property
    def _plain_labels(self) -> list[str]:
        """Every configured factor/response label and unit, longest first (so d_10 wins over d_1)."""
        found = set()
        for material in self.config.get("materials", {}).values():
            for group in ("factors", "responses"):
                for item in (material.get(group) or {}).values():
                    found.update(t for t in (item.get("label"), item.get("unit")) if t)
        return sorted(found, key=len, reverse=True)

    def _image(self, path: Path, alt: str = ""):
        """The PNG inline at the page's full width, with alt text and a link to its SVG twin."""
        import base64
        import html

        from IPython.display import HTML

        from .safe_html import sanitize

        if not path.is_file():
            return self._md(f"_(missing figure {path.name})_")
        raw = path.read_bytes()
        data = base64.b64encode(raw).decode("ascii")
        # Print size at 96 CSS px per inch (the PNG's width in pixels over its dpi), narrowed to the page:
        # every figure's text then appears at about the same size.
        css_px = round(int.from_bytes(raw[16:20], "big") / FIGURE_DPI * 96)
        alt = html.escape(alt or path.stem.replace("_", " "), quote=True)
        return HTML(sanitize(f'<figure style="margin:0"><img src="data:image/png;base64,{data}" alt="{alt}" '
                    f'style="width:{css_px}px;max-width:100%;height:auto"><figcaption style="font-size:small">'
                    f'{alt} — vector version: <code>figures/{path.stem}.svg</code></figcaption></figure>', figure=True))

    def _speak(self, text: str, m: str) -> str:
        """``text`` with the material's factor, response and scenario keys written as their labels (a key
        inside a config path or a file name stays)."""
        import re

        from .summary import labelled

        spec = self._specs()[m]
        text = labelled(text, spec)
        names = {sc.name: sc.label for sc in spec.scenarios if sc.label and sc.label != sc.name}
        if not names or not text:
            return text
        keys = "|".join(re.escape(k) for k in sorted(names, key=len, reverse=True))
        return re.sub(r"(?<![\w./`'])'?(" + keys + r")'?(?![\w`]|\.\w)", lambda k: names[k.group(1)], text)

    def _paper(self, what: str) -> str:
        """`` (paper Table 2)`` where published numbers are declared, else nothing: headings stay generic."""
        return f" (paper {what})" if self.config.get("published") else ""

    def _csv(self, name: str) -> pd.DataFrame | None:
        path = self.root / "tables" / name
        return pd.read_csv(path) if path.is_file() else None

    def _label(self, material: str) -> str:
        return self._specs()[material].label

    def _specs(self) -> dict:
        """Each material's spec, built once for the report."""
        if getattr(self, "_spec_cache", None) is None:
            from ..spec import MaterialSpec

            self._spec_cache = {m: MaterialSpec.from_material(m, entry)
                                for m, entry in self.config["materials"].items()}
        return self._spec_cache

    # sections
    def all(self) -> list:
        parts = self.header()
        parts += self.summary()
        parts += self.surrogate_fit()
        parts += self.identifiability()
        for m in self.materials:
            parts += self.material(m)
        parts += self.model_extensions()
        parts += self.glossary()
        parts += self.paper_comparison()
        return parts

    def model_extensions(self) -> list:
        """Extending the model: a material that extends another against it (tables/model_extensions.csv)."""
        from ..story.extensions import extension_sentence

        table = self._csv("model_extensions.csv")
        if table is None or not len(table):
            return []
        lines = ["## Extending the model", ""]
        for row in table.fillna("").to_dict("records"):
            spec = self._specs()[row["material"]]
            scenario = next((sc.label for sc in spec.scenarios if sc.name == row["scenario"]), row["scenario"])
            labels = {m: self._label(m) for m in (row["material"], row["extends"])}
            lines.append("- " + extension_sentence(row, labels, {f.name: f.label for f in spec.factors}, scenario))
        return [self._md("\n".join(lines))]

    def summary(self) -> list:
        """Per material: recommended set, verdict per factor and scenario, criticism, next step.

        Verdicts and advice are read from ``tables/verdicts.csv`` and ``tables/advice.csv`` (rule
        ``story``): the same rows level 2 and the next-wave section show."""
        from ..sampling.residuals import PLAUSIBLE_DEFINITION
        from ..story import StudyAdvice, verdict_display
        from ..story.verdicts import VERDICT_TEXT
        from ..story.words import in_order
        from .summary import combination_lines, criticism_lines

        verdicts_all = self._csv("verdicts.csv")
        advice = StudyAdvice.from_frame(self._csv("advice.csv"))
        answers = [self._answer_line(m, verdicts_all, advice) for m in self.materials]
        parts = [self._md("## Summary\n\n" + "\n".join(f"- {a}" for a in answers if a) + "\n\n"
                          "**How to read it.** Per factor and observable scenario the "
                          f"{term('plausible interval', 'plausible-set')} is judged; the strict interval (the set if "
                          "surrogate and measurements were exact: section "
                          f"*Admissible sets*{self._paper('Table 3')}) stands beside it. "
                          f"{term('Plausible set', 'plausible-set')}: "
                          + PLAUSIBLE_DEFINITION + " Verdicts: " + VERDICT_TEXT
                          + " **uninformative observable**: every observable of the scenario leaves at least 99 % "
                          "of the search range admissible on its own (its band covers its whole simulated range). "
                          "Other terms: [Terms](#Terms).")]
        for m in self.materials:
            spec = self._specs()[m]
            lines = [f"### {spec.label}", ""]
            info = self._json(self.root / "criticism" / f"{m}.json")
            unc = self._json(self.root / "uncertainty" / f"{m}.json")
            level2 = info.get("level2") or {}
            verdicts = (verdicts_all[verdicts_all["material"] == m] if verdicts_all is not None
                        else pd.DataFrame(columns=["scenario", "factor", "verdict"]))
            widened = {(i.factor, i.bound) for i in advice.items if i.material == m and i.kind == "widen"}
            lines += self._recommended_lines(spec, unc.get("recommended"), verdicts, level2, widened)
            for o, why in in_order(unc.get("uninformative") or {}, spec.response_names):
                lines.append(f"{spec.response_labels.get(o, o)} is an **uninformative observable**: {why}.")
            if len(verdicts):
                lines += ["", markdown_table(verdict_display(verdicts, spec), 3)]
            combos = self._json(self.root / "combinations" / f"{m}.json")
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
            parts.append(self._md("\n".join(lines)))
        return parts

    def _answer_line(self, m: str, verdicts_all: pd.DataFrame | None, advice) -> str:
        """One material's answer in a line: with its fullest scenario, the factors identified, those not
        (with their verdict), and the next step."""
        spec = self._specs()[m]
        if verdicts_all is None or not len(verdicts_all[verdicts_all["material"] == m]):
            return ""
        rows = verdicts_all[verdicts_all["material"] == m]
        scenario = max(spec.scenarios, key=lambda sc: len(sc.observables))
        rows = rows[rows["scenario"] == scenario.name]
        found = [spec.factor(f).label for f, v in zip(rows["factor"], rows["verdict"]) if str(v) == "identified"]
        combined = [spec.factor(f).label for f, v in zip(rows["factor"], rows["verdict"])
                    if "identified in combination" in str(v)]
        missing = [f"{spec.factor(f).label} {v}" for f, v in zip(rows["factor"], rows["verdict"])
                   if str(v) != "identified" and "identified in combination" not in str(v)]
        text = (f"**{spec.label}**, with *{scenario.label}*: identified: {', '.join(found) or 'none'}"
                + (f"; in {term('combination', 'combination')} only: {', '.join(combined)}" if combined else "")
                + f"; not identified: {', '.join(missing) or 'none'}.")
        decision, _ = advice.next_step(m)
        return text + (f" **Next step:** {decision}" if decision else "")

    @staticmethod
    def _json(path: Path) -> dict:
        import json

        return json.loads(path.read_text(encoding="utf-8")) if path.is_file() else {}

    def _recommended_lines(self, spec, recommended: dict | None, verdicts: pd.DataFrame, level2: dict,
                           widened: set = frozenset()) -> list[str]:
        """The most robust plausible point with each factor's plausible interval beside it, to the digits that
        interval supports; plainly said when the set is wide, or when no point meets every target, or when the
        point sits on a search bound or outside the runs (``widened``: the (factor, side) pairs advised wider)."""
        import numpy as np

        from ..uncertainty.recommended import digits_for
        from ..story.words import unit_text
        from .summary import point_on_edge_text

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
        edge = point_on_edge_text(spec, recommended["point"], self._runs(spec),
                                  {} if rows is None else rows["verdict"].astype(str).to_dict(), widened)
        return [text] + (["", edge, ""] if edge else []) + lines

    def _runs(self, spec):
        """The material's design runs (factor columns, actual units), or None before validation."""
        path = self.root / "validated" / f"{spec.name}.parquet"
        return read_parquet(path)[spec.factor_names].to_numpy(dtype=float) if path.is_file() else None

    def glossary(self) -> list:
        return [self._md("## Terms\n\n" + "\n".join(f"- <strong id=\"term-{key}\">{name}</strong>: {text}"
                                                    for key, name, text in GLOSSARY))]

    def header(self) -> list:
        text = ["# demid — identifiability report", "",
                "Which measured observables identify the DEM micro-parameters within the design domain? "
                "For every material, quadratic response surfaces are fitted to the designed simulation runs, "
                "and the *admissible set* — parameter points whose predicted observables all lie within a "
                "relative tolerance of the measured targets — is compared across observable scenarios "
                f"(feasible fraction {term('Φ', 'phi')} of the domain and per-parameter span W).", "",
                f"Materials: {', '.join(self._label(m) for m in self.materials)}."]
        published = self.config.get("published")
        if published and Path(published).is_file():
            import yaml

            with open(published, encoding="utf-8") as fh:
                pub = yaml.safe_load(fh) or {}
            provenance = pub.get("provenance")
            if provenance:
                text += ["", "> **Data provenance.** " + " ".join(str(provenance).split())]
        return [self._md("\n".join(text))]

    def paper_comparison(self) -> list:
        table = self._csv("paper_comparison.csv")
        if table is None:
            return []
        passed = table["pass"].astype(str).str.lower().eq("true")
        printed = table["printed_agrees"].astype(str).str.lower().eq("true")
        text = (f"## Appendix: reproduction of the published numbers\n\n{int(passed.sum())} of {len(table)} published "
                f"numbers are reproduced within their tolerance.")
        off = table[passed & ~printed]
        if len(off):
            text += (f" `printed_agrees` is False on {len(off)} of them: the reproduction lies within the stated "
                     "tolerance but does not round to every digit the paper printed (a table rebuilt from published "
                     "summaries, or transcribed from rounded values, meets a tolerance without matching the last "
                     "printed digit): " + "; ".join(f"{self._speak(row.quantity, row.material)} "
                                                    f"({self._label(row.material)}): printed {row.published:g}, "
                                                    f"reproduced {row.reproduced:.6g}" for row in off.itertuples())
                     + ".")
        shown = table.copy()
        # a difference at floating-point round-off of the value is no difference (1.4e-14 of 100)
        noise = shown["abs_diff"].abs() <= 1e-9 * shown["published"].abs().clip(lower=1e-300)
        shown.loc[noise, ["abs_diff", "rel_diff"]] = 0.0
        known = shown["material"].isin(self.materials)
        shown.loc[known, "quantity"] = [self._speak(q, m) for q, m in zip(shown.loc[known, "quantity"],
                                                                          shown.loc[known, "material"])]
        shown.loc[known, "material"] = shown.loc[known, "material"].map(self._label)
        return [self._md(text + "\n\n" + markdown_table(shown))]

    def surrogate_fit(self) -> list:
        table = self._csv("surrogate_fit.csv")
        if table is None:
            return []
        return [self._md(f"## Surrogate fidelity{self._paper('Table 2')}\n\nrmse = √(SSE/n); resid_std = √(SSE/(n−p)); "
                         "q2 = 1 − PRESS/SST (leave-one-out); lack of fit is tested against pure error from "
                         "replicated runs.\n\n" + markdown_table(study_keys_labelled(table, self._specs())))]

    def identifiability(self) -> list:
        table = self._csv("identifiability.csv")
        if table is None:
            return []
        lines = [f"## Admissible sets{self._paper('Table 3')}", "",
                 markdown_table(study_keys_labelled(table[IDENTIFIABILITY_COLUMNS], self._specs())), ""]
        for m in self.materials:
            path = self.root / "scenarios" / f"{m}.parquet"
            if not path.is_file():
                continue
            scen = read_parquet(path).drop_duplicates("scenario")
            from ..precision import percent_text
            from ..tolerance import has_own_tolerance

            own = has_own_tolerance(self._specs()[m])
            error = ("largest relative error, each observable's against its own tolerance, expressed at the "
                     "scenario's" if own else "largest relative error")
            scenario_label = {sc.name: sc.label for sc in self._specs()[m].scenarios}
            for _, row in scen[scen["feasible_fraction_pct"] == 0].iterrows():
                lines.append(f"- **{self._label(m)}**, {scenario_label.get(row['scenario'], row['scenario'])}: no point of the domain meets every target "
                             f"within {100 * row['tolerance']:g} %{' (or its own tolerance)' if own else ''}; the "
                             f"closest point misses by {percent_text(row['best_max_rel_error'])} ({error}).")
        for m in self.materials:
            sub = table[table["material"] == m]
            scen = list(dict.fromkeys(sub["scenario"]))
            if len(scen) < 2:
                continue
            base = sub[sub["scenario"] == scen[0]]
            spec = self._specs()[m]
            scenario_label = {sc.name: sc.label for sc in spec.scenarios}
            factor_label = {f.name: f.label for f in spec.factors}
            for s in scen[1:]:
                other = sub[sub["scenario"] == s]
                f0 = base["feasible_fraction_pct"].iloc[0]
                f1 = other["feasible_fraction_pct"].iloc[0]
                change = f"{100 * (f1 - f0) / f0:+.1f} %" if f0 > 0 else "n/a"
                widths = []
                for fac in base["factor"]:
                    w0 = base.loc[base["factor"] == fac, "width"].iloc[0]
                    w1 = other.loc[other["factor"] == fac, "width"].iloc[0]
                    if w0 > 0 and w1 == w1:
                        widths.append(f"W({factor_label.get(fac, fac)}) {100 * (w1 - w0) / w0:+.1f} %")
                lines.append(f"- **{self._label(m)}**: {scenario_label.get(s, s)} vs "
                             f"{scenario_label.get(scen[0], scen[0])}: Φ {f0:.4g} % → {f1:.4g} % "
                             f"({change}); " + ", ".join(widths))
        return [self._md("\n".join(lines))]

    def transcription(self, checks: dict, labels: dict | None = None) -> list:
        """Per response: does the refit reproduce the statistics the source published?  ``labels``: response
        key -> label."""
        if not checks:
            return []
        labels = labels or {}
        from ..story.words import in_order

        lines = ["**Transcription check** against the statistics the source published:"]
        for response, res in in_order(checks):
            stats = ", ".join(f"{k} {res['printed'].get(k, res['published'][k])} → "
                              f"{_fmt(res['reproduced'][k])}{'' if res['agrees'][k] else ' ✗'}"
                              for k in res["published"])
            verdict = "agrees" if res["consistent"] else "**disagrees**"
            lines.append(f"- {labels.get(response, response)} {verdict} ({stats}).")
            if not res["consistent"]:
                lines.append(f"  {res['message']}")
                for s in res["suspects"][:5]:
                    lines.append(f"  - run {s['run']}, column `{s['column']}`: found {s['found']}, "
                                 f"suggested {s['suggested']} ({s['kind'].replace('_', ' ')}; restores "
                                 f"{s['restores']} of {res['n_published']} statistics)")
        return [self._md("\n".join(lines))]

    def criticism(self, m: str) -> list:
        """What the surrogate and the calibrated simulation get wrong, the named cause and the gain."""
        summary = self.root / "criticism" / f"{m}.json"
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

        spec = self._specs()[m]
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
        findings = self._csv("criticism.csv")
        if findings is not None and "cause" in findings.columns:
            findings = findings[findings["cause"] != "none"]
        if findings is not None and "response" in findings.columns and len(findings[findings["material"] == m]):
            cols = [c for c in ["response", "cause", "detail", "p_value", "loo_rmse_baseline", "loo_rmse_extended",
                                "delta_aicc"] if c in findings.columns]
            shown = keys_labelled(findings[findings["material"] == m][cols], spec)
            shown["cause"] = shown["cause"].astype(str).str.replace(";", ", ").str.replace("_", " ")
            if "detail" in shown:
                shown["detail"] = shown["detail"].fillna("").astype(str).map(lambda t: self._speak(t, m))
            lines += ["", markdown_table(shown)]
        level2 = info.get("level2")
        if level2:
            from ..story import LEVEL2_KINDS, StudyAdvice

            advice = StudyAdvice.from_frame(self._csv("advice.csv")).texts(m, LEVEL2_KINDS)
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
            scenario = self._speak(pos["scenario"], m)
            lines.append(f"- Reference point vs scenario *{scenario}*: it {where} (errors {errs}).")
        parts = [self._md("\n".join(lines))]
        parts.append(self._image(self.root / "figures" / f"residuals_{m}.png",
                                 f"Residuals of each response surface of {self._label(m)} against fitted value, run order and normal quantiles"))
        return parts

    def uncertainty(self, m: str) -> list:
        """Strict vs plausible sets, tolerance sweep, posteriors and the next-experiment advice."""
        summary = self.root / "uncertainty" / f"{m}.json"
        if not summary.is_file():
            return []
        import json

        info = json.loads(summary.read_text(encoding="utf-8"))
        spec = self._specs()[m]
        parts = [self._md("### Beyond deterministic admissibility")]
        plausible = self._csv("robust_identifiability.csv")
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
                def _contr(a, b):
                    return f"{100 * (b - a) / a:+.1f} %" if a > 0 else "n/a"
                lines += ["", f"From {shown.get(scen[0], scen[0])} to {shown.get(scen[-1], scen[-1])} the feasible "
                          "fraction changes by "
                          f"{_contr(first['strict_fraction_pct'], last['strict_fraction_pct'])} (strict) and "
                          f"{_contr(first['robust_fraction_pct'], last['robust_fraction_pct'])} (plausible)."]
            parts.append(self._md("\n".join(lines)))
        parts.append(self._md("**Tolerance sweep** — conclusions should not hang on one ε."))
        parts.append(self._image(self.root / "figures" / f"sweep_{m}.png",
                                 f"Feasible fraction and admissible widths of {self._label(m)} against the tolerance"))
        ranking = self._csv("observable_ranking.csv")
        if ranking is not None and len(ranking[ranking["material"] == m]):
            from ..story import RANKING_KINDS, StudyAdvice

            sub = ranking[ranking["material"] == m]
            walk = StudyAdvice.from_frame(self._csv("advice.csv")).texts(m, RANKING_KINDS)
            out_of_reach = ("targets_reachable" in sub.columns
                            and not sub["targets_reachable"].astype(str).str.lower().eq("true").all())
            parts.append(self._md("**Which experiment next.** Every observable set ranked by the information it "
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
        parts.append(self._image(self.root / "figures" / f"posterior_{m}.png",
                                 f"Marginal posterior densities of the factors of {self._label(m)}, one curve per observable set"))
        if info.get("notes"):
            parts.append(self._md("\n".join(f"- {self._speak(n, m)}" for n in info["notes"])))
        return parts

    def next_wave(self, m: str) -> list:
        """The proposed next wave (only for materials with ``next_runs``)."""
        reasons = self.root / "next_wave" / "reasons.json"
        runs = self._csv("next_runs.csv")
        if runs is None or not reasons.is_file() or not len(runs[runs["material"] == m]):
            return []
        import json

        from ..story import NEXT_WAVE_KINDS, StudyAdvice

        reason = json.loads(reasons.read_text(encoding="utf-8")).get(m, "")
        advice = " ".join(StudyAdvice.from_frame(self._csv("advice.csv")).texts(m, NEXT_WAVE_KINDS))
        sub = runs[runs["material"] == m].dropna(axis=1, how="all")
        spec = self._specs()[m]
        sub = keys_labelled(sub, spec)
        from ..precision import coordinate_text

        for f in spec.factors:
            if f.name in sub:
                sub[f.name] = [coordinate_text(float(v), f.lower, f.upper) for v in sub[f.name]]
        sub = sub.rename(columns={f.name: f.label for f in spec.factors})
        return [self._md("### What to simulate next\n\n" + self._speak(reason, m) + (" " + advice if advice else "")
                         + " Once simulated, they are studied in the next domain (tables/next_domain.csv) with the "
                         "earlier runs inside it (`design: {type: custom}`).\n\n"
                         + markdown_table(sub.drop(columns="material")))]

    def waves(self, m: str) -> list:
        """A simulated material's waves (``waves/summary_{m}.json``): per wave the runs simulated, failed and
        analysed, the surrogate and its Q², the plausible share of Omega and each factor's plausible interval; the
        runs-per-wave figure; and why the loop stopped, in the words of the study's advice."""
        from ..story import StudyAdvice

        summary = self._json(self.root / "waves" / f"summary_{m}.json")
        if not summary.get("waves"):
            return []
        spec = self._specs()[m]
        rows = []
        for w in summary["waves"]:
            row = {"wave": w["wave"], "runs simulated": w["simulated"], "failed": w["failed"],
                   "analysed": w["analysed"], "surrogate": w["surrogate"],
                   "Q²": ", ".join(f"{spec.response_labels.get(r, r)} " + (f"{q:.2f}" if q is not None else
                                                                            "undefined")
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
                 f"demid simulated {last['simulated']} runs in {len(summary['waves'])} wave(s) ({last['failed']} "
                 f"failed); wave 1 is the declared design, each later wave the runs the one before proposed. Per "
                 f"wave: the runs simulated up to it, the failed ones among them, the runs its analysis used, its "
                 f"surrogate and the surrogate's leave-one-out Q², and the plausible set of {used} as a share of the "
                 "search range Ω with each factor's plausible interval.", "",
                 markdown_table(pd.DataFrame(rows), 3)]
        told = StudyAdvice.from_frame(self._csv("advice.csv")).texts(m, ("stop", "next_runs", "recalibrate"))
        decision = summary.get("decision")
        if decision:
            stop_line = next((t for t in told if decision["reason"] in t), decision["reason"])
            lines += ["", f"**Why the loop stopped after wave {last['wave']}:** {stop_line}"]
        parts = [self._md("\n".join(lines))]
        parts.append(self._image(self.root / "figures" / f"waves_{m}.png",
                                 f"Feasible fraction of Ω against the runs simulated, and each factor's admissible "
                                 f"interval per wave over the wave's box, of {self._label(m)}"))
        return parts

    def response_surfaces(self, m: str) -> list:
        """Per response: equation (coded, actual), block ANOVA, coefficients, canonical analysis."""
        import json

        from ..surrogate import coding_from_frame
        from .rsm import canonical_text, equation, stored_surfaces

        table = self.root / "validated" / f"{m}.parquet"
        fits, anova = self.root / "fits" / f"{m}.parquet", self.root / "fits" / f"{m}_anova.parquet"
        if not (table.is_file() and fits.is_file() and anova.is_file()):
            return []
        spec = self._specs()[m]
        letters = {f: chr(ord("A") + i) for i, f in enumerate(spec.factor_names)}
        fit_json = self.root / "fits" / f"{m}.json"
        canonical = json.loads(fit_json.read_text(encoding="utf-8")) if fit_json.is_file() else {}
        lines = ["### Response-surface models", "", f"A {term('ridge', 'ridge')} in a canonical analysis is a "
                 "direction along which the response hardly changes.", ""]
        fits = read_parquet(fits)
        coding = coding_from_frame(fits, spec.factor_names) if len(fits) else None
        # the fits and their statistics as the fit step stored them: the report does not fit again
        for surface in stored_surfaces(fits, read_parquet(anova), read_parquet(table), spec):
            label = spec.response_labels.get(surface.response, surface.response)
            coef = surface.coefficients.copy()  # the symbol column is for this table only
            coef.insert(1, "symbol", [_symbol_of(t, letters) for t in coef["term"]])
            entry = canonical.get(surface.response, {}).get("canonical")
            where = canonical_text(entry, spec.factor_names, spec, letters, label) if entry is not None else ""
            term_names = coef["term"].tolist()  # keys, for the equations; the table shows labels
            coef["term"] = [t if t == "Intercept" else _symbol_of(t, spec.factor_labels) for t in coef["term"]]
            lines += [f"#### {label}", "",
                      "Coded units (" + ", ".join(f"{letters[f]} = {spec.factor(f).label}"
                                                   for f in spec.factor_names) + ", coded as below):", "",
                      f"`{equation(term_names, coef['estimate'].to_numpy(), letters, label)}`", "",
                      "Actual units" + (" (log10 of log-scaled factors)" if spec.log_factors else "") + ":", "",
                      f"`{equation(term_names, surface.actual, {f: spec.factor(f).label for f in spec.factor_names}, label)}`",
                      "", where, "", "ANOVA (block sums of squares are partial: the increase of the residual sum of "
                      "squares when the block is dropped from the full quadratic):", "",
                      markdown_table(surface.anova), "", "Coefficients in coded units:", "",
                      markdown_table(coefficients_shown(coef)), ""]
            if surface.blocked:
                lines += ["The runs were made in blocks (the table's `block` column): the fit carries a block term, "
                          "and the equations, sets and scenarios use the block-averaged surface (the response at the "
                          "mean block effect).", ""]
        if coding is not None:
            lines += ["Coding: " + "; ".join(
                f"{letters[f]} = ({'log10 ' if f in spec.log_factors else ''}{spec.factor(f).label} "
                f"{'−' if c >= 0 else '+'} {abs(c):.4g}) / {u:.4g}"
                for f, c, u in zip(coding.factors, coding.center, coding.unit)) + " (±1 = factorial levels)."]
        return [self._md("\n".join(lines))]

    def material(self, m: str) -> list:
        cfg = self.config["materials"][m]
        parts = [self._md(f"## {self._label(m)}")]
        summary = self.root / "validated" / f"{m}.json"
        if summary.is_file():
            import json

            info = json.loads(summary.read_text(encoding="utf-8"))
            types = ", ".join(f"{v} {k}" for k, v in info["point_types"].items())
            text = f"**Table check.** {info['n_runs']} runs ({types}); every factor value sits on a level of the declared design and inside the search bounds."
            waves = self._json(self.root / "waves" / f"summary_{m}.json").get("waves")
            if waves:  # a simulated material: every run demid simulated counts, not only the last wave's
                last = waves[-1]
                text = (f"**Table check.** {last['simulated']} runs simulated in {len(waves)} wave(s), "
                        f"{last['failed']} of them failed; the last wave's analysis takes its table's "
                        f"{info['n_runs']} runs ({types}) over the whole search range, every factor value "
                        "inside the search bounds (section *Waves*).")
            if info["warnings"]:
                text += "\n\n" + "\n".join(f"- ⚠ {w}" for w in info["warnings"])
            parts.append(self._md(text))
            parts += self.transcription(info.get("transcription") or {}, self._specs()[m].response_labels)
        star = "; ★ = reference point" if cfg.get("reference_point") else ""
        projected = ("; with more than two factors each panel is the set's projection onto a pair of factors "
                     "(a point is coloured when some value of the other factors is admissible)"
                     if len(cfg.get("factors", {})) > 2 else "")
        parts.append(self._md(f"**Admissible sets by scenario** (cells drawn without smoothing{star}{projected})."))
        parts.append(self._image(self.root / "figures" / f"sets_{m}.png",
                                 f"Admissible sets of {self._label(m)} per observable scenario over the search range"))
        parts.append(self._md("**Response surfaces** with design runs (○) and the target contour (dashed, where the target lies in "
                                  "the plotted range); with more than two factors, a slice through the centre of the others, "
                                  "showing only the runs on that slice."))
        parts.append(self._image(self.root / "figures" / f"surface_{m}.png",
                                 f"Fitted response surfaces of {self._label(m)} with design runs and target contours"))
        if cfg.get("pareto"):
            par = cfg["pareto"]
            said = self._specs()[m].response_labels
            text = (f"**Pareto trade-off**: relative error of {said.get(par['error_of'], par['error_of'])} vs "
                    f"predicted {said.get(par['minimise'], par['minimise'])}.")
            crit_path = self.root / "criticism" / f"{m}.json"
            if crit_path.is_file():
                import json

                from .summary import unpredictive_responses

                bad = [r for r in dict.fromkeys((par["error_of"], par["minimise"]))
                       if r in unpredictive_responses(json.loads(crit_path.read_text(encoding="utf-8")))]
                if bad:
                    text += (f" ⚠ It relies on the surrogate of {', '.join(said.get(r, r) for r in bad)}, which "
                             "does not predict left-out "
                             f"runs (Q² < 0): treat the front as indicative only.")
            parts.append(self._md(text))
            parts.append(self._image(self.root / "figures" / f"pareto_{m}.png",
                                 f"Pareto trade-off of {self._label(m)}: target error against the minimised response"))
            pareto = self._csv(f"pareto_{m}.csv")
            if pareto is not None:
                iv = pareto[pareto["kind"] == "interval"][["factor", "lower", "upper", "n_points"]]
                parts.append(self._md(f"Intervals over Pareto points with error < {100 * par['max_error']:g} %:\n\n"
                                      + markdown_table(keys_labelled(iv, self._specs()[m]))))
        parts += self.waves(m)
        parts += self.criticism(m)
        parts += self.uncertainty(m)
        parts += self.next_wave(m)
        parts += self.response_surfaces(m)
        diag = self.root / "fits" / f"{m}_diagnostics.parquet"
        if diag.is_file():
            parts.append(self._md("**Residual diagnostics** (Breusch–Pagan, RESET, Shapiro–Wilk p-values; "
                                  "largest VIF, Cook's distance, |studentised residual|)\n\n"
                                  + markdown_table(keys_labelled(read_parquet(diag), self._specs()[m]), 3)))
        return parts

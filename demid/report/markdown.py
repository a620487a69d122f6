"""The report's Markdown: tables with headers in words and numbers to their digits, keys shown as labels, labels
typeset.  Every section writes its tables and prose through these."""

from __future__ import annotations

import pandas as pd


def short_number(value, digits: int = 4) -> str:
    """A number to ``digits`` significant digits (NaN as "–"); anything else as its text."""
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


def change_text(before: float, after: float) -> str:
    """The relative change from ``before`` to ``after``, signed, in % to one decimal; "n/a" from nothing."""
    return f"{100 * (after - before) / before:+.1f} %" if before > 0 else "n/a"


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
        lines.append("| " + " | ".join(_cell(short_number(row[c], digits)) for c in cols) + " |")
    return "\n".join(lines)


def _cell(text: str) -> str:
    """A table cell's text as Markdown: a bar inside it (``|studentised residual|``) would end the cell and
    leave the whole table as raw text, so it is escaped; a line break would end the row."""
    return str(text).replace("|", "\\|").replace("\n", " ")


#: Report headers of observable_ranking.csv: what the column says, with its unit.
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


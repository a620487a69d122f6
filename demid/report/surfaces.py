"""The report's section "Response-surface models": per response the equations in coded and actual units, the
ANOVA, the coefficients and the canonical analysis, as the fit step stored them (laid out by :mod:`.rsm`); and
the residual diagnostics."""

from __future__ import annotations

from typing import TYPE_CHECKING

import pandas as pd

from ..io import read_parquet
from .glossary import term
from .markdown import keys_labelled, markdown_table

if TYPE_CHECKING:
    from .context import ReportContext


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


def response_surfaces(report: ReportContext, m: str) -> list:
    """Per response: equation (coded, actual), block ANOVA, coefficients, canonical analysis."""
    from ..surrogate import coding_from_frame
    from .rsm import canonical_text, equation, stored_surfaces, term_symbol

    table = report.root / "validated" / f"{m}.parquet"
    fits, anova = report.root / "fits" / f"{m}.parquet", report.root / "fits" / f"{m}_anova.parquet"
    if not (table.is_file() and fits.is_file() and anova.is_file()):
        return []
    spec = report.specs()[m]
    letters = {f: chr(ord("A") + i) for i, f in enumerate(spec.factor_names)}
    fit_json = report.root / "fits" / f"{m}.json"
    canonical = report.json(fit_json)
    lines = ["### Response-surface models", "", f"A {term('ridge', 'ridge')} in a canonical analysis is a "
             "direction along which the response hardly changes.", ""]
    fits = read_parquet(fits)
    coding = coding_from_frame(fits, spec.factor_names) if len(fits) else None
    # the fits and their statistics as the fit step stored them: the report does not fit again
    for surface in stored_surfaces(fits, read_parquet(anova), read_parquet(table), spec):
        label = spec.response_labels.get(surface.response, surface.response)
        coef = surface.coefficients.copy()  # the symbol column is for this table only
        coef.insert(1, "symbol", [term_symbol(t, letters) for t in coef["term"]])
        entry = canonical.get(surface.response, {}).get("canonical")
        where = canonical_text(entry, spec.factor_names, spec, letters, label) if entry is not None else ""
        term_names = coef["term"].tolist()  # keys, for the equations; the table shows labels
        coef["term"] = [t if t == "Intercept" else term_symbol(t, spec.factor_labels) for t in coef["term"]]
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
    return [report.md("\n".join(lines))]


def diagnostics(report: ReportContext, m: str) -> list:
    """The residual diagnostics of each response surface (``fits/{m}_diagnostics.parquet``)."""
    diag = report.root / "fits" / f"{m}_diagnostics.parquet"
    if not diag.is_file():
        return []
    return [report.md("**Residual diagnostics** (Breusch–Pagan, RESET, Shapiro–Wilk p-values; "
                      "largest VIF, Cook's distance, |studentised residual|)\n\n"
                      + markdown_table(keys_labelled(read_parquet(diag), report.specs()[m]), 3))]

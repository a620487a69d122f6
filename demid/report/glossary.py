"""The report's terms: each with its anchor, linked from the text (:func:`term`) and listed in the last section."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from .context import ReportContext


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


def glossary(report: ReportContext) -> list:
    """The last section: every term with its anchor."""
    return [report.md("## Terms\n\n" + "\n".join(f"- <strong id=\"term-{key}\">{name}</strong>: {text}"
                                                 for key, name, text in GLOSSARY))]


"""The data dictionary ``tables/columns.csv``: every column of every CSV the pipeline writes.

One row per table x column with its unit and a description a reader needs without the code.
Units that depend on the study (factor and response columns) name where they are configured.
"""

from __future__ import annotations

import pandas as pd

from ..sampling.domain import BOUND_TOUCH

FRACTION = "fraction (0.02 = 2 %)"
PCT = "% of Ω"
FACTOR_UNIT = "unit of the factor (config: factors.<name>.unit)"
RESPONSE_UNIT = "unit of the response (config: responses.<name>.unit)"

_COMMON = {
    "material": ("–", "Material key in the config."),
    "response": ("–", "Response (simulated observable) key in the config."),
    "scenario": ("–", "Scenario key in the config: a set of observables with one tolerance."),
    "observables": ("–", "Observables matched, joined with '+'."),
    "tolerance": (FRACTION, "Relative tolerance ε: a prediction matches when |y − y*| ≤ ε·|y*|."),
    "feasible_fraction_pct": (PCT, "Feasible fraction Φ: share of the search range Ω whose predictions match every "
                                   "target within ε, in percent."),
    "factor": ("–", "Factor (micro-parameter) key in the config."),
    "lower": (FACTOR_UNIT, "Smallest admissible value of the factor."),
    "upper": (FACTOR_UNIT, "Largest admissible value of the factor."),
    "width": (FACTOR_UNIT, "upper − lower: the admissible span W of the factor."),
    "n_observables": ("–", "Number of observables in the set."),
    "information_gain_bits": ("bit", "Kullback–Leibler divergence from the uniform prior on Ω to the posterior; one "
                                     "bit halves the plausible volume."),
    "information_gain_error_bits": ("bit", "Numerical (grid) error estimate of information_gain_bits."),
}

_TABLES: dict[str, dict[str, tuple[str, str]]] = {
    "surrogate_fit": {
        "n_runs": ("–", "Simulation runs used in the fit."),
        "r2": ("–", "Coefficient of determination R²."),
        "adj_r2": ("–", "R² adjusted for the number of model terms."),
        "rmse": (RESPONSE_UNIT, "√(SSE/n): root-mean-square residual."),
        "resid_std": (RESPONSE_UNIT, "√(SSE/(n−p)): residual standard deviation."),
        "q2": ("–", "1 − PRESS/SST: leave-one-out predictive R²."),
        "lof_f": ("–", "Lack-of-fit F statistic (lack of fit vs pure error of replicated runs)."),
        "lof_p": ("–", "p-value of the lack-of-fit F test."),
    },
    "identifiability": {
        "at_bound": ("–", f"Which ends of the factor's search range the admissible set reaches (within "
                          f"{100 * BOUND_TOUCH:g} % of the range): none, lower, upper or both. A set that reaches "
                          f"a bound may extend beyond it: widen the range there, unless the bound is the factor's "
                          f"physical limit. none when the set is empty."),
    },
    "transcription_check": {
        "statistic": ("–", "Published fit statistic checked (r2, rmse, …)."),
        "published": ("as the statistic", "Value printed in the source."),
        "reproduced": ("as the statistic", "Value recomputed from the table."),
        "agrees": ("–", "True when the reproduced value rounds to the published one."),
        "printed": ("–", "The published value as printed: trailing zeros and relation (<, >) kept; a value "
                         "printed with more than 6 significant digits is shown rounded to 6."),
        "printed_decimals": ("–", "Decimals the source printed; agreement means the reproduction lies within "
                                  "half a unit of that last printed digit."),
    },
    "robust_identifiability": {
        "z": ("–", "Standard deviations added to ε in the plausible set (z = 2 covers about 95 %)."),
        "strict_fraction_pct": (PCT, "Feasible fraction of the strict set (tolerance only)."),
        "robust_fraction_pct": (PCT, "Feasible fraction of the plausible set: tolerance plus "
                                     "z·√(se² + σ²)."),
        "strict_lower": (FACTOR_UNIT, "Smallest factor value in the strict set."),
        "strict_upper": (FACTOR_UNIT, "Largest factor value in the strict set."),
        "strict_width": (FACTOR_UNIT, "strict_upper − strict_lower."),
        "robust_lower": (FACTOR_UNIT, "Smallest factor value in the plausible set."),
        "robust_upper": (FACTOR_UNIT, "Largest factor value in the plausible set."),
        "robust_width": (FACTOR_UNIT, "robust_upper − robust_lower."),
        "strict_fraction_error_pct": (PCT, "Sampling error of strict_fraction_pct (0 on a full grid)."),
        "robust_fraction_error_pct": (PCT, "Sampling error of robust_fraction_pct (0 on a full grid)."),
        "method": ("–", "How the set was evaluated (grid or Sobol points)."),
    },
    "tolerance_sweep": {
        "fraction_error_pct": (PCT, "Sampling error of feasible_fraction_pct (0 on a full grid)."),
    },
    "information_gain": {
        "credible_lower": (FACTOR_UNIT, "Lower end of the central credible interval of the factor."),
        "credible_upper": (FACTOR_UNIT, "Upper end of the central credible interval of the factor."),
        "posterior_mean": (FACTOR_UNIT, "Posterior mean of the factor."),
        "credible_width": (FACTOR_UNIT, "credible_upper − credible_lower."),
        "credible_level": (FRACTION, "Probability content of the credible interval (0.95)."),
        "grid_points": ("–", "Grid points per axis of the posterior evaluation."),
        "sigma_basis": ("–", "Where each observable's measurement σ came from: configured sigma/sigma_rel, or the "
                             "default σ_rel = ε/2."),
    },
    "observable_ranking": {
        "rank": ("–", "Rank by information gain (1 = most informative)."),
        "contraction_pct_vs_best_subset": ("%", "How much smaller the admissible fraction is than that of "
                                                "best_subset (100 % = nothing left)."),
        "best_subset": ("–", "Most informative subset with one observable fewer ('(none)' for single observables)."),
        "gain_vs_best_subset_bits": ("bit", "Information added by the extra observable over best_subset."),
        "rank_by_fraction": ("–", "Rank by smallest feasible fraction instead (sets whose targets cannot be met "
                                  "rank last here too)."),
        "targets_reachable": ("–", "False when no point of Ω meets the set's targets within the tolerance, one "
                                   "of them alone or all together: the set then measures a discrepancy between "
                                   "simulation and experiment, not information (information_gain_bits empty), and "
                                   "ranks after every set with reachable targets."),
    },
    "criticism": {
        "cause": ("–", "Named defect of the quadratic surrogate (missing_term, response_transform, outlier, drift, "
                       "heteroscedasticity, factor_level), 'unexplained' when the runs show misfit that no "
                       "catalogued cause accounts for, or 'none' when every test came back clean."),
        "detail": ("–", "What exactly: the missing term, the transform, the outlying run, the run that fits another "
                        "factor level (factor_level), the tests that fired (unexplained, ';'-separated), …"),
        "aliases": ("–", "Readings these runs cannot tell apart from the named one, ';'-separated: the terms "
                         "aliased with a missing term, the other reading of one run (outlier or slipped factor "
                         "value), the covariates unequal scatter follows about as well."),
        "p_value": ("–", "Family-wise adjusted p-value of the finding."),
        "loo_rmse_baseline": (RESPONSE_UNIT, "Leave-one-out RMSE of the plain quadratic."),
        "loo_rmse_extended": (RESPONSE_UNIT, "Leave-one-out RMSE with the finding's extension."),
        "delta_aicc": ("–", "AICc of the extension minus AICc of the quadratic (negative = better)."),
        "message": ("–", "The finding in words."),
        "verdict": ("–", "What the evidence supports for this response (repeated on each of its rows): 'adequate' "
                         "(no test fired; the message says what size of defect could have been missed), 'defect' "
                         "(cause named), 'ambiguous' (two or more causes explain the misfit about equally: the "
                         "row's cause is 'ambiguous', its detail the candidates), 'unexplained' (misfit, cause not "
                         "singled out) or 'does_not_predict' (Q² < 0: do not use the surrogate to decide "
                         "admissibility)."),
        "discriminating_runs": ("–", "On the row they serve, the runs the criticism proposes (JSON list of points, "
                                     "each with its purpose): those that decide between the candidates of an "
                                     "'ambiguous' row, or those that would confirm or correct a named cause. A next "
                                     "wave makes them first, those inside its refocused box. The column is present "
                                     "only when some response has such runs."),
    },
    "calibration_residuals": {
        "observable": ("–", "Observable with a measured target."),
        "target": (RESPONSE_UNIT, "Measured target y*."),
        "at_best": (RESPONSE_UNIT, "Predicted value at the best point (smallest largest relative error, each "
                                   "observable's weighed by ε/ε_k against its own tolerance where one is configured)."),
        "rel_error_best": (FRACTION, "(prediction − target)/target at the best point."),
        "at_reference": (RESPONSE_UNIT, "Predicted value at the configured reference point."),
        "rel_error_reference": (FRACTION, "(prediction − target)/target at the reference point."),
        "tolerance": (FRACTION, "This observable's relative tolerance ε_k: its own (responses.<r>.tolerance, or "
                                "tolerance_abs / |target|) or the scenario's."),
        "within_tolerance": ("–", "|rel_error_best| ≤ tolerance."),
        "within_tolerance_reference": ("–", "|rel_error_reference| ≤ tolerance (empty without reference point)."),
        "bottleneck": ("–", "True for the observable that keeps the targets from being met together."),
        "max_error_without": (FRACTION, "Best achievable largest relative error when this observable is left out "
                                        "(each weighed by ε/ε_k where observables have their own tolerance)."),
        "implied_bias": (FRACTION, "Smallest relative simulation bias this observable would need while the other "
                                   "targets are met as well as they can be (0 when every target can be met within "
                                   "the tolerance together)."),
        "bias_candidate": ("–", "True when leaving this observable out makes every other target reachable: the "
                                "simulation may be biased in it."),
    },
    "paper_comparison": {
        "quantity": ("–", "Published number compared (paper table/figure and what)."),
        "published": ("as the quantity", "Value in the paper."),
        "reproduced": ("as the quantity", "Value computed here."),
        "abs_diff": ("as the quantity", "|reproduced − published|."),
        "rel_diff": (FRACTION, "abs_diff/|published|."),
        "tolerance": ("–", "Agreement required, as text (absolute '±0.005' or relative '±2 % rel')."),
        "pass": ("–", "True when the difference is within the tolerance."),
        "printed_agrees": ("–", "True when the reproduction, rounded to the decimals the paper printed, equals "
                                "the printed value."),
    },
    "next_domain": {
        "lower": ("unit of the factor", "Lower end of the refocused search range for the next wave (a simulated "
                                        "material's waves: of the box that holds the next wave's runs, placed "
                                        "over the whole search range)."),
        "upper": ("unit of the factor", "Upper end of the same range."),
    },
    "verdicts": {
        "strict_lower": (FACTOR_UNIT, "Lower end of the strict admissible interval (identifiability.csv): the set if surrogate "
                                      "and measurements were exact."),
        "strict_upper": (FACTOR_UNIT, "Upper end of the strict admissible interval."),
        "plausible_lower": (FACTOR_UNIT, "Lower end of the plausible interval: |ŷ − y*| ≤ z·√(se² + σ² + δ²) for "
                                         "every observable (σ = ε·|y*|/z where no σ is configured); empty when no "
                                         "point is plausible."),
        "plausible_upper": (FACTOR_UNIT, "Upper end of the plausible interval."),
        "verdict": ("–", "Judged on the plausible interval: identified, bounded, unresolved, cut by the search range "
                         "(lower/upper bound), no admissible point or uninformative observable."),
        "reason": ("–", "Why, in words, with the strict interval where its verdict differs."),
    },
    "advice": {
        "kind": ("–", "check_target, recalibrate, add_observable, widen, next_runs or stop; measurement_order: "
                      "one sentence of the observable ranking in words (which measurement next, set by set)."),
        "factor": ("–", "Factor key of a widen advice, or of a recalibrate advice on a bound that widening "
                        "cannot help (empty otherwise)."),
        "bound": ("–", "lower or upper: the bound to move outwards (widen), or the one not worth moving "
                       "(recalibrate)."),
        "observable": ("–", "Response key the advice is about (check_target, recalibrate, add_observable)."),
        "text": ("–", "The advice as the report prints it (summary, level 2, the observable ranking or the "
                      "next-wave section)."),
        "decision": ("–", "True for the material's one next step (the first advice by priority: check_target, "
                          "recalibrate, widen, next_runs, add_observable, stop); the summary lists the others "
                          "below it as 'also'."),
    },
    "model_extensions": {
        "extends": ("–", "The material whose model this one extends (config key materials.<m>.extends)."),
        "added_factors": ("–", "Factors of this material the extended one does not vary, joined by '+'."),
        "best_error_before": (FRACTION, "Largest |relative error| at the best point of the extended material "
                                        "(level 2's best_max_error in criticism/<extends>.json)."),
        "best_error_after": (FRACTION, "The same for this material."),
        "feasible_fraction_before_pct": (PCT, "Admissible fraction of Ω of the scenario for the extended material "
                                              "(identifiability.csv)."),
        "feasible_fraction_after_pct": (PCT, "The same for this material."),
        "surrogate_q2_before": ("–", "Lowest leave-one-out Q² of the extended material's surrogates of the "
                                     "scenario's observables (surrogate_fit.csv): below 0.5 its admissible fraction "
                                     "is what a surrogate that does not predict well enough says, and the report "
                                     "says so beside it."),
        "surrogate_q2_after": ("–", "The same for this material."),
    },
    "next_runs": {
        "proposal": ("–", "Number of the proposed run (1..count)."),
        "purpose": ("–", "Why the run is proposed: first the criticism's runs, to decide between causes it cannot "
                         "tell apart ('decide between causes') and then to confirm or correct a named cause "
                         "('confirm the named cause'); then a design run in the refocused box "
                         "(over the whole box, so its edges are supported, or on the band near the plausible set), "
                         "or, for a simulated material's waves, over the whole search range where the "
                         "classification of the set is most uncertain or where the surrogate is least certain; "
                         "or a run that separates terms the criticism found aliased."),
    },
}

_PARETO = {
    "kind": ("–", "'front': a Pareto-optimal grid point; 'interval': factor range over front points below "
                  "max_error."),
    "error": (FRACTION, "Relative error of the pareto.error_of response at the point."),
    "objective": (RESPONSE_UNIT, "Predicted value of the pareto.minimise response."),
    "factor": ("–", "Factor of an interval row."),
    "lower": (FACTOR_UNIT, "Smallest factor value over front points with error below max_error."),
    "upper": (FACTOR_UNIT, "Largest factor value over front points with error below max_error."),
    "n_points": ("–", "Front points with error below max_error."),
}

#: Columns of each table in the order they are written (the common ones included).
TABLE_COLUMNS = {
    "surrogate_fit": ["material", "response", "n_runs", "r2", "adj_r2", "rmse", "resid_std", "q2", "lof_f", "lof_p"],
    "identifiability": ["material", "scenario", "observables", "tolerance", "feasible_fraction_pct", "factor",
                        "lower", "upper", "width", "at_bound"],
    "transcription_check": ["material", "response", "statistic", "published", "reproduced", "agrees", "printed",
                            "printed_decimals"],
    "robust_identifiability": ["material", "scenario", "observables", "tolerance", "z", "factor",
                               "strict_fraction_pct", "robust_fraction_pct", "strict_lower", "strict_upper",
                               "strict_width", "robust_lower", "robust_upper", "robust_width",
                               "strict_fraction_error_pct", "robust_fraction_error_pct", "method"],
    "tolerance_sweep": ["material", "scenario", "observables", "tolerance", "feasible_fraction_pct", "factor", "lower",
                        "upper", "width", "fraction_error_pct"],
    "information_gain": ["material", "observables", "n_observables", "information_gain_bits", "factor",
                         "credible_lower", "credible_upper", "posterior_mean", "credible_width", "credible_level",
                         "information_gain_error_bits", "grid_points", "sigma_basis"],
    "observable_ranking": ["material", "rank", "observables", "information_gain_bits", "feasible_fraction_pct",
                           "contraction_pct_vs_best_subset", "n_observables", "best_subset",
                           "gain_vs_best_subset_bits", "information_gain_error_bits", "tolerance", "rank_by_fraction",
                           "targets_reachable"],
    "criticism": ["material", "response", "cause", "detail", "aliases", "p_value", "loo_rmse_baseline",
                  "loo_rmse_extended", "delta_aicc", "message", "verdict", "discriminating_runs"],
    "calibration_residuals": ["material", "observable", "target", "at_best", "rel_error_best", "at_reference",
                              "rel_error_reference", "tolerance", "within_tolerance", "within_tolerance_reference",
                              "bottleneck", "max_error_without", "implied_bias", "bias_candidate"],
    "verdicts": ["material", "scenario", "factor", "strict_lower", "strict_upper", "plausible_lower",
                 "plausible_upper", "verdict", "reason"],
    "advice": ["material", "kind", "factor", "bound", "observable", "text", "decision"],
    "model_extensions": ["material", "extends", "added_factors", "best_error_before", "best_error_after",
                         "feasible_fraction_before_pct", "feasible_fraction_after_pct", "scenario",
                         "surrogate_q2_before", "surrogate_q2_after"],
    "paper_comparison": ["quantity", "material", "published", "reproduced", "abs_diff", "rel_diff", "tolerance",
                         "pass", "printed_agrees"],
}


def _describe(table: str, column: str) -> tuple[str, str]:
    own = _TABLES.get(table, {})
    if column in own:
        return own[column]
    return _COMMON[column]


def _next_wave_rows(next_wave: dict) -> list[tuple]:
    """Rows of the next-wave tables; ``next_wave`` maps factors and responses to their units."""
    if not next_wave:
        return []
    rows = [("next_domain.csv", c, *(_describe("next_domain", c) if c in ("lower", "upper") else _COMMON[c]))
            for c in ("material", "factor", "lower", "upper")]
    rows += [("next_runs.csv", c, *(_COMMON[c] if c == "material" else _describe("next_runs", c)))
             for c in ("material", "proposal")]
    for name, unit in next_wave["factors"]:
        rows.append(("next_runs.csv", name, unit if unit and unit != "-" else "–", f"Factor {name} of the run."))
    rows.append(("next_runs.csv", "purpose", *_describe("next_runs", "purpose")))
    for name, unit in next_wave["responses"]:
        rows.append(("next_runs.csv", f"predicted_{name}", unit if unit and unit != "-" else "–",
                     f"Surrogate prediction of {name} at the run."))
    return rows


_COMBINATIONS = {
    "set": ("–", "strict: the admissible set; plausible: the admissible set with the tolerance widened by z standard deviations "
                 "of the surrogate's mean and of the measurement."),
    "direction": ("–", "Principal axis of the set in coded units, 1 = narrowest (the identified combination when "
                       "narrow), widest last."),
    "width_coded": ("coded unit", "√12 × standard deviation of the set along the direction: the full width of a "
                                  "uniform slab with the same spread (a straight band's thickness)."),
    "width_fraction_of_range": ("–", "width_coded / the search range's own extent along the direction "
                                     "(Σ |loading| × coded range): 1 fills the range, near 0 is a thin band."),
}


def _combination_rows(factors: list[str]) -> list[tuple]:
    """Rows of ``combinations.csv``: one loading column per factor of every material."""
    if not factors:
        return []
    rows = [("combinations.csv", c, *_COMMON[c]) for c in ("material", "scenario")]
    rows += [("combinations.csv", c, *_COMBINATIONS[c]) for c in ("set", "direction")]
    rows += [("combinations.csv", f, "–", f"Loading of factor {f} on the direction (coded units, log10 for a "
                                          f"log-scaled factor; unit-length vector; empty for materials without {f}).")
             for f in factors]
    rows += [("combinations.csv", c, *_COMBINATIONS[c]) for c in ("width_coded", "width_fraction_of_range")]
    return rows


def columns_table(pareto_factors: dict[str, list[tuple[str, str]]], next_wave: dict | None = None,
                  combination_factors: list[str] | None = None) -> pd.DataFrame:
    """The data dictionary; ``pareto_factors`` maps each Pareto material to its (factor, unit) pairs;
    ``next_wave`` holds the (name, unit) pairs of the factors and responses of next-wave materials;
    ``combination_factors`` the factor names that have a loading column in ``combinations.csv``."""
    rows = _next_wave_rows(next_wave or {}) + _combination_rows(list(combination_factors or []))
    for table, columns in TABLE_COLUMNS.items():
        for column in columns:
            unit, description = _describe(table, column)
            rows.append((f"{table}.csv", column, unit, description))
    for material, factors in pareto_factors.items():
        table = f"pareto_{material}.csv"
        rows.append((table, "kind", *_PARETO["kind"]))
        for name, unit in factors:
            rows.append((table, name, unit if unit and unit != "-" else "–",
                         f"Factor {name} of a front point."))
        for column in ("error", "objective", "factor", "lower", "upper", "n_points"):
            rows.append((table, column, *_PARETO[column]))
    rows.append(("columns.csv", "table", "–", "CSV file under tables/ that the row describes."))
    rows.append(("columns.csv", "column", "–", "Column name in that file."))
    rows.append(("columns.csv", "unit", "–", "Unit of the column's values ('–' for none or text)."))
    rows.append(("columns.csv", "description", "–", "What the column holds."))
    return pd.DataFrame(rows, columns=["table", "column", "unit", "description"])

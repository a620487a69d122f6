"""Plausible developer bugs in the input and story modules (tables, printed values, designs, the sentences a
user reads), each written by reading the module, before any test was written against it.

First run (on 410120f, before any test was written against these mutants): 14 of 16 killed, 87.5 %.  Survivors:
recommended point_on_edge_text's hull judged in actual units (the existing tests' hulls were boxes, which a
per-factor monotone map keeps boxes); design_inference _levels' median of a level printed two ways taken as the mean
(no test had a level printed two ways by three or more runs).
After: 16 of 16 killed (tests/story/test_point_outside_runs_whole.py: a star of runs whose hull is no box, log and
linear ranges; tests/inputs/test_level_printed_two_ways_whole.py: one factorial run off its level by a last-digit
slip leaves every inferred axial distance).
"""
from hand_mutants import HandMutant

MUTANTS = [
    HandMutant(
        "demid/story/measurements.py",
        "share(100 * (1 - f_new / base_frac))",
        "share(base_frac - f_new)",
        reads_wrong="the measurement order says the admissible fraction shrinks by the difference in percentage "
                    "points, not by the share of the smaller set's fraction"),
    HandMutant(
        "demid/story/verdicts.py",
        "    f = np.log10 if log else (lambda v: v)\n    width = (f(upper) - f(lower))",
        "    f = (lambda v: v)\n    width = (f(upper) - f(lower))",
        reads_wrong="a log-scale factor's interval width (and so its verdict) is measured in actual units, not "
                    "in decades of its search range"),
    HandMutant(
        "demid/story/extensions.py",
        "return float(q2.min()) if len(set(rows[\"response\"]))",
        "return float(q2.mean()) if len(set(rows[\"response\"]))",
        reads_wrong="the model extension's surrogate Q² is the average over the scenario's observables, so a "
                    "weak surrogate hides behind a good one and the 'not yet the answer' caveat is missing"),
    HandMutant(
        "demid/story/extensions.py",
        "\"surrogate_q2_before\": _lowest_q2(surrogate_fit, base, observables[base])",
        "\"surrogate_q2_before\": _lowest_q2(surrogate_fit, name, observables[base])",
        reads_wrong="the Q² quoted for the model before the extension is the extended model's"),
    HandMutant(
        "demid/story/advice.py",
        "best = grow.sort_values(\"gain_vs_best_subset_bits\", ascending=False).iloc[0]",
        "best = grow.sort_values(\"feasible_fraction_pct\").iloc[0]",
        reads_wrong="the add-observable advice names the observable leaving the smallest fraction, not the one "
                    "that gains the most information"),
    HandMutant(
        "demid/story/advice.py",
        "shrink the plausible set of *{label}* by about {100 * shrink:.0f} %",
        "shrink the plausible set of *{label}* by about {100 * (1 - shrink):.0f} %",
        reads_wrong="the next-runs advice quotes the share of the plausible set that remains as its shrinkage"),
    HandMutant(
        "demid/story/recommended.py",
        "        z = (domain.to_search(np.asarray(runs, dtype=float)) - lo) / span\n"
        "        u = (domain.to_search(np.array([[point[f] for f in spec.factor_names]], dtype=float))[0] - lo) / span",
        "        z = (np.asarray(runs, dtype=float) - lo) / span\n"
        "        u = (np.array([[point[f] for f in spec.factor_names]], dtype=float)[0] - lo) / span",
        reads_wrong="whether the recommended point lies outside the design runs' hull is judged in actual units "
                    "against log10 search bounds, so a log-scale factor's point is called covered or not wrongly"),
    HandMutant(
        "demid/scenario.py",
        "return float(cfg[\"sigma_rel\"]) * abs(float(target))",
        "return float(cfg[\"sigma_rel\"]) * float(target)",
        reads_wrong="a negative target's measurement σ from sigma_rel is negative"),
    HandMutant(
        "demid/tolerance.py",
        "coefficients[intercept[0]] += (1.0 - scale) * float(target)",
        "coefficients[intercept[0]] += (scale - 1.0) * float(target)",
        reads_wrong="an observable with its own tolerance is judged by a surrogate shifted the wrong way, so its "
                    "strict and plausible sets are wrong"),
    HandMutant(
        "demid/paper.py",
        "rep = 100.0 * (after / before - 1.0) if before else math.nan",
        "rep = 100.0 * (1.0 - after / before) if before else math.nan",
        reads_wrong="the reproduced contraction has the opposite sign of the published one"),
    HandMutant(
        "demid/data.py",
        "for power in sorted((p for p in range(-6, 7) if p), key=abs):",
        "for power in (p for p in range(-6, 7) if p):",
        reads_wrong="a unit-slip repair names the first power of ten from 1e-6 up that lands in the simulated "
                    "range, not the nearest one"),
    HandMutant(
        "demid/blocks.py",
        "se = np.sqrt(np.maximum(np.einsum(\"ij,jk,ik->i\", contrasts, cov, contrasts), 0.0))",
        "se = np.sqrt(np.maximum((contrasts ** 2) @ np.diag(cov), 0.0))",
        reads_wrong="the block effects' standard errors ignore the covariance of the effect-coded coefficients"),
    HandMutant(
        "demid/design_inference.py",
        "levels = np.array([float(np.median(g)) for g in groups])",
        "levels = np.array([float(np.mean(g)) for g in groups])",
        reads_wrong="a level printed two ways is read at the mean of its values, so the inferred axial distance "
                    "moves with a single off value"),
    HandMutant(
        "demid/transcription/typos.py",
        "se = s_loo * np.sqrt(1 + h / (1 - h))",
        "se = s_loo",
        reads_wrong="the likely-typo flag's prediction error from the other runs leaves out the run's leverage, "
                    "so too few repairs fit and the quoted prediction_se is too small"),
    HandMutant(
        "demid/transcription/printed.py",
        "        number, inferred = number.scaleb(-2), inferred + 2",
        "        number, inferred = number.scaleb(-2), inferred",
        reads_wrong="a percentage printed as 98.27% is judged to 2 decimals of the fraction, not 4, so a "
                    "reproduction off in the third decimal agrees"),
    HandMutant(
        "demid/transcription/engine.py",
        "\"rmse\": np.sqrt(sse / n),",
        "\"rmse\": np.sqrt(sse / (n - p)),",
        reads_wrong="the reproduced RMSE is the residual standard deviation (n - p), so a published RMSE is "
                    "reported as not reproduced"),
]

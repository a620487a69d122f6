"""Hand-written mutants of the numerical core's user-facing results: the observable ranking, the grid posterior,
the plausible and swept sets, the Pareto front, the canonical analysis, the principal axes of a set and the
number formatting every sentence uses.  Each changes a number or a decision a user reads, for some valid input.

First run (held out: written before any test aimed at them; on the code and tests of 4ca6908, the suite as it stood
before this catalogue plus one ranking test written for an earlier survivor): **16 of 16 killed (100 %)**, no
survivor.  The suite already checked these outputs against independent computations (brute-force fronts, closed-form
posteriors, rsm's canonical rules, written-out principal axes, shares read apart), so the catalogue stays as a
regression check.
"""
from hand_mutants import HandMutant

FIRST_RUN = "16 of 16 killed (100 %); no survivor"

MUTANTS = [
    # --- uncertainty/ranking.py
    HandMutant(
        "demid/uncertainty/ranking.py",
        "        best = min(proper, key=lambda t: (frac[t], -gain[t]))",
        "        best = min(proper, key=lambda t: (frac[t], gain[t]))",
        reads_wrong="between two proper subsets of equal fraction, best_subset is the one with the smaller gain, "
                    "so 'measure X as well: it adds N bits' quotes the gain over the less informative subset"),
    HandMutant(
        "demid/uncertainty/ranking.py",
        "    by_fraction = frame[\"feasible_fraction_pct\"].where(reachable_rows, np.inf)\n"
        "    frame[\"rank_by_fraction\"] = by_fraction.rank(method=\"min\").astype(int)",
        "    frame[\"rank_by_fraction\"] = frame[\"feasible_fraction_pct\"].rank(method=\"min\").astype(int)",
        reads_wrong="a set whose targets are out of reach (fraction 0) ranks first by fraction: the narrowest "
                    "set named is one that no point meets"),
    HandMutant(
        "demid/uncertainty/ranking.py",
        "        contraction = 100.0 * (1.0 - frac[s] / frac[best]) if frac[best] > 0 else np.nan",
        "        contraction = 100.0 * (1.0 - frac[s] / frac[(s[0],)]) if frac[(s[0],)] > 0 else np.nan",
        reads_wrong="the contraction of a set is taken against its first observable, not against its narrowest "
                    "proper subset: 'shrinks the admissible fraction by N %' quotes the wrong N"),
    # --- uncertainty/posterior.py
    HandMutant(
        "demid/uncertainty/posterior.py",
        "        means.append(float(np.dot(weights[i], m * actual)))",
        "        means.append(float(10.0 ** np.dot(weights[i], m * axes[i]) if lg else np.dot(weights[i], m * actual)))",
        reads_wrong="the posterior mean of a log-scale factor is the geometric mean (10 ** mean of log10), not "
                    "the mean in actual units the column promises"),
    HandMutant(
        "demid/uncertainty/posterior.py",
        "    var = se ** 2 + float(sigma) ** 2",
        "    var = float(sigma) ** 2 + (se ** 2 if predictive else 0.0)",
        reads_wrong="the likelihood leaves out the surrogate's own standard error of the mean: posteriors and "
                    "information gains come out too sharp where the surrogate is uncertain"),
    HandMutant(
        "demid/uncertainty/posterior.py",
        "    tail = (1.0 - level) / 2\n    for i, lg in enumerate(domain.log):\n        m = _weighted_sum(p, weights, keep=i)",
        "    tail = 1.0 - level\n    for i, lg in enumerate(domain.log):\n        m = _weighted_sum(p, weights, keep=i)",
        reads_wrong="the 95 % credible interval is cut at the 5 % and 95 % quantiles: a 90 % interval reported "
                    "as 95 %"),
    # --- uncertainty/plausible.py
    HandMutant(
        "demid/uncertainty/plausible.py",
        "            \"strict_lower\": strict.lower, \"strict_upper\": strict.upper, \"strict_width\": strict.width,",
        "            \"strict_lower\": strict.lower, \"strict_upper\": strict.upper, \"strict_width\": plausible.width,",
        reads_wrong="the strict set's width column repeats the plausible set's width"),
    # --- uncertainty/sweep.py
    HandMutant(
        "demid/uncertainty/sweep.py",
        "        for eps in sorted(set(float(t) for t in tolerances) | {float(nominal)}):",
        "        for eps in sorted(set(float(t) for t in tolerances)):",
        reads_wrong="the sweep leaves out the scenario's own nominal tolerance when it is not one of the sweep's, "
                    "so the table does not repeat the scenario's fraction"),
    # --- pareto.py
    HandMutant(
        "demid/pareto.py",
        "    below = front[front[\"error\"] < max_error]",
        "    below = front[front[\"error\"] <= max_error]",
        reads_wrong="front points whose error equals the cap are counted in the factor intervals and n_points"),
    HandMutant(
        "demid/pareto.py",
        "    error = np.abs(relative_error(grid[error_of].to_numpy(), target))\n    objective = grid[minimise].to_numpy()",
        "    error = relative_error(grid[error_of].to_numpy(), target)\n    objective = grid[minimise].to_numpy()",
        reads_wrong="the signed error is minimised: points far below the target look best and the front runs "
                    "off to the under-predicting side"),
    # --- canonical.py
    HandMutant(
        "demid/canonical.py",
        "    kind = \"rising ridge\" if np.any(rising) and not common[\"inside\"] else \"stationary ridge\"",
        "    kind = \"rising ridge\" if np.any(rising) else \"stationary ridge\"",
        reads_wrong="a ridge whose stationary point lies inside the region is called rising when its slope is "
                    "large, though the optimum lies inside"),
    HandMutant(
        "demid/canonical.py",
        "    radius = float(np.linalg.norm(hi - lo) / 2)",
        "    radius = float(np.max(hi - lo) / 2)",
        reads_wrong="the region's radius is the half-side, not the half-diagonal: a ridge between the two is "
                    "called rising instead of stationary (or the other way)"),
    # --- combinations/axes.py
    HandMutant(
        "demid/combinations/axes.py",
        "    extent = np.abs(vectors).T @ ranges",
        "    extent = np.sqrt((vectors ** 2).T @ ranges ** 2)",
        reads_wrong="the box's extent along a direction is the Euclidean norm, not the sum of |v_i| range_i: "
                    "width fractions of oblique directions come out too large and 'identified in combination' is "
                    "missed"),
    HandMutant(
        "demid/combinations/axes.py",
        "        return float(self.fractions[order][np.searchsorted(cum, cum[-1] / 2)])",
        "        return float(np.mean(self.fractions))",
        reads_wrong="the local thickness is the plain mean of the cells' fractions, not the point-weighted median"),
    # --- precision.py
    HandMutant(
        "demid/precision.py",
        "    place = max(place_of(uncertainty), own)",
        "    place = place_of(uncertainty)",
        reads_wrong="a value with a tiny uncertainty is printed with more significant digits than MAX_DIGITS"),
    HandMutant(
        "demid/precision.py",
        "        if texts[0] != texts[1] or before == after:\n            break",
        "        if texts[0] != texts[1] or before == after:\n            return texts\n        break",
        reads_wrong="two shares that read alike at 3 digits are not written to more digits: '1.61 % -> 1.61 %' "
                    "beside a +0.4 % change"),
]

"""Hand-written mutants of the numerical core, second catalogue: the ranking's gain over the best subset, the
posteriors' information gain and its error above three factors, the canonical analysis' quadratic form and its kind,
the wave loop's stop evidence and measured change, and the combination sentence's half-width.  Each changes a number
or a decision a user reads, for some valid input; none repeats a mutant of the earlier catalogues.

First run (held out: written and committed before any test aimed at them; on the code and tests of d64c2d5 plus the
tests then added for the coverage triage's never-run lines and the seed-45 draw, none aimed at these): **8 of 8 killed
(100 %)**, no survivor: each killed within seconds by the module's existing test subset, so the catalogue stays as a
regression check.
"""
from hand_mutants import HandMutant

FIRST_RUN = "8 of 8 killed (100 %); no survivor"

MUTANTS = [
    # --- uncertainty/ranking.py
    HandMutant(
        "demid/uncertainty/ranking.py",
        "            \"gain_vs_best_subset_bits\": gain[s] - gain[best],",
        "            \"gain_vs_best_subset_bits\": gain[s] - np.nanmax([gain[t] for t in proper]),",
        reads_wrong="the gain over the best subset is taken over the most informative proper subset, not over "
                    "best_subset (the narrowest one) the row names: 'measure X as well: it adds N bits' quotes a "
                    "smaller N whenever the narrowest subset is not the most informative"),
    # --- uncertainty/posterior.py
    HandMutant(
        "demid/uncertainty/posterior.py",
        "        term = np.where(p > 0, p * (ll - np.log(z) + np.log(volume)), 0.0)",
        "        term = np.where(p > 0, p * (ll - np.log(z)), 0.0)",
        reads_wrong="the information gain is taken against a prior density of 1 per search unit, not 1/volume of "
                    "Omega: every gain shifts by log2 of the domain's volume (bits a user compares across sets "
                    "and materials)"),
    HandMutant(
        "demid/uncertainty/posterior.py",
        "float(np.std(per_rep, ddof=1) / np.sqrt(replicates)) / LN2,",
        "float(np.std(per_rep, ddof=1)) / LN2,",
        reads_wrong="above three factors the information gain's error is the scatter of one scramble, not the "
                    "standard error of the mean of eight: the error column is sqrt(8) times too large"),
    # --- canonical.py
    HandMutant(
        "demid/canonical.py",
        "                big_b[i, j] += coef / 2\n                big_b[j, i] += coef / 2",
        "                big_b[i, j] += coef\n                big_b[j, i] += coef",
        reads_wrong="the two-factor interaction enters B whole on both sides of the diagonal (x'Bx counts it "
                    "twice): eigenvalues, the stationary point and the kind of a surface with an interaction "
                    "come out wrong"),
    HandMutant(
        "demid/canonical.py",
        "        kind = \"maximum\" if np.all(values < 0) else",
        "        kind = \"maximum\" if np.any(values < 0) else",
        reads_wrong="a saddle point (eigenvalues of both signs, none small) is called a maximum"),
    # --- waves.py
    HandMutant(
        "demid/waves.py",
        "    return bool(shares) and all(s is not None and np.isfinite(s) and s <= BAND_FIXED_SHARE for s in shares)",
        "    return bool(shares) and any(s is not None and np.isfinite(s) and s <= BAND_FIXED_SHARE for s in shares)",
        reads_wrong="the tolerance band counts as fixed when one surrogate's leave-one-out error is small, though "
                    "another's still moves the boundary: the loop stops after the first wave"),
    HandMutant(
        "demid/waves.py",
        "    return (evidence.plausible_pct - evidence.previous_pct) / evidence.previous_pct",
        "    return (evidence.plausible_pct - evidence.previous_pct) / evidence.plausible_pct",
        reads_wrong="the measured change of the plausible share is relative to the new share, not the previous "
                    "one: '(-40.0 %)' reads '(-66.7 %)', and the stop rule compares the wrong number"),
    # --- combinations/axes.py
    HandMutant(
        "demid/combinations/axes.py",
        "    w = width / 2\n",
        "    w = width\n",
        reads_wrong="the combination sentence 'mu_r + 1.63 log10 gamma = 2.37 +- w' quotes the full width of the "
                    "band as its half-width"),
]

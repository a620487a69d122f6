"""A second catalogue of hand-written mutants of the modules that write numbers into sentences and tables (issue #40).

Written by reading demid/criticism/messages.py, demid/criticism/material.py, the report's summary, plausible and
model-criticism sections and demid/published_values.py again, after the first catalogue (sentences.py) was killed
and before any test was written against these: each changes a number or a decision a user reads, and none repeats a
bug of the earlier catalogues.

First run (held-out: no test written against these yet; the rows' test subsets of commit 154c6ed, run from an
export of that commit): **6 of 8 killed, 75.0 %**.  Survivors: level 2's set taken from a scenario of the same
observables at another tolerance than the reference one; the nearest admissible point's values zipped with the
config's factor order instead of read by name.

After the whole-output tests (tests/criticism/test_material_level2_sets_whole.py: level 2's feasibility and bound
reach against linear programs, with a scenario of the same observables at a looser tolerance listed first;
tests/report/test_report_edges_whole.py: the nearest point's values stored in another order than the config's):
8 of 8 killed.
"""
from hand_mutants import HandMutant

M = "demid/criticism/messages.py"
MAT = "demid/criticism/material.py"
S = "demid/report/summary.py"
P = "demid/report/plausible.py"
MC = "demid/report/model_criticism.py"
PV = "demid/published_values.py"

MUTANTS = [
    HandMutant(M, "    ratio = abs(errors[worst]) / own[worst]\n", "    ratio = abs(errors[worst]) / tolerance\n",
               reads_wrong="level 2's worst observable said to miss by '1.6 times its tolerance of 0.33 %' where it "
                           "misses by 9.3 times it: the multiple taken of the scenario's tolerance, not of its own"),
    HandMutant(M, "span = slope * float(np.ptp(data.runs.astype(float)))", "span = slope * (len(data.runs) - 1)",
               reads_wrong="a drift's change 'from first to last run' counted over the number of runs, not over "
                           "the run numbers: too small when the run numbers have gaps (failed runs left out)"),
    HandMutant(MAT, "if set(sc.observables) == set(with_targets)\n                and sc.tolerance == "
                    "spec.reference_tolerance]",
               "if set(sc.observables) == set(with_targets)]",
               reads_wrong="level 2 decides 'every target can be met' from a scenario of the same observables at "
                           "another (looser) tolerance than the one it judges"),
    HandMutant(MAT, "distance = 0.0 if inside else float(100 * np.sqrt(np.sum((u[k] - u_ref) ** 2)))",
               "distance = 0.0 if inside else float(100 * np.sqrt(np.mean((u[k] - u_ref) ** 2)))",
               reads_wrong="the reference point's distance from a sampled set quoted as a root-mean-square offset "
                           "per factor: half the distance with four factors"),
    HandMutant(S, "        digits = digits_for(hi - lo)\n", "        digits = digits_for(hi)\n",
               reads_wrong="the recommended point and its plausible interval printed to the digits of the upper end, "
                           "not of the interval's width: 0.5 (plausible 0.5–0.6) for 0.547 (0.521–0.583)"),
    HandMutant(P, 'ranking["targets_reachable"].astype(str).str.lower().eq("true").all()',
               'ranking["targets_reachable"].astype(str).str.lower().eq("true").any()',
               reads_wrong="the ranking's 'targets reachable' column dropped as soon as one set can be met: the sets "
                           "whose targets cannot be met are no longer marked"),
    HandMutant(MC, 'for f, v in in_order(pos["nearest_admissible"],\n'
                   '                                                                                      '
                   'spec.factor_names))',
               'for f, v in zip(spec.factor_names, pos["nearest_admissible"].values()))',
               reads_wrong="the nearest admissible point's values printed under the wrong factors when the JSON's "
                           "keys are not in the config's order (Beta = the value of Alpha)"),
    HandMutant(PV, 'c.number(path + ["value"], item["value"], -100, math.inf, "contraction in %")',
               'c.number(path + ["value"], item["value"], 0, math.inf, "contraction in %")',
               reads_wrong="a published contraction below zero (the set widened from one scenario to the next) "
                           "refused as impossible"),
]

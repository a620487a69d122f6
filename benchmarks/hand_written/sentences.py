"""Hand-written mutants of the modules that write numbers into sentences and tables (issue #40).

Written by reading demid/criticism/messages.py, demid/criticism/material.py and the report's summary, columns,
plausible, loop and model-criticism sections and demid/published_values.py, before any test was written against
them: each changes a number or word a user reads.

First run (held-out: no test written against these yet; the rows' test subsets of commit ad302ff): **7 of 16
killed, 43.8 %**.  Survivors: and_list joined with " and " throughout; the outlier's "the other runs predict" quoting
the observed value; unequal scatter's factor without 1 / ratio when it shrinks; level 2's worst observable by raw
error, not against its own tolerance; an extension's fraction after read from the set before; the summary's "wide"
list only for unresolved factors; the data dictionary's at_bound share without the factor 100; the reference point
judged within/outside against the shared tolerance; a reference point's error printed without its sign.

After the whole-output tests (tests/criticism/test_finding_sentences_whole.py, test_material_step_whole.py,
tests/report/test_report_sentences_whole.py, test_columns_whole.py, tests/inputs/test_published_values_whole.py):
16 of 16 killed.
"""
from hand_mutants import HandMutant

M = "demid/criticism/messages.py"
MAT = "demid/criticism/material.py"
S = "demid/report/summary.py"
C = "demid/report/columns.py"
P = "demid/report/plausible.py"
L = "demid/report/loop.py"
MC = "demid/report/model_criticism.py"
PV = "demid/published_values.py"

MUTANTS = [
    HandMutant(M, 'f"cuts the leave-one-out error by {100 * (1 - ratio):.0f} %"',
               'f"cuts the leave-one-out error by {100 * ratio:.0f} %"',
               reads_wrong="a 40 % cut of the leave-one-out error printed as 'by 60 %' (the ratio kept, not the cut)"),
    HandMutant(M, "    if ratio <= 1.005:\n", "    if ratio <= 1.05:\n",
               reads_wrong="a 3 % loss of leave-one-out error reported as 'unchanged' (the band widened ten-fold)"),
    HandMutant(M, 'names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]',
               'names[0] if len(names) == 1 else " and ".join(names)',
               reads_wrong="three aliased terms listed 'a and b and c'"),
    HandMutant(M, "the other runs predict {short_number(info['predicted_without'])}",
               "the other runs predict {short_number(info['observed'])}",
               reads_wrong="an outlier's sentence quotes its observed value as what the other runs predict"),
    HandMutant(M, "factor = ratio if grows else 1 / ratio", "factor = ratio",
               reads_wrong="a scatter that shrinks reads 'about 0.4 times larger at the low end'"),
    HandMutant(M, "worst = max(errors, key=lambda o: abs(errors[o]) / own[o])",
               "worst = max(errors, key=lambda o: abs(errors[o]))",
               reads_wrong="level 2 names the observable with the largest raw error, not the largest against its "
                           "own tolerance, and quotes its ratio"),
    HandMutant(MAT, "distance = 0.0 if inside else float(100 * aset.exact.reference_distance)",
               "distance = 0.0 if inside else float(aset.exact.reference_distance)",
               reads_wrong="the reference point's distance from the set printed as a fraction under a '% of the "
                           "search range' label"),
    HandMutant(MAT, '"fraction_pct_after": 100 * after.fraction', '"fraction_pct_after": 100 * before.fraction',
               reads_wrong="the feasible fraction after an extension reads the same as before it"),
    HandMutant(S, 'if verdict != "identified":\n                wide.append(f.label)',
               'if verdict == "unresolved":\n                wide.append(f.label)',
               reads_wrong="a bounded factor not said to be wide: the recommended point reads as pinned down"),
    HandMutant(S, 'zip(curve["along_actual"], curve["lower"], curve["mid"], curve["upper"])',
               'zip(curve["along_actual"], curve["mid"], curve["lower"], curve["upper"])',
               reads_wrong="a curved band's row prints its lower edge as the mid value and the mid as the lowest"),
    HandMutant(C, "{100 * BOUND_TOUCH:g} % of the range", "{BOUND_TOUCH:g} % of the range",
               reads_wrong="the data dictionary says at_bound means within 0.01 % of the range, not 1 %"),
    HandMutant(P, "f\"~0 ({float(ranking.loc[i, 'information_gain_bits']):.2f}; uninformative)\"",
               "f\"~0 ({float(ranking.loc[i, 'gain_vs_best_subset_bits']):.2f}; uninformative)\"",
               reads_wrong="an uninformative observable's own gain quoted from the added-gain column"),
    HandMutant(L, "({last['failed']} \"", "({sum(w['failed'] for w in summary['waves'])} \"",
               reads_wrong="the failed runs (already counted up to each wave) summed over the waves: counted twice"),
    HandMutant(MC, "f\"({'within' if reference_within(level2) else 'outside'} \"",
               "f\"({'within' if level2['reference_max_error'] <= level2['tolerance'] else 'outside'} \"",
               reads_wrong="the reference point called within/outside against the shared tolerance where "
                           "observables have their own"),
    HandMutant(MC, "{'+' if e > 0 else ''}{percent_text(e)}", "{'+' if e > 0 else ''}{percent_text(abs(e))}",
               reads_wrong="a reference point's error below its target printed without its minus sign"),
    HandMutant(PV, 'c.number(["tolerances", m, s], eps, 0, 1, "relative tolerance", percent=True)',
               'c.number(["tolerances", m, s], eps, 0, 100, "relative tolerance", percent=True)',
               reads_wrong="a published tolerance written in percent (2 for 2 %) accepted as a fraction of 2"),
]

"""Plausible developer bugs in the input and story modules, a second catalogue (none repeats benchmarks/hand_written/
inputs.py's), each written by reading the module, before any test was written against it.

First run (on 632bb26, before any test was written against these mutants): 8 of 9 killed, 88.9 %.  Survivor:
story/advice _add_observable's filter of uninformative observables applied to every observable of a growth set, not
only the added one (no test had an observable in use that is uninformative).
After: the survivor is killed by tests/story/test_add_observable_used_uninformative_whole.py (an observable in use
is uninformative, and the advice still names the informative one that gains most, with its gain and fraction; the
mutant applied by hand against that file), and the blocks mutant by tests/test_blocks_orthogonal_boundary_whole.py
as well; the whole catalogue re-run after (on 0b6b92c): 9 of 9 killed.
"""
from hand_mutants import HandMutant

MUTANTS = [
    HandMutant(
        "demid/story/measurements.py",
        'text += f"; {name([options[1][2]])} would gain {bits(options[1][0])} bits"',
        'text += f"; {name([options[-1][2]])} would gain {bits(options[-1][0])} bits"',
        reads_wrong="the measurement order's runner-up is the least informative of three or more added "
                    "measurements, not the second best, with that one's gain"),
    HandMutant(
        "demid/story/measurements.py",
        "and all(np.isfinite(sets[by_members[frozenset(t)]][0])",
        "and any(np.isfinite(sets[by_members[frozenset(t)]][0])",
        reads_wrong="a set containing a target no set can meet (or a pair already in conflict) is said to hold "
                    "targets that 'can each be met but not together'"),
    HandMutant(
        "demid/story/advice.py",
        'grow = grow[[not any(o in uninformative for o in s.split("+") if o not in used) for s in grow["observables"]]]',
        'grow = grow[[not any(o in uninformative for o in s.split("+")) for s in grow["observables"]]]',
        reads_wrong="when an observable already used is uninformative, no measurement to add is named: the advice "
                    "falls back to 'a new kind of measurement' though a ranked one would narrow the set"),
    HandMutant(
        "demid/story/advice.py",
        'limit = f.limits[0 if side == "lower" else 1]',
        'limit = f.limits[1 if side == "lower" else 0]',
        reads_wrong="the widen advice quotes the physical limit of the other side of the range (down to the upper "
                    "limit), or none where only the bound's own side has a limit"),
    HandMutant(
        "demid/story/verdicts.py",
        "cut = [side for side in SIDES_OF[at_bound] if side not in sides_at_limit((bound_lower, bound_upper), limits)]",
        "cut = list(SIDES_OF[at_bound])",
        reads_wrong="an interval ending at a search bound that is the factor's physical limit is called 'cut by "
                    "the search range' though no value lies beyond it"),
    HandMutant(
        "demid/story/recommended.py",
        'names = ", ".join(labels[:-1]) + " and " + labels[-1] if many else labels[0]',
        'names = " and ".join(labels[-2:]) if many else labels[0]',
        reads_wrong="with three or more factors on the same kind of bound, the sentence names only the last two"),
    HandMutant(
        "demid/tolerance.py",
        "return all(abs(float(v) - tolerance) <= 1e-12 * tolerance for v in (tolerances or {}).values())",
        "return any(abs(float(v) - tolerance) <= 1e-12 * tolerance for v in (tolerances or {}).values())",
        reads_wrong="observables with different own tolerances are described as sharing the scenario's one "
                    "tolerance when any of them has it (and a scenario without overrides as having several)"),
    HandMutant(
        "demid/blocks.py",
        "worst = float(np.max(np.abs(corr))) if corr.size else 0.0",
        "worst = float(np.max(corr)) if corr.size else 0.0",
        reads_wrong="a block negatively correlated with a model term is missed: non-orthogonal blocking is "
                    "called orthogonal, and the largest correlation quoted is the largest positive one"),
    HandMutant(
        "demid/data.py",
        "if kind in _BOUND_SLIPS and lo <= value <= hi]",
        "if kind in _BOUND_SLIPS]",
        reads_wrong="a far target is said to look like a one-keystroke slip of it that lands nowhere near the "
                    "simulated values"),
]

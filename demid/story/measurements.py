"""Which measurement next, set by set: the walk through ``tables/observable_ranking.csv`` in words.

From each smaller observable set, the single added measurement that gains most information (the
runner-up, and where the fraction criterion disagrees); first, the targets no set can meet.  The
ranking itself is :func:`demid.uncertainty.ranking.rank_observable_sets`'s; these sentences are advice
of kind ``measurement_order`` (:mod:`demid.story.advice`), the one source the report reads.
"""

from __future__ import annotations

from itertools import combinations

import numpy as np
import pandas as pd

from ..precision import rough_text


def _pct(value: float) -> str:
    return f"{value:.3g} %"


def _discrepancies(sets: dict, order: list, by_members: dict, name) -> list[str]:
    """The targets no set can meet, alone or together: named first, and left out of the walk."""
    lines = []
    unreachable = [o for o in order if (o,) in sets and not np.isfinite(sets[(o,)][0])]
    if unreachable:
        many = len(unreachable) > 1
        lines.append(f"The target{'s' if many else ''} of {name(unreachable)} cannot be met anywhere in the search "
                     f"range within the tolerance: a discrepancy between simulation and experiment (see level 2), "
                     f"not information. Sets with {'them' if many else 'it'} get no information gain and rank last; "
                     f"the advice below leaves {'them' if many else 'it'} out.")
    # Sets whose targets are each within reach but not together, named where the conflict first appears
    conflicts = [k for k in sets if len(k) > 1 and not np.isfinite(sets[k][0])
                 and all(np.isfinite(sets[by_members[frozenset(t)]][0])
                         for t in combinations(k, len(k) - 1) if frozenset(t) in by_members)]
    for k in sorted(conflicts, key=lambda k: (len(k), k)):
        lines.append(f"The targets of {name(k)} can each be met but not together within the tolerance: a "
                     "discrepancy between simulation and experiment (see level 2), not information; sets with "
                     "all of them get no information gain and rank last.")
    return lines


def measurement_order(ranking: pd.DataFrame, labels: dict[str, str] | None = None, rough: bool = False) -> list[str]:
    """In words: from each smaller observable set, which single added measurement gains most.

    Uses the ``observables``, ``information_gain_bits`` and ``feasible_fraction_pct``
    columns of :func:`~demid.uncertainty.ranking.rank_observable_sets`.  One sentence per starting set (the first
    for starting from nothing), naming the runner-up and any disagreement with the
    fraction criterion.  ``rough``: the ranking rests on a surrogate that does not predict left-out runs, so
    every number is given to one significant digit (:func:`~demid.precision.rough_text`).
    """
    labels = labels or {}
    bits = rough_text if rough else (lambda v: f"{v:.2f}")
    pct = (lambda v: f"{rough_text(v)} %") if rough else _pct
    share = (lambda v: f"{rough_text(v)} %") if rough else (lambda v: f"{v:.1f} %")

    def name(obs) -> str:
        return " + ".join(labels.get(o, o) for o in obs)

    sets = {tuple(str(s).split("+")): (float(g), float(f)) for s, g, f in
            zip(ranking["observables"], ranking["information_gain_bits"], ranking["feasible_fraction_pct"])}
    order = [o for o in max(sets, key=len)]
    sets[()] = (0.0, 100.0)
    by_members = {frozenset(k): k for k in sets}
    lines = _discrepancies(sets, order, by_members, name)
    for size in range(len(order)):
        for start in combinations(order, size):
            if frozenset(start) not in by_members:
                continue  # a ranking read back without this set (a table cut by hand) says nothing from it
            base_gain, base_frac = sets[by_members[frozenset(start)]]
            if not np.isfinite(base_gain):
                continue
            options = []
            for o in order:
                if o in start or frozenset(start) | {o} not in by_members:
                    continue
                g, f = sets[by_members[frozenset(start) | {o}]]
                if not np.isfinite(g):
                    continue
                options.append((g - base_gain, f, o, g))
            if not options:
                continue
            options.sort(key=lambda t: (-t[0], t[1]))
            delta, f_new, best, g_new = options[0]
            if not start:
                text = (f"As a first measurement, {name([best])} is the most informative: "
                        f"{bits(g_new)} bits, admissible fraction {pct(f_new)} of the domain")
            else:
                text = (f"From {name(start)}, adding {name([best])} gains {bits(delta)} bits "
                        f"({bits(base_gain)} -> {bits(g_new)})")
                if base_frac > 0 and 1 - f_new / base_frac < 5e-4:
                    text += f" but leaves the admissible fraction at {pct(f_new)}"
                elif base_frac > 0:
                    text += (f" and shrinks the admissible fraction by {share(100 * (1 - f_new / base_frac))} "
                             f"({pct(base_frac)} -> {pct(f_new)})")
                else:
                    text += " (the admissible set is already empty at this tolerance)"
            if len(options) > 1:
                text += f"; {name([options[1][2]])} would gain {bits(options[1][0])} bits"
                by_frac = min(options, key=lambda t: t[1])
                if by_frac[2] != best and by_frac[1] < f_new:
                    text += (f"; by fraction alone {name([by_frac[2]])} contracts more "
                             f"({pct(by_frac[1])} vs {pct(f_new)})")
            lines.append(text + ".")
    return lines

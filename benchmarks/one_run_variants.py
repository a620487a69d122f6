"""Variants of the one-run rule (demid.criticism.verdict.ONE_RUN_CAUSES, ONE_RUN_P) from one pass.

The cells of ``benchmarks/honest_causes.py`` are criticised once with the rule switched off; for every
cause about to be named the worst single-run deletion of its test is recorded (criticism.one_run).  The
effect of each variant (which causes the rule applies to, at which nominal level) on the confidently
wrong first cause (off-catalogue cells) and on catalogue naming is then exact: a vetoed cause in the
first round leaves the misfit unexplained; in a later round the causes named so far stand unless the
round's tests show residual misfit (verdict.RESIDUAL_MISFIT_LEVEL).  Detection and false alarms do not
change: a vetoed cause is still reported as unexplained misfit.

    python benchmarks/one_run_variants.py --reps 20 [--seed0 20]
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
sys.path.insert(0, str(Path(__file__).resolve().parent))
import honest_causes as hc  # noqa: E402
from criticism_power import DESIGNS, named  # noqa: E402
from generators import FACTORS, ccd_table, off_catalogue_table  # noqa: E402

from demid.criticism import level1, naming, verdict  # noqa: E402
from demid.criticism.one_run import WHOLE_DESIGN, worst_deletion  # noqa: E402

VARIANTS = [(causes, p) for causes in (("heteroscedasticity",), ("missing_term",), ("response_transform",),
                                        ("heteroscedasticity", "missing_term"), WHOLE_DESIGN)
            for p in (0.1, 0.05, 0.02, 0.01)]

_CALLS: list = []
_ROUND_MIN_P: list = []


class _RecordingRound(level1.Round):
    def __init__(self, *args):
        super().__init__(*args)
        _ROUND_MIN_P.append(min((h.p_family for h in self.hypotheses), default=1.0))


def _record(data, model, h):
    worst = worst_deletion(data, model, h)
    _CALLS.append((len(_ROUND_MIN_P) - 1, h.cause, None if worst is None else worst.p_without))
    return None


def _criticize(table, factors):
    _CALLS.clear()
    _ROUND_MIN_P.clear()
    result = level1.criticize(table, factors, "y")
    return result, list(_CALLS), list(_ROUND_MIN_P)


def _outcome(rec: dict, causes, p_level: float) -> str:
    """``same``, ``unexplained``, or ``revived`` (the first finding, discarded for residual misfit later,
    stands because the naming stops earlier)."""
    for rnd, cause, p_without in rec["calls"]:
        if cause in causes and p_without is not None and p_without > p_level:
            if rnd == 0 or rec["round_min_p"][rnd] <= verdict.RESIDUAL_MISFIT_LEVEL * 0.05:
                return "unexplained"
            return "same" if rec["cause"] not in (None, "unexplained") else "revived"
    return "same"


def collect(reps: int, seed0: int) -> list[dict]:
    recs = []
    for index in (0, 1, 2):
        k, replicates, sizes = DESIGNS[index]
        for kind, values in sizes.items():
            for size in values:
                for r in range(reps):
                    table, planted = ccd_table(seed0 + r, k, kind, size, replicates=replicates)
                    result, calls, mins = _criticize(table, FACTORS[k])
                    recs.append({"part": "catalogue", "cell": (k, replicates, kind, size), "named": named(result, planted)[0],
                                 "cause": hc.first_cause(result)[0], "calls": calls, "round_min_p": mins})
    for k in (2, 3):
        for kind, size in hc.OFF_CELLS:
            for r in range(reps):
                seed = 100_000 + seed0 + r
                if kind == "slip":
                    table, planted = off_catalogue_table(seed, k, "slip", n_slipped=int(size))
                else:
                    table, planted = off_catalogue_table(seed, k, kind, size)
                result, calls, mins = _criticize(table, FACTORS[k])
                cause, detail, aliases, info = hc.first_cause(result)
                _, wrong, lenient = hc._judge(kind, planted, cause, detail, aliases, info)
                recs.append({"part": "off", "cell": (k, kind, size), "wrong": wrong, "lenient": lenient, "cause": cause,
                             "calls": calls, "round_min_p": mins})
    return recs


def rates(recs: list[dict], causes=(), p_level: float = 1.0) -> dict:
    cells: dict = {}
    for rec in recs:
        out = _outcome(rec, causes, p_level)
        cell = cells.setdefault((rec["part"], rec["cell"]), {"wrong": [], "lenient": [], "named": []})
        if rec["part"] == "off":
            cell["wrong"].append(rec["wrong"] if out == "same" else out == "revived")
            cell["lenient"].append(rec["lenient"] if out == "same" else out == "revived")
        else:
            cell["named"].append(rec["named"] and out == "same")
    mean = {key: float(np.mean([np.mean(c[key]) for c in cells.values() if c[key]])) for key in ("wrong", "lenient", "named")}
    return mean


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--reps", type=int, default=20)
    parser.add_argument("--seed0", type=int, default=0)
    args = parser.parse_args(argv)
    start = time.time()
    level1.Round = _RecordingRound
    naming.rests_on_one_run = _record
    recs = collect(args.reps, args.seed0)
    base = rates(recs)
    print(f"no rule: wrong {base['wrong']:.3f}, wrong (lenient) {base['lenient']:.3f}, catalogue naming {base['named']:.3f}")
    for causes, p_level in VARIANTS:
        r = rates(recs, causes, p_level)
        print(f"{'+'.join(causes):70s} p {p_level:<5g} wrong {r['wrong']:.3f}, lenient {r['lenient']:.3f}, "
              f"naming {r['named']:.3f}")
    print(f"elapsed {time.time() - start:.0f} s")


if __name__ == "__main__":
    main()

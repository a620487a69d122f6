"""Honest causes: naming and false-alarm rates of level-1 criticism on catalogued defects, and the
confidently-wrong-cause rate on defects outside the catalogue, against the classical lack-of-fit test.

Part 1 (catalogue) repeats the cells of ``benchmarks/criticism_power.py`` (2- and 3-factor CCDs and the
2-factor CCD with triplicated factorial and axial points): per cell, over ``--reps`` seeds,

named   the first cause is the planted one at its exact place (criticism_power's ``named``);
alarm   anything reported: a finding, or misfit reported as ``unexplained``.  On ``clean`` rows this is
        the false-alarm rate, to be compared with the family-wise level 0.05.

Part 2 (off-catalogue, ``tests/generators.off_catalogue_table``): a decimal slip (one or two runs
simulated at a tenth of one factor's recorded value), a plateau, a step in one region, a hidden batch of
three runs, an unrecorded factor entering as a cubic, noise proportional to the mean.  Per cell:

right   the first cause is the right one: ``factor_level`` naming a slipped run and its factor; for
        ``multiplicative`` noise unequal scatter or a transform;
wrong   a catalogue cause was named first and it is not right (``unexplained`` is never wrong);
        ``wrong_lenient`` also accepts an outlier finding on a run the defect really moved (a slipped
        run, a run of the batch, of the step, or moved by the hidden factor by 3 noise SDs or more) and,
        for a plateau, a missing term in the plateau factor;
unexpl  ``unexplained`` reported first;
detect  anything reported (finding or ``unexplained``);
lof     the classical lack-of-fit F test (pure error from the centre runs) rejects at 5 %.
wrong_shape  ``wrong_lenient``, except that a missing term is not wrong when it describes the defect's
        shape on this design: the term (residualised on the quadratic) carries at least half of what the
        defect adds beyond the quadratic (a step over the corner where the coded factors sum past 0.5 is,
        at the factorial points of a 3-factor CCD, exactly the majority function: linear terms plus
        -x1*x2*x3/2, so "missing term x1:x2:x3" is what the runs show).

    python benchmarks/honest_causes.py --reps 20 --out per_table.csv
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import pandas as pd  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
sys.path.insert(0, str(Path(__file__).resolve().parent))
from criticism_power import DESIGNS, named  # noqa: E402
from generators import FACTORS, ccd_table, off_catalogue_table  # noqa: E402

from demid.criticism import criticize  # noqa: E402
from demid.surrogate import fit_response  # noqa: E402

OFF_CELLS = [("slip", 1), ("slip", 2), ("plateau", 20), ("plateau", 40), ("step", 4), ("step", 8),
             ("batch", 6), ("batch", 10), ("hidden", 10), ("hidden", 20), ("multiplicative", 5),
             ("multiplicative", 10)]


def first_cause(result) -> tuple[str | None, object, list, dict]:
    """(cause, detail, aliases, info) reported first: a named finding, ``unexplained``, or None."""
    if result.findings:
        f = result.findings[0]
        return f.cause, f.detail, list(f.aliases), dict(f.info)
    if getattr(result, "unexplained", None):
        return "unexplained", "", [], {}
    if getattr(result, "candidates", None):  # ambiguous: the candidates, none of them named
        return "ambiguous", "", [], {"candidates": result.candidates}
    return None, None, [], {}


def shape_share(table, factors, planted, term: str) -> float:
    """Share of the defect's departure from the quadratic (its noise-free signal, residualised on the
    quadratic at the runs) that the named term's residualised column carries."""
    import numpy as np

    from demid.design import model_matrix, parse_term, quadratic_terms
    from generators import design

    signal = np.asarray(planted.signal, dtype=float)
    if not signal.size:
        return 0.0
    coded = design(len(factors))[1].to_coded(table[factors].to_numpy(dtype=float))
    q, _ = np.linalg.qr(model_matrix(coded, quadratic_terms(len(factors))))
    r = signal - q @ (q.T @ signal)
    column = model_matrix(coded, [parse_term(term, factors)])[:, 0]
    u = column - q @ (q.T @ column)
    denominator = float((u @ u) * (r @ r))
    return float((r @ u) ** 2 / denominator) if denominator > 0 else 0.0


def _judge(kind: str, planted, cause, detail, aliases, info) -> tuple[bool, bool, bool]:
    """(right, wrong, wrong_lenient) of the first cause for an off-catalogue defect.

    An ``outlier`` finding on a run the defect really moved (a slipped run, a run of the shifted batch,
    of the step or moved by the hidden factor by 3 noise SDs or more) says something true about that
    run: it is counted wrong strictly and not wrong leniently.
    """
    if cause in (None, "unexplained"):
        return False, False, False
    if cause == "ambiguous":  # wrong unless the truth is among the candidates (judged one by one)
        judged = [_judge(kind, planted, c["cause"], c["detail"], [c["detail"]], {}) for c in info["candidates"]]
        inside = any(j[0] for j in judged)
        return False, not inside, not inside and all(j[2] for j in judged)
    if kind == "slip" and cause == "factor_level":
        right = detail in planted.runs and info.get("factor") == planted.factor
        return right, not right, not right
    if cause == "outlier" and detail in planted.runs:
        return False, True, False
    if kind == "multiplicative":
        right = cause in ("heteroscedasticity", "response_transform")
        return right, not right, not right
    lenient = kind == "plateau" and cause == "missing_term" and any(planted.factor in a for a in aliases)
    return False, True, not lenient


def catalogue_part(reps: int, seed0: int, rows: list, per_table: list) -> None:
    for index in (0, 1, 2):
        k, replicates, sizes = DESIGNS[index]
        factors = FACTORS[k]
        cells = [("clean", 0.0)] + [(kind, s) for kind, values in sizes.items() for s in values]
        for kind, size in cells:
            n_named = n_alarm = 0
            for r in range(reps):
                table, planted = ccd_table(seed0 + r, k, kind, size, replicates=replicates)
                result = criticize(table, factors, "y")
                cause, detail, _, _ = first_cause(result)
                n_named += named(result, planted)[0]
                n_alarm += cause is not None
                per_table.append({"part": "catalogue", "design": f"{k}f x{replicates}", "kind": kind, "size": size,
                                  "seed": seed0 + r, "cause": cause, "detail": str(detail)})
            rows.append({"part": "catalogue", "design": f"{k}-factor CCD x{replicates} ({len(table)} runs)",
                         "kind": kind, "size": size, "reps": reps, "named": n_named / reps,
                         "alarm": n_alarm / reps})


def off_catalogue_part(reps: int, seed0: int, rows: list, per_table: list) -> None:
    for k in (2, 3):
        factors = FACTORS[k]
        for kind, size in OFF_CELLS:
            counts = dict.fromkeys(("right", "wrong", "wrong_lenient", "wrong_shape", "unexpl", "detect", "lof"), 0)
            causes: dict[str, int] = {}
            for r in range(reps):
                if kind == "slip":
                    table, planted = off_catalogue_table(seed0 + r, k, "slip", n_slipped=int(size))
                else:
                    table, planted = off_catalogue_table(seed0 + r, k, kind, size)
                result = criticize(table, factors, "y")
                cause, detail, aliases, info = first_cause(result)
                right, wrong, wrong_lenient = _judge(kind, planted, cause, detail, aliases, info)
                lof_p = fit_response(table, factors, "y").statistics().lof_p
                counts["right"] += right
                counts["wrong"] += wrong
                counts["wrong_lenient"] += wrong_lenient
                counts["wrong_shape"] += wrong_lenient and not (
                    cause == "missing_term" and shape_share(table, factors, planted, str(detail)) >= 0.5)
                counts["unexpl"] += cause == "unexplained"
                counts["detect"] += cause is not None
                counts["lof"] += bool(lof_p < 0.05)
                causes[str(cause)] = causes.get(str(cause), 0) + 1
                per_table.append({"part": "off", "design": f"{k}f", "kind": kind, "size": size, "seed": seed0 + r,
                                  "cause": cause, "detail": str(detail), "lof_p": lof_p})
            rows.append({"part": "off", "design": f"{k}-factor CCD ({len(table)} runs)", "kind": kind, "size": size,
                         "reps": reps, **{key: v / reps for key, v in counts.items()},
                         "first_cause": ", ".join(f"{c}:{v}" for c, v in sorted(causes.items()))})


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--reps", type=int, default=20)
    parser.add_argument("--seed0", type=int, default=0)
    parser.add_argument("--parts", default="catalogue,off")
    parser.add_argument("--out", help="per-table causes (CSV), for pairing two versions")
    args = parser.parse_args(argv)
    start = time.time()
    rows: list = []
    per_table: list = []
    if "catalogue" in args.parts:
        catalogue_part(args.reps, args.seed0, rows, per_table)
    if "off" in args.parts:
        off_catalogue_part(args.reps, 100_000 + args.seed0, rows, per_table)
    frame = pd.DataFrame(rows)
    with pd.option_context("display.width", 250, "display.max_columns", 20, "display.max_colwidth", 90):
        for part, sub in frame.groupby("part", sort=False):
            print(sub.dropna(axis=1, how="all").to_string(index=False, float_format=lambda v: f"{v:.2f}"))
            print()
        off = frame[frame["part"] == "off"]
        if len(off):
            print(f"off-catalogue overall: wrong {off['wrong'].mean():.3f}, wrong (lenient) "
                  f"{off['wrong_lenient'].mean():.3f}, wrong (lenient, shape) {off['wrong_shape'].mean():.3f}, "
                  f"detect {off['detect'].mean():.3f}, lof {off['lof'].mean():.3f}")
        cat = frame[frame["part"] == "catalogue"]
        if len(cat):
            clean = cat[cat["kind"] == "clean"]
            print(f"catalogue: mean naming rate (defect cells) {cat[cat['kind'] != 'clean']['named'].mean():.3f}, "
                  f"false alarms on clean tables {clean['alarm'].mean():.3f}")
    if args.out:
        pd.DataFrame(per_table).to_csv(args.out, index=False)
    print(f"elapsed {time.time() - start:.0f} s")


if __name__ == "__main__":
    main()

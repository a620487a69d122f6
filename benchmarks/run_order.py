"""False drift findings on tables printed in another order, and drift power on randomised orders.

Clean CCD tables (tests/generators.py: random quadratic, unit noise, no defect) are
criticised with their ``run`` column renumbered three ways:

random      the randomised order the runs were made in (the generator's);
sorted      sorted by the response (run = rank of y), as published tables often are;
standard    the design's standard order (factorial in Yates order, axial, centre).

``drift`` is the share of tables with any drift finding (the false drift rate for clean
tables).  Tables with drift planted (``size`` noise SDs from the first to the last run, in
randomised order) give the power: ``drift`` = share with a drift finding, ``first`` = share
whose first finding is drift.  ``untested`` is the share where drift was not tested
(criticism.run_order; absent before that module existed).  Tables with a missing cubic term
(``term``, ``size`` noise SDs) printed in standard order check whether misfit poses as drift
there: ``drift`` is then the share whose misfit was blamed (at least partly) on drift.

    python benchmarks/run_order.py --reps 100          # this tree
    PYTHONPATH=/path/to/older/tree python benchmarks/run_order.py --reps 100   # before
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
import pandas as pd  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
from generators import FACTORS, ccd_table, design  # noqa: E402

from demid.criticism import criticize  # noqa: E402

DRIFT_SIZES = (4, 8, 12)
TERM_SIZE = 6


def renumber(table: pd.DataFrame, seed: int, n_factors: int, order: str) -> pd.DataFrame:
    """The table with its run column replaced by the response ranks or the standard order."""
    out = table.copy()
    if order == "sorted":
        out["run"] = out["y"].rank(method="first").astype(int)
    elif order == "standard":
        # the generator draws the randomised run of each standard-order point first (tests/generators.py)
        n = len(design(n_factors)[2])
        run_of_standard = np.random.default_rng(seed).permutation(n) + 1
        standard_index = {int(r): i + 1 for i, r in enumerate(run_of_standard)}
        out["run"] = out["run"].map(standard_index)
    return out.sort_values("run").reset_index(drop=True)


def one(table: pd.DataFrame, factors: list[str]) -> dict:
    result = criticize(table, factors, "y")
    causes = [f.cause for f in result.findings]
    order = getattr(result, "run_order", None)
    return {"drift": "drift" in causes, "first": bool(causes) and causes[0] == "drift",
            "untested": bool(order is not None and not order.drift_tested)}


def run(reps: dict[int, int], seed0: int = 0, kinds=("clean", "drift", "term")) -> pd.DataFrame:
    rows = []
    for k, n_reps in reps.items():
        factors = FACTORS[k]
        cells = [("clean", 0, order) for order in ("random", "sorted", "standard")]
        cells += [("drift", size, "random") for size in DRIFT_SIZES]
        cells += [("term", TERM_SIZE, order) for order in ("random", "standard")]
        cells = [c for c in cells if c[0] in kinds]
        for kind, size, order in cells:
            counts = {"drift": 0, "first": 0, "untested": 0}
            for r in range(n_reps):
                seed = seed0 + r
                table, _ = ccd_table(seed, k, kind, size)
                for key, v in one(renumber(table, seed, k, order), factors).items():
                    counts[key] += v
            rows.append({"design": f"{k}-factor CCD ({len(table)} runs)", "kind": kind, "size": size,
                         "order": order, "reps": n_reps, **{key: v / n_reps for key, v in counts.items()}})
            print(rows[-1], flush=True)  # progress: a long benchmark keeps what it has
    return pd.DataFrame(rows)


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--reps", type=int, default=100, help="tables per cell, 2-factor CCD")
    parser.add_argument("--reps3", type=int, default=None, help="tables per cell, 3-factor CCD (default: --reps)")
    parser.add_argument("--kinds", default="clean,drift,term", help="table kinds to run (clean, drift, term)")
    args = parser.parse_args(argv)
    start = time.time()
    frame = run({2: args.reps, 3: args.reps3 if args.reps3 is not None else args.reps},
                kinds=tuple(args.kinds.split(",")))
    with pd.option_context("display.width", 200, "display.max_columns", 20):
        print(frame.to_string(index=False, float_format=lambda v: f"{v:.3f}"))
    print(f"\nelapsed {time.time() - start:.0f} s")


if __name__ == "__main__":
    main()

"""Naming rate and false-alarm rate of demid.criticism.criticize, against oracle tests.

For each design (2-factor CCD, 13 runs; 3-factor CCD, 20 runs; 2-factor CCD with
factorial and axial points in triplicate, 29 runs, for unequal scatter), each planted
defect kind and size (tests/generators.py), ``--reps`` random tables are
criticised.  Printed per cell:

named     first finding names the planted cause *and* its exact place (the planted
          term is in the reported alias set, the shifted run, the drifting ``run``,
          the factor along which the scatter grows, the ``log`` transform);
cause     first finding names the planted cause (any place / transform);
any       at least one finding;
oracle    power of the single 5 % test that knows the defect: added-variable F-test
          of the true term / of the run order, t-test of the known run's mean shift,
          Box-Cox likelihood-ratio test of lambda = 1, likelihood-ratio test of a log-linear variance in the
          true factor.  Critical values of the two likelihood-ratio tests (Box-Cox, variance) are the 95 %
          quantiles of their statistic on clean tables (their chi-square
          approximations are not trustworthy at 13 runs); the others are exact.

The ``clean`` rows give the false-alarm rate (any finding on a table without defect),
to be compared with the family-wise level 0.05.

    python benchmarks/criticism_power.py --reps 200
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path

# Small matrices: BLAS threads only contend with each other (and with other jobs) here.
for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402
import statsmodels.api as sm  # noqa: E402
from scipy import optimize, special  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
from generators import FACTORS, Planted, ccd_table  # noqa: E402

from demid.criticism import criticize, infer_axial_distance  # noqa: E402
from demid.design import Coding, model_matrix, parse_term, quadratic_terms  # noqa: E402

DESIGNS = [  # (factors, replicates of factorial+axial points, {kind: sizes})
    (2, 1, {"term": [2, 4, 6, 8], "log": [1, 2, 3], "outlier": [6, 10, 15, 30], "drift": [4, 8, 12],
            "het": [10, 30, 100]}),
    (3, 1, {"term": [2, 4, 6], "log": [1, 2, 3], "outlier": [6, 10, 15, 20], "drift": [4, 8, 12],
            "het": [10, 30, 100]}),
    (2, 3, {"het": [3, 10, 30]}),
]


def _design(table: pd.DataFrame, factors: list[str]) -> tuple[np.ndarray, float]:
    x = table[factors].to_numpy(float)
    alpha = infer_axial_distance(x)
    return Coding.from_levels(factors, x, alpha).to_coded(x), alpha


def oracle_statistic(table: pd.DataFrame, factors: list[str], planted) -> float:
    """Statistic of the oracle test (larger = more evidence); p-values for exact tests."""
    coded, alpha = _design(table, factors)
    y = table["y"].to_numpy(float)
    x = model_matrix(coded, quadratic_terms(len(factors)))
    base = sm.OLS(y, x).fit()
    if planted.kind == "term":
        ext = sm.OLS(y, np.column_stack([x, model_matrix(coded, [parse_term(planted.term, factors)])])).fit()
        return -ext.compare_f_test(base)[1]
    if planted.kind == "drift":
        run = table["run"].to_numpy(float)
        ext = sm.OLS(y, np.column_stack([x, run - run.mean()])).fit()
        return -ext.compare_f_test(base)[1]
    if planted.kind == "outlier":
        row = int(np.flatnonzero(table["run"].to_numpy() == planted.run)[0])
        return -float(np.asarray(base.outlier_test(method="bonf"))[row, 1])
    if planted.kind == "het":
        v = coded[:, factors.index(planted.factor)] / alpha
        llf = max(sm.WLS(y, x, weights=np.exp(-g * v)).fit().llf for g in np.linspace(-2.5, 2.5, 21))
        return float(2 * (llf - base.llf))
    if planted.kind == "log":
        def prof(lam):
            ssr = sm.OLS(special.boxcox(y, lam), x).fit().ssr
            return -0.5 * len(y) * np.log(ssr / len(y)) + (lam - 1) * np.sum(np.log(y))

        res = optimize.minimize_scalar(lambda v: -prof(v), bounds=(-3, 3), method="bounded")
        return float(2 * (-res.fun - prof(1.0)))
    raise ValueError(planted.kind)


def oracle_critical(n_factors: int, replicates: int, kind: str, reps: int) -> float:
    """Rejection threshold of the oracle statistic at level 0.05."""
    if kind in ("term", "drift", "outlier"):
        return -0.05
    factors = FACTORS[n_factors]
    values = []
    for seed in range(reps):
        table, _ = ccd_table(10_000 + seed, n_factors, "clean", replicates=replicates)
        planted = (Planted("het", 1.0, factor=factors[seed % n_factors]) if kind == "het"
                   else Planted("log", 1.0))
        values.append(oracle_statistic(table, factors, planted))
    return float(np.quantile(values, 0.95))


def named(result, planted) -> tuple[bool, bool]:
    if not result.findings:
        return False, False
    f = result.findings[0]
    cause = {"term": "missing_term", "log": "response_transform", "outlier": "outlier",
             "drift": "drift", "het": "heteroscedasticity"}.get(planted.kind)
    ok_cause = f.cause == cause
    exact = ok_cause and {
        "term": lambda: planted.term in f.aliases,
        "log": lambda: f.detail == "log",
        "outlier": lambda: f.detail == planted.run,
        "drift": lambda: True,
        "het": lambda: f.detail == planted.factor,
    }[planted.kind]()
    return exact, ok_cause


def run(reps: int, designs=(0, 1, 2), seed0: int = 0) -> pd.DataFrame:
    rows = []
    for index in designs:
        k, replicates, sizes = DESIGNS[index]
        factors = FACTORS[k]
        cells = [("clean", 0.0)] + [(kind, s) for kind, values in sizes.items() for s in values]
        crit = {kind: oracle_critical(k, replicates, kind, max(reps, 400)) for kind in sizes}
        for kind, size in cells:
            counts = {"named": 0, "cause": 0, "any": 0, "oracle": 0}
            first_causes: dict[str, int] = {}
            for r in range(reps):
                table, planted = ccd_table(seed0 + r, k, kind, size, replicates=replicates)
                result = criticize(table, factors, "y")
                exact, ok = named(result, planted)
                counts["named"] += exact
                counts["cause"] += ok
                counts["any"] += bool(result.findings)
                if result.findings:
                    c = result.findings[0].cause
                    first_causes[c] = first_causes.get(c, 0) + 1
                if kind != "clean":
                    counts["oracle"] += oracle_statistic(table, factors, planted) > crit[kind]
            label = f"{k}-factor CCD{' x' + str(replicates) if replicates > 1 else ''} ({len(table)} runs)"
            rows.append({"design": label, "kind": kind, "size": size, "reps": reps,
                         **{key: v / reps for key, v in counts.items()},
                         "first_cause": ", ".join(f"{c}:{v}" for c, v in sorted(first_causes.items()))})
            if kind == "clean":
                rows[-1]["oracle"] = np.nan
    return pd.DataFrame(rows)


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--reps", type=int, default=200)
    parser.add_argument("--designs", default="0,1,2", help="indices into DESIGNS")
    args = parser.parse_args(argv)
    start = time.time()
    frame = run(args.reps, tuple(int(v) for v in args.designs.split(",")))
    with pd.option_context("display.width", 200, "display.max_columns", 20, "display.max_colwidth", 80):
        print(frame.to_string(index=False, float_format=lambda v: f"{v:.3f}"))
    print(f"\ndesigns: rotatable CCDs, 5 (2 factors) / 6 (3 factors) centre runs; 'x3' repeats every factorial "
          f"and axial point three times.")
    print(f"sizes: term = coefficient of the cubic term in noise SDs (coded units, factorial at +-1); "
          f"log = range of log(y) over the design in nepers (3 % multiplicative noise); outlier = shift in "
          f"noise SDs; drift = first-to-last-run change in noise SDs; het = SD ratio top/bottom axial level.")
    print(f"elapsed {time.time() - start:.0f} s")


if __name__ == "__main__":
    main()

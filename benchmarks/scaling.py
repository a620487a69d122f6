"""Cost of one material job against the number of factors and the number of runs.

Each case is a generated study: a smooth quadratic-plus-noise simulator (seeded) over ``k`` factors
with three responses (two with targets, one to minimise on a Pareto front), two scenarios and a
``pareto:`` entry.  Factor cases use a rotatable CCD from the project's own generator
(:func:`demid.design_generation.generate_sheet`, as ``demid design`` writes it); run cases use a
``custom`` design of uniformly random runs.  Each case runs the material job exactly as the
``analyse_material`` rule does (:func:`demid.steps.material_step`, then every output written), in a
fresh Python process so that imports count as they do under Snakemake, and the table shows its
wall and CPU seconds (median of ``--reps``), the ratios to the previous row, and for the run cases
the CPU milliseconds per added run (flat when the cost is linear in the runs).  ``--grid`` gives runs x
factors (custom designs) with CPU seconds and the job process's peak resident memory.

    python benchmarks/scaling.py --factors 2 3 4 5 6 --runs 13 100 1000 10000
    python benchmarks/scaling.py --grid --runs 13 200 2000 10000 --grid-factors 2 4 6
    python benchmarks/scaling.py --quick                # 2, 4, 6 factors; 13, 1000 runs; one rep
    python benchmarks/scaling.py --one 6 ccd            # one case, JSON (used by the table; or --one 2 1000)

Measured on the shared two-core machine (load 8-11, so wall times are inflated; CPU is the figure to read),
2,000 runs x 2 factors, one material job: 55.9 CPU s before the round became linear (and with OpenBLAS
threads, which the workflow never runs with), 18.1 after it with threads, 11.0 on one BLAS thread as the
workflow runs (peak 545 MB).

Earlier rounds (one material job, CPU s, 10,000 runs): 2 / 4 / 6 factors 54 / 158 / 103 s before the criticism
became linear in the runs (slips for all runs at once, running sums, one decomposition per model).  This round:
the slip search worked in place, unequal scatter's gamma searched without a model per step above 256 runs, the
residual figure's points an image in the SVG above 2,000 runs.

The grid (``--grid``; one material job; CPU s and the job's peak resident memory; the round's final code at load 1
on the two cores):

    runs   2 factors        4 factors        6 factors
    13     5.6 s  363 MB    (13 runs cannot determine a quadratic in 4 or 6 factors: refused with the column)
    200    7.1 s  364 MB    11.6 s  416 MB   18.8 s  429 MB
    2000   8.0 s  543 MB    11.8 s  497 MB   20.0 s  585 MB
    10000  18.7 s 1118 MB   31.1 s 1252 MB   46.8 s 1607 MB

Most of 200 and 2,000 runs at 6 factors is not the runs' (the Sobol evaluation of the sets, the figures).

10,000 x 6 was refused until the typo screen measured residuals against the scatter at each run's level: the
generated responses scatter in proportion to their level, and against the pooled scale one cell of the top of the
range passed the Bonferroni bound over 10,000 runs ("11.685914 looks like 11.865914", 4.2 of its own scatter).

The whole pipeline (``snakemake -c2`` on ``write_study``'s studies, /usr/bin/time, one BLAS thread), the final
code of the round, measured one after another at load 1-2 on the two cores (an otherwise idle machine):

    factors   2,000 rows: wall  CPU    peak      10,000 rows: wall  CPU    peak
    2         12.8 s  14.9 s   0.5 GB         23.6 s  26.0 s   1.1 GB
    3         21.8 s  24.2 s   1.3 GB         37.7 s  40.6 s   1.3 GB
    4         16.5 s  19.9 s   0.5 GB         33.9 s  37.5 s   1.3 GB
    6         23.7 s  28.1 s   0.6 GB         47.2 s  51.8 s   1.6 GB

Before the round, 10,000 rows of 3 factors took 61.0 s and of 6 factors about 78 s (the material job alone 103
CPU s); 10,000 x 4's material job alone 158 CPU s.  2,000 rows stay above 15 s from 3 factors on: their cost is
the fixed part (a 3-factor grid evaluation of the sets, the Sobol evaluation and figures of up to fifteen factor
pairs with more factors), not the runs.
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]
NOISE = 0.003  # relative noise of each simulated response


def _names(k: int) -> list[str]:
    return [f"x{i + 1}" for i in range(k)]


def _simulator(k: int, seed: int):
    """A smooth quadratic on the coded cube [-1, 1]^k: responses y1, y2 (with targets) and s."""
    rng = np.random.default_rng(seed)

    def quadratic(offset):
        lin = rng.uniform(-1, 1, k)
        quad = rng.uniform(-0.3, 0.3, k)
        inter = np.triu(rng.uniform(-0.2, 0.2, (k, k)), 1)
        return lambda u: offset + u @ lin + (u ** 2) @ quad + np.einsum("ni,ij,nj->n", u, inter, u)

    return {"y1": quadratic(20.0), "y2": quadratic(15.0), "s": quadratic(10.0)}


def write_study(folder: Path, k: int, runs: int | None, seed: int = 1) -> Path:
    """The study's table and config in ``folder``; ``runs=None`` -> the CCD of ``k`` factors."""
    from demid.design_generation import FactorRange, generate_sheet

    names = _names(k)
    factors = [FactorRange(n, 0.0, 1.0) for n in names]
    if runs is None:
        sheet = generate_sheet("ccd", factors, center_runs=max(k, 3), alpha="rotatable", seed=seed)
        table = sheet.to_frame().drop(columns="std_order")
        design = sheet.design_config()
    else:
        rng = np.random.default_rng(seed)
        unit = np.round(rng.uniform(0, 1, (runs, k)), 6)
        import pandas as pd

        table = pd.DataFrame({"run": np.arange(1, runs + 1), **{n: unit[:, i] for i, n in enumerate(names)}})
        design = {"type": "custom"}
    coded = 2 * table[names].to_numpy() - 1  # bounds 0..1 are the outer levels in both cases
    simulator = _simulator(k, seed)
    rng = np.random.default_rng(seed + 1)
    for response, f in simulator.items():
        clean = f(coded)
        table[response] = np.round(clean * (1 + NOISE * rng.standard_normal(len(clean))), 6)
    table.to_csv(folder / "study.csv", index=False)
    inside = rng.uniform(-0.3, 0.3, (1, k))  # targets at an interior point: the sets are not empty
    targets = {r: float(f"{simulator[r](inside)[0]:.6g}") for r in ("y1", "y2")}
    config = {
        "results_dir": "results",
        "materials": {"study": {
            "data": "study.csv", "design": design,
            "factors": {n: {"lower": 0.0, "upper": 1.0} for n in names},
            "responses": {"y1": {"target": targets["y1"]}, "y2": {"target": targets["y2"]}, "s": {}},
            "scenarios": {"y1_only": {"observables": ["y1"], "tolerance": 0.02},
                          "both": {"observables": ["y1", "y2"], "tolerance": 0.02}},
            "pareto": {"error_of": "y1", "minimise": "s", "max_error": 0.02},
        }},
    }
    import yaml

    path = folder / "config.yaml"
    path.write_text(yaml.safe_dump(config, sort_keys=False))
    return path


def run_one(k: int, runs: int | None) -> dict:
    """Generate the study, run its material job as the rule does, and return wall and CPU seconds."""
    start_wall, start_cpu = time.perf_counter(), time.process_time()
    from demid.config import load_config
    from demid.io import save_figure, write_csv, write_json, write_parquet
    from demid.spec import MaterialSpec
    from demid.steps import material_step

    with tempfile.TemporaryDirectory(prefix="demid-scaling-") as tmp:
        folder = Path(tmp)
        config_path = write_study(folder, k, runs)
        os.chdir(folder)
        setup_wall, setup_cpu = time.perf_counter() - start_wall, time.process_time() - start_cpu
        config = load_config(config_path, base_dir=folder)
        spec = MaterialSpec.from_config("study", config)
        result = material_step(spec, folder / "study.csv", z=config["robust_z"], tolerances=config["sweep_tolerances"])
        out = folder / "out"
        out.mkdir()
        for name, frame in result.parquet.items():
            write_parquet(frame, out / f"{name}.parquet")
        for name, frame in result.csv.items():
            write_csv(frame, out / f"{name}.csv")
        for name, document in result.json.items():
            write_json(document, out / f"{name}.json")
        for response, document in result.responses.items():
            write_json(document, out / f"criticism_{response}.json")
        for name, figure in result.figures.items():
            save_figure(figure, out / f"{name}.png")
        n_runs = len(result.parquet["table"])
        os.chdir(REPO)
    # the study's generation is not part of the job; imports are (Snakemake starts a fresh Python)
    return {"factors": k, "runs": n_runs, "wall": time.perf_counter() - start_wall - setup_wall,
            "cpu": time.process_time() - start_cpu - setup_cpu,
            "peak_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024}  # Linux: kB


def measure(k: int, runs: int | None, reps: int) -> dict:
    args = [sys.executable, __file__, "--one", str(k), "ccd" if runs is None else str(runs)]
    env = dict(os.environ, PYTHONPATH=str(REPO) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    env.setdefault("OPENBLAS_NUM_THREADS", "1")  # as the workflow runs every job (workflow/rules/common.smk)
    rows = []
    for _ in range(reps):
        done = subprocess.run(args, env=env, capture_output=True, text=True)
        if done.returncode:  # e.g. fewer runs than the quadratic's terms: the job refuses the table
            lines = (done.stderr or done.stdout).strip().splitlines()
            return {"factors": k, "runs": runs, "error": lines[-1] if lines else f"exit {done.returncode}"}
        rows.append(json.loads(done.stdout.strip().splitlines()[-1]))
    return {"factors": k, "runs": rows[0]["runs"], "wall": statistics.median(r["wall"] for r in rows),
            "cpu": statistics.median(r["cpu"] for r in rows), "peak_mb": max(r["peak_mb"] for r in rows)}


def _grid_table(rows: list[dict]) -> None:
    print("\ncustom designs (uniformly random runs): one material job, runs x factors")
    print(f"{'runs':>6} {'factors':>7} {'wall s':>8} {'cpu s':>8} {'peak MB':>8}")
    for row in rows:
        if "error" in row:
            print(f"{row['runs']:>6} {row['factors']:>7}  refused: {row['error'][:90]}")
        else:
            print(f"{row['runs']:>6} {row['factors']:>7} {row['wall']:8.2f} {row['cpu']:8.2f} {row['peak_mb']:8.0f}")


def _table(title: str, rows: list[dict], per: str) -> None:
    print(f"\n{title}")
    print(f"{'factors':>7} {'runs':>6} {'wall s':>8} {'cpu s':>8} {'wall ratio':>11} {'cpu ratio':>10}"
          + (f" {'cpu ms per added run':>21}" if per == "runs" else ""))
    previous = None
    for row in rows:
        ratio = ("" if previous is None else f"{row['wall'] / previous['wall']:.2f}",
                 "" if previous is None else f"{row['cpu'] / previous['cpu']:.2f}")
        extra = ""
        if per == "runs" and previous is not None:  # the marginal cost: flat when the cost is linear in runs
            extra = f" {1000 * (row['cpu'] - previous['cpu']) / (row['runs'] - previous['runs']):21.2f}"
        print(f"{row['factors']:>7} {row['runs']:>6} {row['wall']:8.2f} {row['cpu']:8.2f} {ratio[0]:>11} "
              f"{ratio[1]:>10}{extra}")
        previous = row
    print(f"(ratios: each row over the row above; {'per added factor' if per == 'factors' else 'per step in runs'})")


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--factors", type=int, nargs="*", default=[2, 3, 4, 5, 6],
                        help="factor counts of the CCD studies")
    parser.add_argument("--runs", type=int, nargs="*", default=[13, 100, 1000, 10000],
                        help="run counts of the custom-design studies")
    parser.add_argument("--run-factors", type=int, default=2, help="factors of the custom-design studies")
    parser.add_argument("--reps", type=int, default=1, help="repeats per case (median shown)")
    parser.add_argument("--grid", action="store_true",
                        help="runs x factors of custom designs (--runs, --grid-factors), with peak memory")
    parser.add_argument("--grid-factors", type=int, nargs="*", default=[2, 4, 6], help="factors of the grid")
    parser.add_argument("--quick", action="store_true", help="2, 4, 6 factors; 13 and 1000 runs; one repeat")
    parser.add_argument("--one", nargs=2, metavar=("FACTORS", "RUNS"), help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.one:
        k, runs = int(args.one[0]), None if args.one[1] == "ccd" else int(args.one[1])
        print(json.dumps(run_one(k, runs)))
        return
    if args.grid:
        _grid_table([measure(k, n, args.reps) for n in args.runs for k in args.grid_factors])
        return
    if args.quick:
        args.factors, args.runs, args.reps = [2, 4, 6], [13, 1000], 1
    if args.factors:
        _table("CCD studies (rotatable, max(k, 3) centre runs): one material job",
               [measure(k, None, args.reps) for k in args.factors], "factors")
    if args.runs:
        _table(f"custom designs, {args.run_factors} factors: one material job",
               [measure(args.run_factors, n, args.reps) for n in args.runs], "runs")


if __name__ == "__main__":
    main()

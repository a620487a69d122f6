"""Run every row of a run sheet through a simulation command and write the filled-in table.

    python examples/dem_heap/run_design.py --sheet sheet.csv --out table.csv --runs-dir runs/rolling \\
        --command "python examples/dem_heap/heap.py --mu {mu_s} --mur {mu_r} --seed {seed} \\
                   --out {run_dir}/responses.json" --jobs 2

The sheet is the one ``python -m demid design`` writes (``run``, ``std_order``, one column per
factor, one empty column per response). The command follows the ``simulation:`` contract: each
factor name, ``{run}``, ``{wave}``, ``{seed}`` and ``{run_dir}`` are replaced by numbers and paths,
the command is split with shlex (no shell), and it writes ``responses.json`` ({response: value})
into ``{run_dir}``. A run that exits non-zero, times out or writes no valid responses is kept in
the table with empty responses and ``status`` ``failed``. The seed is ``seed_base + run``.
"""
import argparse
import csv
import json
import math
import shlex
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path


def command_for(template, row, factors, run_dir, wave, seed):
    values = {name: row[name] for name in factors}
    values.update(run=row["run"], wave=wave, seed=seed, run_dir=str(run_dir))
    return [part.format(**values) for part in shlex.split(template)]


def run_one(template, row, factors, responses, runs_dir, wave, seed_base, timeout):
    run = int(row["run"])
    run_dir = runs_dir / f"run{run}"
    run_dir.mkdir(parents=True, exist_ok=True)
    argv = command_for(template, row, factors, run_dir, wave, seed_base + run)
    started = time.time()
    with open(run_dir / "log", "w") as log:
        try:
            code = subprocess.run(argv, stdout=log, stderr=subprocess.STDOUT, timeout=timeout).returncode
        except subprocess.TimeoutExpired:
            code = "timeout"
    result = {"run": run, "seed": seed_base + run, "wall_s": round(time.time() - started, 1)}
    try:
        values = json.loads((run_dir / "responses.json").read_text())
        ok = code == 0 and all(math.isfinite(float(values[r])) for r in responses)
    except (OSError, ValueError, KeyError, TypeError):
        values, ok = {}, False
    result.update(values)
    result["status"] = "ok" if ok else "failed"
    return result


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--sheet", type=Path, required=True)
    parser.add_argument("--out", type=Path, required=True, help="the filled-in table (CSV)")
    parser.add_argument("--runs-dir", type=Path, required=True, help="one folder per run")
    parser.add_argument("--command", required=True)
    parser.add_argument("--wave", type=int, default=1)
    parser.add_argument("--seed-base", type=int, default=0)
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--timeout", type=float, default=1800.0, help="[s] per run")
    args = parser.parse_args(argv)

    with open(args.sheet, newline="") as handle:
        rows = list(csv.DictReader(handle))
    columns = list(rows[0])
    responses = [c for c in columns if all(row[c] == "" for row in rows)]
    factors = [c for c in columns if c not in responses and c not in ("run", "std_order")]
    with ThreadPoolExecutor(args.jobs) as pool:
        results = list(pool.map(lambda row: run_one(
            args.command, row, factors, responses, args.runs_dir, args.wave, args.seed_base,
            args.timeout), rows))

    table_columns = ["run"] + factors + responses + ["status"]
    args.out.parent.mkdir(parents=True, exist_ok=True)
    with open(args.out, "w", newline="") as handle:
        writer = csv.writer(handle, lineterminator="\n")
        writer.writerow(table_columns)
        for row, result in sorted(zip(rows, results), key=lambda pair: int(pair[0]["run"])):
            ok = result["status"] == "ok"
            writer.writerow([row["run"]] + [row[f] for f in factors]
                            + [result[r] if ok else "" for r in responses] + [result["status"]])
    summary = args.runs_dir / "runs.json"
    summary.write_text(json.dumps(sorted(results, key=lambda r: r["run"]), indent=1) + "\n")
    failed = sum(r["status"] != "ok" for r in results)
    print(f"{args.out}: {len(results)} runs, {failed} failed; per-run details in {summary}")


if __name__ == "__main__":
    sys.exit(main())

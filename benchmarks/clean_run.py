"""Wall time of a clean demo run, per rule and in all, optionally against an earlier commit.

Each revision is cloned into a temporary folder and run there with its own package on PYTHONPATH:
``--runs`` clean ``snakemake -c2`` runs (results/ and .snakemake/ removed before each), then ``--runs``
dry runs.  Each run's wall and CPU seconds (every process the run started), the sums of the
``benchmark:`` files' ``s`` and ``cpu_time`` columns, and per rule their medians.  With
``--against REV`` the same for REV, and the ratios (this / REV): the clean-run goal is stated on one
machine, and a ratio carries over to another.

    python benchmarks/clean_run.py --runs 3 --against f6b9132

Measured (the 2-core demo machine, shared: other work kept its load average between 1 and 6, so wall
times swing by a factor of two between runs; CPU seconds are steadier but also inflated under load):

- 54f7080 -> cc18223 (paper figures copied by ``cp``, not a second Snakemake; figures drawn in two
  processes; OpenBLAS on one thread per job; the report's kernel stopped at once; lighter imports).
  ``--runs 3 --against 54f7080`` at 38268f2 (load 6 falling to 0.8 while it ran, so the base met the calmer
  machine): clean-run CPU 36.2 -> 31.8 s (0.88), wall 47.7 -> 48.5 s; dry run 1.57 -> 1.69 CPU s (noise).
  Clean runs alternating base and this commit (same load for both): at load ~5, wall 58.7 -> 48.4 s,
  CPU 37.3 -> 32.2 s; at load 1-2.5, wall 30.5 -> 28.5 s, CPU 34.1 -> 29.0 s (0.85); the calmest pair
  (load 1.3-1.5, cc18223): wall 25.1 -> 20.6 s (0.82), CPU 34.1 -> 28.7 s (0.84).  Per rule (CPU s,
  the benchmark files' sampled cpu_time): each paper_figure 1.3 -> 0.0 (it had started a second
  Snakemake that parsed the workflow again, and held a core for 2-4 s: the third material waited for
  it); the paste grid's prediction 1.3 -> 0.3 (OpenBLAS threads spinning beside the other job).  Every
  output file byte-identical to 54f7080's (``diff -r`` of clean runs).
"""

from __future__ import annotations

import argparse
import os
import resource
import statistics
import subprocess
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]


def _children_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def _timed(cmd: list[str], cwd: Path, env: dict, cpu: list | None = None) -> float:
    """Wall seconds of ``cmd``; with ``cpu``, its CPU seconds (every process it started, Snakemake's own
    included: less sensitive to other load on the machine than wall time) are appended there."""
    start, start_cpu = time.perf_counter(), _children_cpu()
    subprocess.run(cmd, cwd=cwd, env=env, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    if cpu is not None:
        cpu.append(_children_cpu() - start_cpu)
    return time.perf_counter() - start


def _benchmark_files(clone: Path) -> list[Path]:
    """The rules' benchmark files: under results/benchmarks, or under benchmarks/ in a revision from
    before they moved beside the results."""
    return sorted([*(clone / "results" / "benchmarks").glob("*/*.tsv"), *(clone / "benchmarks").glob("*/*.tsv")])


def _rule_times(clone: Path) -> dict[str, tuple[float, float]]:
    """(wall s, cpu s) per benchmark file of the last run, named by rule folder and file."""
    out = {}
    for tsv in _benchmark_files(clone):
        header, *rows = tsv.read_text().splitlines()
        last = dict(zip(header.split("\t"), rows[-1].split("\t")))
        out[f"{tsv.parent.name}/{tsv.stem}"] = (float(last["s"]), float(last["cpu_time"]))
    return out


def measure(rev: str, runs: int) -> dict:
    with tempfile.TemporaryDirectory(prefix="demid-bench-") as tmp:
        clone = Path(tmp) / "clone"
        subprocess.run(["git", "clone", "-q", str(REPO), str(clone)], check=True)
        subprocess.run(["git", "checkout", "-q", rev], cwd=clone, check=True)
        env = dict(os.environ, PYTHONPATH=str(clone))
        walls, cpus, per_rule = [], [], []
        for _ in range(runs):
            subprocess.run(["rm", "-rf", "results", ".snakemake"], cwd=clone, check=True)
            for tsv in _benchmark_files(clone):
                tsv.unlink()
            walls.append(_timed(["snakemake", "-c2", "-q"], clone, env, cpus))
            per_rule.append(_rule_times(clone))
        dry_cpus = []
        dry = [_timed(["snakemake", "-n", "-q"], clone, env, dry_cpus) for _ in range(runs)]
        size = sum(f.stat().st_size for f in (clone / "results").rglob("*") if f.is_file())
    rules = {name: (statistics.median(r[name][0] for r in per_rule), statistics.median(r[name][1] for r in per_rule))
             for name in per_rule[0] if all(name in r for r in per_rule)}
    # the benchmark files' sums per run (their cpu_time is sampled, so it misses the last moments of a job)
    sums = [(sum(w for w, _ in r.values()), sum(c for _, c in r.values())) for r in per_rule]
    return {"rev": rev, "walls": walls, "cpus": cpus, "dry": dry, "dry_cpus": dry_cpus, "rules": rules,
            "rule_wall_sum": statistics.median(w for w, _ in sums), "rule_cpu_sum": statistics.median(c for _, c in sums),
            "mb": size / 1e6}


def _print(result: dict, base: dict | None) -> None:
    def line(label, now, before):
        ratio = f"{now / before:6.2f}" if before else ""
        print(f"{label:40s} {now:9.2f} {before if before is not None else '':>9} {ratio}")

    print(f"{'':40s} {result['rev'][:9]:>9} {base['rev'][:9] if base else '':>9} {'ratio' if base else ''}")
    line("clean snakemake -c2, wall s (median)", statistics.median(result["walls"]),
         round(statistics.median(base["walls"]), 2) if base else None)
    line("clean snakemake -c2, CPU s (median)", statistics.median(result["cpus"]),
         round(statistics.median(base["cpus"]), 2) if base else None)
    line("benchmark files: sum s (median)", result["rule_wall_sum"],
         round(base["rule_wall_sum"], 2) if base else None)
    line("benchmark files: sum cpu_time (median)", result["rule_cpu_sum"],
         round(base["rule_cpu_sum"], 2) if base else None)
    line("snakemake -n, wall s (median)", statistics.median(result["dry"]),
         round(statistics.median(base["dry"]), 2) if base else None)
    line("snakemake -n, CPU s (median)", statistics.median(result["dry_cpus"]),
         round(statistics.median(base["dry_cpus"]), 2) if base else None)
    line("results/, MB", result["mb"], round(base["mb"], 1) if base else None)
    print("runs:", ", ".join(f"{w:.2f}" for w in result["walls"]),
          *(["| base:", ", ".join(f"{w:.2f}" for w in base["walls"])] if base else []))
    print(f"\n{'rule (median wall s / cpu s)':40s} {'this':>15}")
    for name, (wall, cpu) in result["rules"].items():
        print(f"{name:40s} {wall:7.2f} / {cpu:5.2f}")
    if base:
        print(f"\n{'rule of ' + base['rev'][:9]:40s}")
        for name, (wall, cpu) in base["rules"].items():
            print(f"{name:40s} {wall:7.2f} / {cpu:5.2f}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--rev", default="HEAD", help="the revision measured (default: HEAD)")
    parser.add_argument("--against", help="an earlier revision to compare with")
    args = parser.parse_args()
    result = measure(args.rev, args.runs)
    base = measure(args.against, args.runs) if args.against else None
    _print(result, base)


if __name__ == "__main__":
    main()

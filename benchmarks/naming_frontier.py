"""Where the catalogue naming rate went: the engine with each of three pieces of level-1 criticism taken out.

Three parts of ``demid.criticism`` each cost catalogue naming (``benchmarks/honest_causes.py``, part 1)
and each buys something another measure asks for:

lof-share   lack of fit holds ``catalogue.LOF_SHARE`` of the family's level (detection at least as often
            as the classical lack-of-fit test); ``equal`` gives every family member the same weight;
slip        the ``factor_level`` test (a run that fits a slipped factor value); ``no-slip`` drops it, so
            a planted outlier can no longer be read as a slip;
rules       a cause is named only when it is singled out (``naming.why_not_singled_out``: corner-only terms,
            a stronger rival of another kind, unequal scatter resting on one run); ``no-rules`` names
            the strongest rejected cause whatever else fired.

Per variant: catalogue naming and false alarms, and on the off-catalogue defects the confidently wrong
first cause (strict, lenient, shape) and detection against the classical lack-of-fit test.

``--combinations`` adds a screen of other ways to combine the family's first-round p-values into the
test that decides whether anything is reported (weighted min-P, as used; a weighted harmonic mean of
p-values; a truncated product), each calibrated on the same simulated joint null: alarm rate on the
catalogue's defect cells against detection off the catalogue.  Naming cannot exceed the first.

    python benchmarks/naming_frontier.py --reps 20 [--jobs 2] [--combinations]
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from concurrent.futures import ProcessPoolExecutor
from dataclasses import replace
from pathlib import Path

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
sys.path.insert(0, str(Path(__file__).resolve().parent))

VARIANTS = {
    "as built": (),
    "equal weights": ("equal",),
    "no factor_level": ("no-slip",),
    "no naming rules": ("no-rules",),
    "equal weights, no factor_level": ("equal", "no-slip"),
    "equal weights, no factor_level, no naming rules": ("equal", "no-slip", "no-rules"),
}


def _patch(changes: tuple[str, ...]) -> None:
    """Take pieces out of the engine in this (worker) process."""
    from demid.criticism import catalogue, level1, verdict

    if "equal" in changes:
        def equal(causes):
            return np.ones(len(causes))
        catalogue.family_weights = equal
        verdict.family_weights = equal
    if "no-slip" in changes:
        catalogue.Round._factor_level = lambda self, data, m, eps: None
    if "no-rules" in changes:
        level1.why_not_singled_out = lambda data, model, h, hypotheses: None


def _run_variant(job: tuple[str, str, int, int]) -> list[dict]:
    name, part, reps, seed0 = job
    _patch(VARIANTS[name])
    import honest_causes as hc

    rows: list = []
    if part == "catalogue":
        hc.catalogue_part(reps, seed0, rows, [])
    else:
        hc.off_catalogue_part(reps, 100_000 + seed0, rows, [])
    return [{**r, "variant": name} for r in rows]


def _summary(rows: list[dict]) -> pd.DataFrame:
    frame = pd.DataFrame(rows)
    out = []
    for name in VARIANTS:
        sub = frame[frame["variant"] == name]
        cat, off = sub[sub["part"] == "catalogue"], sub[sub["part"] == "off"]
        out.append({"variant": name, "naming": cat[cat["kind"] != "clean"]["named"].mean(),
                    "false_alarm": cat[cat["kind"] == "clean"]["alarm"].mean(),
                    "wrong": off["wrong"].mean(), "wrong_lenient": off["wrong_lenient"].mean(),
                    "wrong_shape": off["wrong_shape"].mean(), "detect": off["detect"].mean(),
                    "lack_of_fit_test": off["lof"].mean()})
    return pd.DataFrame(out)


# --------------------------------------------------------------------------- other combinations
def _first_round(table, factors) -> tuple[list[str], np.ndarray, np.ndarray]:
    from demid.criticism.catalogue import Round
    from demid.criticism.level1 import prepare_data
    from demid.criticism.models import Model, ModelForm
    from demid.criticism.run_order import assess_run_order

    data, _ = prepare_data(table, factors, "y", None, ())
    order = assess_run_order(data.runs, data.coded, {"y": data.y}, "performed")
    data = replace(data, drift_tested=order.drift_tested)
    rnd = Round(data, Model(data, ModelForm()), 1999, np.random.default_rng(0))
    causes = [h.cause for h in rnd.hypotheses]
    if not causes:
        return causes, np.zeros(0), np.zeros((1999, 0))
    return causes, np.array([h.logp for h in rnd.hypotheses]), np.column_stack([h.null_logp for h in rnd.hypotheses])


def _weights(causes: list[str], share: float | None) -> np.ndarray:
    m = len(causes)
    if share is None or "lack_of_fit" not in causes or m == 1:
        return np.ones(m)
    return np.array([share * m if c == "lack_of_fit" else (1 - share) * m / (m - 1) for c in causes])


def _combined(kind: str, logp: np.ndarray, w: np.ndarray) -> np.ndarray:
    """Evidence against the joint null (larger = more), per row of log p-values."""
    if kind == "min-P":
        return -(logp - np.log(w)).min(axis=-1)
    if kind == "harmonic mean":
        return np.log(np.sum(w * np.exp(np.clip(-logp, None, 700.0)), axis=-1))
    cut = np.log(0.05)  # truncated product of the p-values below 0.05
    return np.sum(np.where(logp < cut, -w * (logp - cut), 0.0), axis=-1)


COMBINATIONS = [(kind, share) for kind in ("min-P", "harmonic mean", "truncated product")
                for share in (None, 0.5, 0.65)]


def _combination_job(job: tuple[str, int, int]) -> list[dict]:
    import honest_causes as hc
    from criticism_power import DESIGNS
    from generators import FACTORS, ccd_table, off_catalogue_table

    part, reps, seed0 = job
    tables = []
    if part == "catalogue":
        for k, replicates, sizes in DESIGNS:
            cells = [("clean", 0.0)] + [(kind, s) for kind, values in sizes.items() for s in values]
            for kind, size in cells:
                for r in range(reps):
                    t, _ = ccd_table(seed0 + r, k, kind, size, replicates=replicates)
                    tables.append(((k, replicates, kind, size), t, k))
    else:
        for k in (2, 3):
            for kind, size in hc.OFF_CELLS:
                for r in range(reps):
                    seed = 100_000 + seed0 + r
                    t, _ = (off_catalogue_table(seed, k, "slip", n_slipped=int(size)) if kind == "slip"
                            else off_catalogue_table(seed, k, kind, size))
                    tables.append(((k, 1, kind, size), t, k))
    rows = []
    for cell, table, k in tables:
        causes, obs, null = _first_round(table, FACTORS[k])
        row = {"part": part, "cell": cell, "clean": cell[2] == "clean"}
        for kind, share in COMBINATIONS:
            if not causes:
                row[f"{kind}|{share}"] = False
                continue
            w = _weights(causes, share)
            t_obs = _combined(kind, obs[None, :], w)[0]
            p = (1.0 + np.count_nonzero(_combined(kind, null, w) >= t_obs - 1e-12)) / (len(null) + 1.0)
            row[f"{kind}|{share}"] = bool(p <= 0.05)
        rows.append(row)
    return rows


def _combination_table(rows: list[dict]) -> pd.DataFrame:
    frame = pd.DataFrame(rows)
    out = []
    for kind, share in COMBINATIONS:
        col = f"{kind}|{share}"
        per_cell = frame.groupby(["part", "cell"])[col].mean().reset_index()
        cat = per_cell[per_cell["part"] == "catalogue"]
        clean = cat["cell"].map(lambda c: c[2] == "clean")
        out.append({"combination": kind, "lack_of_fit_share": "equal" if share is None else share,
                    "catalogue_alarm": cat.loc[~clean, col].mean(), "false_alarm": cat.loc[clean, col].mean(),
                    "off_catalogue_detect": per_cell.loc[per_cell["part"] == "off", col].mean()})
    return pd.DataFrame(out)


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--reps", type=int, default=20)
    parser.add_argument("--seed0", type=int, default=0)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--combinations", action="store_true")
    args = parser.parse_args(argv)
    start = time.time()
    jobs = [(name, part, args.reps, args.seed0) for name in VARIANTS for part in ("catalogue", "off")]
    with ProcessPoolExecutor(max_workers=args.jobs, max_tasks_per_child=1) as pool:
        rows = [r for chunk in pool.map(_run_variant, jobs) for r in chunk]
        combos = ([r for chunk in pool.map(_combination_job, [(p, args.reps, args.seed0) for p in ("catalogue", "off")])
                   for r in chunk] if args.combinations else [])
    with pd.option_context("display.width", 200, "display.max_columns", 20):
        print(_summary(rows).to_string(index=False, float_format=lambda v: f"{v:.3f}"))
        if combos:
            print()
            print(_combination_table(combos).to_string(index=False, float_format=lambda v: f"{v:.3f}"))
    print(f"elapsed {time.time() - start:.0f} s")


if __name__ == "__main__":
    main()

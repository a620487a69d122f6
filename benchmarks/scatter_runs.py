"""Unequal scatter after one round of runs: where the runs would have to go, and whether the table says where.

On the unequal-scatter tables of benchmarks/decide_causes.py (sd growing 30-fold along one factor), one round of
at most four proposed runs names the scatter less often than any other kind.  This asks why, per table:

needs       ambiguous or misnamed first (decide_causes.py's tables that need runs)
proposed    named after the runs the first verdict proposes (what the loop makes; none: the first verdict)
reading     named after four replicates at the noisiest point of the first round's best scatter reading (its
            covariate and direction, discrimination's prediction of the noise there): what the table itself says
noisy_end   named after four replicates at the planted factor's far axial end, the others at their centre: an
            oracle that knows where the scatter is, to bound what four runs can do
follows     the first round's best scatter reading follows the planted factor (its covariate), growing the right way

Measured (n_null 199, 2 and 3 factors, 20 seeds each; seeds 0-19 | 20-39 | 40-59):

    tables ambiguous or misnamed first          7      | 10     | 3
      named after the proposed runs             0.429  | 0.700  | 0.333
      after four at the reading's noisiest      0.286  | 0.600  | 0.333
      after four at the planted noisy end       0.714  | 0.900  | 0.667
      the reading follows the planted factor    0.429  | 0.600  | 0.333
    tables adequate first (no misfit found)     25     | 22     | 25
      after four at the planted noisy end       0.520  | 0.500  | 0.640
      the reading follows the planted factor    0.280  | 0.455  | 0.360

No unequal-scatter table is named in the first verdict.  Four replicates where the scatter really is name it in
two thirds to nine tenths of the tables that need runs; the table does not say where that is (its best scatter
reading follows the planted factor, the right way, in a third to three fifths of them), and replicates where the
reading points name it no more often than the proposed runs do.  What one round of four runs leaves on unequal
scatter is the information in 13-20 runs, not the choice among the points the table suggests.

    python benchmarks/scatter_runs.py --reps 20 [--seed0 20] [--n-null 199]
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

sys.path.insert(0, str(Path(__file__).resolve().parent))
from decide_causes import CELLS, Truth, verdict_of  # noqa: E402

from demid.criticism import criticize, discrimination, level1, naming  # noqa: E402


def _first_round_entries(truth: Truth, n_null: int):
    """The first verdict and the first round's candidate entries (each cause's extension and AICc)."""
    seen = {}
    original = naming.candidate_entries

    def keep(data, base_model, first_round):
        seen["entries"] = original(data, base_model, first_round)
        seen["data"] = data
        return seen["entries"]

    naming.candidate_entries = keep
    try:
        first = criticize(truth.table, truth.factors, "y", alpha=truth.alpha, n_null=n_null)
        if "entries" not in seen:  # no cause named or not singled out: the entries are computed here alone
            data, _ = level1.prepare_data(truth.table, truth.factors, "y", truth.alpha, (), None)
            base = level1.Model(data, level1.ModelForm())
            first_round = level1.Round(data, base, n_null, np.random.default_rng(0))
            keep(data, base, first_round)
    finally:
        naming.candidate_entries = original
    return first, seen["entries"], seen["data"]


def _named_after(truth: Truth, coded: np.ndarray, n_null: int) -> bool:
    after = criticize(truth.augmented(coded), truth.factors, "y", alpha=truth.alpha, n_null=n_null)
    return bool(verdict_of(after, truth)["named"])


def one_table(seed: int, k: int, size: float, n_null: int) -> dict:
    truth = Truth(seed, k, "het", size)
    first, entries, data = _first_round_entries(truth, n_null)
    verdict = verdict_of(first, truth)
    row = {"k": k, "seed": seed, "first_named": verdict["named"], "first": first.verdict,
           "needs": bool(first.candidates) or verdict["wrong"]}
    runs = first.discriminating_runs if first.runs_for_next_wave else []
    row["proposed"] = row["first_named"] if not runs else _named_after(
        truth, truth.coding.to_coded(np.array([[r[f] for f in truth.factors] for r in runs])), n_null)
    scatter = sorted((e for e in entries if e["cause"] == "heteroscedasticity"), key=lambda e: e["aicc"])
    grid = discrimination.candidate_grid(data)
    j = truth.factors.index(truth.planted.factor)
    if scatter:
        model = scatter[0]["model"]
        noise = discrimination.prediction_parts(model, grid)[2]
        noisiest = grid[int(np.argmax(noise))]
        row["reading"] = _named_after(truth, np.repeat(noisiest[None, :], 4, axis=0), n_null)
        row["follows"] = scatter[0]["detail"] == truth.planted.factor and model.spec.weight_gamma > 0
    else:
        row["reading"], row["follows"] = row["first_named"], False
    end = np.zeros((4, k))
    end[:, j] = truth.alpha
    row["noisy_end"] = _named_after(truth, end, n_null)
    return row


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--reps", type=int, default=20)
    parser.add_argument("--seed0", type=int, default=0)
    parser.add_argument("--n-null", type=int, default=199)
    args = parser.parse_args(argv)
    start = time.time()
    rows = [one_table(args.seed0 + r, k, dict(CELLS[k])["het"], args.n_null)
            for k in (2, 3) for r in range(args.reps)]
    frame = pd.DataFrame(rows)
    print(f"unequal-scatter tables: {len(frame)}, named first {frame['first_named'].mean():.3f}, adequate first "
          f"{(frame['first'] == 'adequate').mean():.3f}")
    for label, part in (("all", frame), ("ambiguous or misnamed first", frame[frame["needs"]]),
                        ("adequate first", frame[frame["first"] == "adequate"])):
        print(f"  {label} ({len(part)}): named after the proposed runs {part['proposed'].mean():.3f}, after four at "
              f"the scatter reading's noisiest point {part['reading'].mean():.3f}, after four at the planted "
              f"noisy end {part['noisy_end'].mean():.3f}; the reading follows the planted factor "
              f"{part['follows'].mean():.3f}")
    print(f"elapsed {time.time() - start:.0f} s")


if __name__ == "__main__":
    main()

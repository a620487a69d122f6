"""Regenerate the demonstration tables data/ccd/{poraver,paste,mortar}.csv.

The tables are reconstructed from the paper's published numbers (see data/README.md);
this script is not part of the Snakemake pipeline, whose input they are.

    python demo/reconstruct_demo_data.py            # write the three CSVs (deterministic)
    python demo/reconstruct_demo_data.py --solve    # also re-solve the surrogate coefficients
                                                    # (minutes) and print them for RHO in demo/reconstruct.py
"""

import argparse
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))  # the repository root: demo/ is not installed
from demo import reconstruct  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--out", default=str(Path(__file__).resolve().parent.parent / "data" / "ccd"),
                    help="output folder (default: data/ccd of this repository)")
parser.add_argument("--solve", action="store_true", help="re-solve the inverse problems and print the coefficients")
args = parser.parse_args()

if args.solve:
    for solver in (reconstruct.solve_poraver, reconstruct.solve_paste, reconstruct.solve_mortar):
        for response, rho in solver().items():
            print(f"{solver.__name__[6:]}.{response}: ({', '.join(f'{v:.10g}' for v in rho)})")
for material, path in reconstruct.reconstruct(args.out).items():
    print(f"wrote {path}", file=sys.stderr)

"""Command line: ``python -m demid <command>``.  A thin dispatcher over the package's functions.

User errors print one line (``demid: error: ...``) and exit with status 2; no traceback.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from .errors import InputError


def _split(text: str) -> list[str]:
    return [t.strip() for t in text.split(",") if t.strip()]


def _load_table(path: str, factors: list[str], responses: list[str]):
    from .data import read_table

    table, warnings = read_table(path, factors, responses)
    for w in warnings:
        print(f"demid: warning: {w}", file=sys.stderr)
    return table


def _alpha(table, factors, alpha):
    """Axial distance: given, or inferred as (max level distance) / (factorial level distance)."""
    if alpha is not None:
        return alpha
    from .data import infer_coding

    coding = infer_coding(table, factors, {"type": "ccd"}, "table")
    return float(abs(coding.to_coded(table[factors].to_numpy(dtype=float))).max())


def cmd_fit(args) -> int:
    from .io import write_json
    from .surrogate import fit_response

    factors, responses = _split(args.factors), _split(args.responses)
    table = _load_table(args.data, factors, responses)
    alpha = _alpha(table, factors, args.alpha)
    out = {}
    for r in responses:
        fit = fit_response(table, factors, r, alpha=alpha)
        st = fit.statistics()
        coef = fit.coefficients()
        out[r] = {
            "n_runs": st.n_runs, "r2": st.r2, "adj_r2": st.adj_r2, "rmse": st.rmse, "resid_std": st.resid_std,
            "q2": st.q2, "lof_f": st.lof_f, "lof_p": st.lof_p,
            # in the table's own (actual) units; coded units (factorial points at +-1) alongside
            "coefficients": dict(zip(coef["term"], coef["coefficient_actual"])),
            "coefficients_coded": dict(zip(coef["term"], coef["coefficient_coded"])),
        }
    write_json(out, args.out)
    return 0


def cmd_validate(args) -> int:
    from .config import load_config
    from .data import validate_material

    config = load_config(args.config)
    for name, mat in config["materials"].items():
        vt = validate_material(name, mat)
        for w in vt.warnings:
            print(f"demid: warning: {w}", file=sys.stderr)
        counts = ", ".join(f"{v} {k}" for k, v in vt.summary(name)["point_types"].items())
        print(f"{name}: {mat['data']} OK ({len(vt.table)} runs: {counts})")
    print(f"{args.config}: configuration and {len(config['materials'])} table(s) valid")
    return 0


def cmd_criticize(args) -> int:
    from .criticism import criticize
    from .io import write_json

    factors = _split(args.factors)
    table = _load_table(args.data, factors, [args.response])
    result = criticize(table, factors, args.response, alpha=args.alpha)
    write_json(result.to_json(), args.out)
    return 0


def _parse_published(text: str) -> dict:
    out = {}
    for item in _split(text):
        key, sep, value = item.partition("=")
        if not sep:
            raise InputError(f"--published: expected key=value, found '{item}'")
        try:
            float(value)
        except ValueError:
            raise InputError(f"--published: '{key}' needs a number, found '{value}'") from None
        out[key.strip()] = value.strip()  # kept as text so printed decimals (trailing zeros) survive
    return out


def cmd_check_transcription(args) -> int:
    from .io import write_json
    from .transcription import check_transcription

    from .data import read_printed

    factors = _split(args.factors)
    table = _load_table(args.data, factors, [args.response])
    published = _parse_published(args.published)
    result = check_transcription(table, factors, args.response, published,
                                 alpha=_alpha(table, factors, args.alpha), design_type=args.design,
                                 printed=read_printed(args.data, table), source=args.data)
    write_json(result.to_json(), args.out)
    return 0


_DATA_HELP = "CSV table of the design runs: one column per factor and response"


def build_parser() -> argparse.ArgumentParser:
    from . import __version__

    parser = argparse.ArgumentParser(prog="demid", description="Command line: python -m demid <command>. "
                                     "The full pipeline runs with snakemake -c2.")
    parser.add_argument("--version", action="version", version=f"demid {__version__}")
    sub = parser.add_subparsers(dest="command", required=True)

    p = sub.add_parser("fit", help="quadratic OLS fit statistics and coefficients as JSON")
    p.add_argument("--data", required=True, help=_DATA_HELP)
    p.add_argument("--factors", required=True, help="comma-separated factor columns, in order")
    p.add_argument("--responses", required=True, help="comma-separated response columns")
    p.add_argument("--alpha", type=float, default=None, help="CCD axial distance (default: inferred)")
    p.add_argument("--out", required=True, help="JSON file to write")
    p.set_defaults(func=cmd_fit)

    p = sub.add_parser("validate", help="check a config and its tables without running anything")
    p.add_argument("--config", required=True, help="the study's config YAML")
    p.set_defaults(func=cmd_validate)

    p = sub.add_parser("criticize", help="what the quadratic surrogate gets wrong, why, and the gain of a fix")
    p.add_argument("--data", required=True, help=_DATA_HELP)
    p.add_argument("--factors", required=True, help="comma-separated factor columns, in order")
    p.add_argument("--response", required=True, help="the response column to criticise")
    p.add_argument("--alpha", type=float, default=None, help="CCD axial distance (default: inferred)")
    p.add_argument("--out", required=True, help="JSON file to write")
    p.set_defaults(func=cmd_criticize)

    p = sub.add_parser("check-transcription", help="hold a table against its published statistics")
    p.add_argument("--data", required=True, help=_DATA_HELP)
    p.add_argument("--factors", required=True, help="comma-separated factor columns, in order")
    p.add_argument("--response", required=True, help="the response column the statistics belong to")
    p.add_argument("--published", required=True, help="published statistics, e.g. r2=0.9617,lof_f=90.33")
    p.add_argument("--alpha", type=float, default=None, help="CCD axial distance (default: inferred)")
    p.add_argument("--design", default="ccd", choices=["ccd", "box_behnken", "factorial", "custom"],
                   help="design type of the table (default: ccd)")
    p.add_argument("--out", required=True, help="JSON file to write")
    p.set_defaults(func=cmd_check_transcription)
    return parser


def main(argv=None) -> int:
    args = build_parser().parse_args(argv)
    try:
        return int(args.func(args) or 0)
    except InputError as err:
        print(f"demid: error: {err}", file=sys.stderr)
        return 2
    except OSError as err:
        print(f"demid: error: {err.filename or ''}: {err.strerror}", file=sys.stderr)
        return 2


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())

"""Command line: ``python -m demid <command>``.  A thin dispatcher over the package's functions.

User errors print one line (``demid: error: ...``) and exit with status 2; no traceback.
"""

from __future__ import annotations

import argparse
import difflib
import re
import sys
from pathlib import Path

from .cli_tables import design_coding, load_table, require_quadratic, table_design
from .errors import InputError
from .out_path import check_out_path


def _split(text: str) -> list[str]:
    if ";" in text:
        raise InputError(f"'{text}': separate the names with commas, not semicolons")
    return [t.strip() for t in text.split(",") if t.strip()]


def _one_response(text: str, command: str) -> None:
    if len(_split(text)) > 1:
        raise InputError(f"--response: {command} takes one response, found '{text}'; run it once per response")


def _say(note: str) -> None:
    if note:
        print(note, file=sys.stderr)


def _check_out(args, is_own) -> None:
    """``--out`` checked before any work: not the command's input, not a folder or device, and an existing
    file replaced only when the command wrote it (or with --force)."""
    check_out_path(args.out, "--out", [getattr(args, "data", None)], force=args.force, is_own=is_own)


def cmd_fit(args) -> int:
    from .canonical import fit_canonical
    from .io import write_json
    from .surrogate import fit_response

    from .out_path import is_demid_json

    _check_out(args, is_demid_json)
    factors, responses = _split(args.factors), _split(args.responses)
    table = load_table(args.data, factors, responses)
    design, alpha, note = table_design(table, factors, args)
    coding = design_coding(table, factors, design, alpha, args.data)
    out = {}
    blocks = _block_check(table, factors, coding, args.data)
    for r in responses:
        require_quadratic(table, factors, r, coding, args.data)
        fit = fit_response(table, factors, r, alpha=alpha, coding=coding)
        st = fit.statistics()
        coef = fit.coefficients()
        out[r] = {
            "n_runs": st.n_runs, "r2": st.r2, "adj_r2": st.adj_r2, "rmse": st.rmse, "resid_std": st.resid_std,
            "q2": st.q2, "lof_f": st.lof_f, "lof_p": st.lof_p,
            # in the table's own (actual) units; coded units (factorial points at +-1) alongside
            "coefficients": dict(zip(coef["term"], coef["coefficient_actual"])),
            "coefficients_coded": dict(zip(coef["term"], coef["coefficient_coded"])),
            # as in the workflow's fits/{material}.json: one canonical analysis per fitted surface
            "canonical": fit_canonical(fit).to_json(),
        }
        if blocks is not None:  # predictions above are at the mean block effect (the block-averaged surface)
            effects = fit.block_effects()
            out[r]["block_effects"] = {label: e for label, (e, _) in effects.items()}
            out[r]["block_effect_se"] = {label: s for label, (_, s) in effects.items()}
            out[r]["blocks"] = blocks.to_json()
            out[r]["anova"] = fit.anova().to_frame().drop(columns="response").to_dict(orient="records")
    write_json(out, args.out)
    _say(note)
    return 0


def _block_check(table, factors, coding, source):
    """How the table's blocks sit in its design (None without a block column): a block term that cannot
    be estimated stops with one line; a block without centre runs, and non-orthogonal blocking, are said."""
    from .blocks import block_labels, check_blocks
    from .design import model_matrix, quadratic_terms

    labels = block_labels(table)
    if labels is None:
        return None
    coded = coding.to_coded(table[factors].to_numpy(dtype=float))
    check = check_blocks(coded, labels, model_matrix(coded, quadratic_terms(len(factors))))
    if check.problems:
        raise InputError(f"column 'block': {check.problems[0]}", source=source)
    for note in check.notes:
        print(f"demid: note: {source}, column 'block': {note}", file=sys.stderr)
    return check


def cmd_validate(args) -> int:
    from .config import load_config
    from .data import content_hidden_outside, read_printed, validate_material
    from .next_wave import check_next_runs
    from .spec import MaterialSpec
    from .transcription.typos import refuse_likely_typos
    from .waves import check_simulated

    from .config_text import refuse_unsafe_config_files

    refuse_unsafe_config_files([args.config])  # a template named as such, as the workflow names it
    base_dir = Path(args.config).parent  # data paths are written relative to the config file
    config = load_config(args.config, base_dir=base_dir)
    check_next_runs(config, source=args.config)
    check_simulated(config, source=args.config)
    for name, mat in config["materials"].items():
        if mat.get("simulation"):  # no table yet: the workflow runs it and validates each wave's
            print(f"{name}: simulated by demid (simulation.command)")
            continue
        spec = MaterialSpec.from_config(name, config)
        with content_hidden_outside(spec.data, base_dir):
            vt = validate_material(spec, base_dir=base_dir)
            confirmed = refuse_likely_typos(vt, spec, read_printed(Path(base_dir) / spec.data, vt.table))
        for w in vt.warnings + _outside_the_runs(vt, spec):
            print(f"demid: warning: {w}", file=sys.stderr)
        for flag in confirmed:
            print(f"demid: note: {spec.data}, run {flag['run']}, column '{flag['column']}': value confirmed "
                  f"in confirmed_values although it looks like a typo", file=sys.stderr)
        order = _run_order_note(vt, spec)
        if order:
            print(f"demid: note: {spec.data}: {order}", file=sys.stderr)
        print(f"{name}: {spec.data} OK ({run_counts(vt, spec.design_type, spec.response_names)})")
    print(f"{args.config}: configuration and {sum('data' in m for m in config['materials'].values())} table(s) valid")
    return 0


#: Point types in the words of a run sheet, in the order they are counted.
_POINT_WORDS = {"factorial": "factorial", "axial": "axial", "edge": "edge", "center": "centre"}


def run_counts(vt, design_type: str, responses: list[str]) -> str:
    """``13 runs: 4 factorial, 4 axial, 5 centre`` — by point type where the design has types (a custom
    design's runs have none) — and how many runs failed (no response) or lost some responses."""
    n = len(vt.table)
    types = vt.summary("")["point_types"]
    if design_type != "custom" and set(types) - {"other"}:
        text = f"{n} runs: " + ", ".join(f"{types[k]} {word}" for k, word in _POINT_WORDS.items() if types.get(k))
        text += f", {types['other']} other" if types.get("other") else ""
    else:
        text = f"{n} runs (custom design)"
    lost = {run for runs in vt.failed.values() for run in runs}
    if lost:
        failed = sum(all(run in vt.failed.get(r, ()) for r in responses) for run in lost)
        partial = len(lost) - failed
        text += (f"; {n - len(lost)} complete" + (f", {failed} failed" if failed else "")
                 + (f", {partial} with a response missing" if partial else ""))
    return text


def _outside_the_runs(vt, spec) -> list[str]:
    """Search bounds or a reference point beyond what the runs simulated (the results would rest on
    extrapolation), said before anything runs; level 2 and the report say it again."""
    from .criticism.edges import extrapolation_warnings

    runs = vt.table[spec.factor_names].to_numpy(dtype=float)
    return [f"{spec.data}: {w}" for w in extrapolation_warnings(spec.domain, runs, spec.reference_point)]


def _run_order_note(vt, spec) -> str:
    """Why drift will not be tested, when the run column cannot be the performed order ("" otherwise)."""
    from .criticism.material import material_run_order

    if spec.run_order == "unknown":
        return ""
    why = material_run_order(vt.table, spec, vt.coding).why
    return f"drift will not be tested: {why}" if why else ""


def cmd_criticize(args) -> int:
    from .criticism import criticize
    from .io import write_json
    from .surrogate import fit_response

    from .out_path import is_demid_json

    _check_out(args, is_demid_json)
    factors = _split(args.factors)
    _one_response(args.response, "criticize")
    table = load_table(args.data, factors, [args.response])
    design, alpha, note = table_design(table, factors, args)
    coding = design_coding(table, factors, design, alpha, args.data)
    require_quadratic(table, factors, args.response, coding, args.data)
    _block_check(table, factors, coding, args.data)
    fit = fit_response(table, factors, args.response, alpha=alpha, coding=coding)
    result = criticize(table, factors, args.response, alpha=alpha, run_order=args.run_order, fit=fit)
    write_json(result.to_json(), args.out)
    _say(note)
    return 0


def _parse_published(text: str) -> dict:
    """``key=value`` pairs read as the config's ``published`` block reads them (bounds such as ``<0.0001``
    and percentages allowed, impossible values and unknown or repeated keys refused)."""
    from .transcription import STATISTICS
    from .transcription.printed import impossible_published

    out = {}
    items = _split(text)
    for index, item in enumerate(items):
        key, sep, value = (part.strip() for part in item.partition("="))
        if not sep:
            before = items[index - 1] if index else ""
            if re.fullmatch(r"\d+(\.\d+)?", item) and re.search(r"=\s*[-+]?\d+$", before):
                if "." in item:  # 1,234.5: a thousands separator
                    raise InputError(f"--published: '{before},{item}' has a thousands separator; write "
                                     f"{before}{item} (pairs are separated by commas)")
                raise InputError(f"--published: '{before},{item}' has a decimal comma; write "
                                 f"{before}.{item} (pairs are separated by commas)")
            raise InputError(f"--published: expected key=value, found '{item}'")
        if key not in STATISTICS:
            same_letters = [k for k in STATISTICS if k.lower() == key.lower()]
            close = same_letters or difflib.get_close_matches(key, STATISTICS, n=1)
            hint = f"did you mean '{close[0]}'? " if close else ""
            raise InputError(f"--published: unknown statistic '{key}'; {hint}known: {', '.join(STATISTICS)}")
        if key in out:
            raise InputError(f"--published: '{key}' is given twice ({out[key]} and {value}); keep the printed one")
        why = impossible_published(key, value, where=f"--published {key}")
        if why:
            raise InputError(f"--published {key}: {why}")
        out[key] = value  # kept as text so printed decimals (trailing zeros) survive
    return out


def cmd_check_transcription(args) -> int:
    from .io import write_json
    from .transcription import check_transcription

    from .data import read_printed

    from .out_path import is_demid_json

    _check_out(args, is_demid_json)
    factors = _split(args.factors)
    _one_response(args.response, "check-transcription")
    table = load_table(args.data, factors, [args.response])
    published = _parse_published(args.published)
    design, alpha, note = table_design(table, factors, args)
    # An inferred design codes the table by its geometry (per-factor axial distances); a declared one as before.
    options = ({"alpha": design["alpha"], "coding": design_coding(table, factors, design, alpha, args.data)}
               if design.get("inferred") else {"alpha": alpha})
    result = check_transcription(table, factors, args.response, published, design_type=design["type"],
                                 printed=read_printed(args.data, table), source=args.data, **options)
    write_json(result.to_json(), args.out)
    _say(note)
    return 0


def cmd_design(args) -> int:
    from .design_generation import fragment_yaml, generate_sheet, parse_factor
    from .io import atomic_path, write_csv

    from .out_path import is_config_fragment, is_unfilled_run_sheet

    _check_design_arguments(args)
    _check_out(args, is_unfilled_run_sheet)
    if args.config_out:
        check_out_path(args.config_out, "--config-out", force=args.force, is_own=is_config_fragment)
    sheet = generate_sheet(args.type, [parse_factor(f) for f in args.factor], center_runs=args.center_runs,
                           alpha=args.alpha or "rotatable", seed=args.seed, blocks=args.blocks)
    frame = sheet.to_frame()
    for response in args.response:
        frame[response] = ""
    write_csv(frame, args.out)
    if args.config_out:
        with atomic_path(args.config_out) as tmp:
            tmp.write_text(fragment_yaml(sheet, args.material, args.out, args.response), encoding="utf-8")
    print(f"{args.out}: {len(frame)} runs of a {args.type} design in randomised order (seed {args.seed})")
    return 0


def _check_design_arguments(args) -> None:
    """Options of ``design`` that would write a sheet or config the rest of demid refuses, or overwrite one
    file with another."""
    from .config import RESERVED_COLUMNS
    from .design_generation import check_name, parse_factor

    names = [parse_factor(f).name for f in args.factor] + list(args.response)
    if len(args.factor) < 2:
        raise InputError("--factor: give at least two NAME=LOW:HIGH (admissible sets and surfaces are drawn over "
                         "factor pairs)")
    for name in args.response:
        check_name(name, "--response")
    repeated = next((n for i, n in enumerate(names) if n in names[:i]), None)
    if repeated:
        raise InputError(f"'{repeated}' is given more than once among --factor and --response; each column needs "
                         "its own name")
    reserved = next((n for n in names if n in RESERVED_COLUMNS), None)
    if reserved:
        raise InputError(f"'{reserved}' names a column demid writes itself (run: the run number, status: ok or "
                         "failed); choose another name")
    if "std_order" in names:
        raise InputError("'std_order' names a column of the run sheet (the design's standard order); choose another "
                         "name")
    check_name(args.material, "--material", "name")
    if args.alpha is not None and args.type != "ccd":
        raise InputError(f"--alpha: only a ccd design has an axial distance, not --type {args.type}; leave --alpha "
                         "out")
    if args.seed < 0:
        raise InputError(f"--seed: must be 0 or more, found {args.seed}")
    if Path(args.out).is_dir():
        raise InputError(f"--out: '{args.out}' is a folder; name the CSV file to write")
    if args.config_out and Path(args.config_out).resolve() == Path(args.out).resolve():
        raise InputError("--config-out names the same file as --out; the config would overwrite the run sheet")


def _one_line_error(message: str):
    """Usage errors of new subcommands as one ``demid: error:`` line, status 2 (as argparse)."""
    print(f"demid: error: {message}", file=sys.stderr)
    sys.exit(2)


_DATA_HELP = "CSV table of the design runs: one column per factor and response"


def _table_arguments(p: argparse.ArgumentParser, response_flag: str, response_help: str) -> None:
    """The options shared by the commands that read one design table."""
    p.add_argument("--data", required=True, help=_DATA_HELP)
    p.add_argument("--factors", required=True, help="comma-separated factor columns, in order")
    p.add_argument(response_flag, required=True, help=response_help)
    p.add_argument("--alpha", type=float, default=None, help="CCD axial distance (default: inferred)")
    p.add_argument("--design", default=None, choices=["ccd", "box_behnken", "factorial", "custom"],
                   help="design family: sets the coding (axial points only in a ccd); default: inferred from the "
                        "table's geometry (CCD with per-factor axial distance, Box-Behnken, 3^k, two-level "
                        "factorial with centre runs, otherwise custom) and said on stderr")
    p.add_argument("--out", required=True, help="JSON file to write")
    _force_argument(p)


def _force_argument(p: argparse.ArgumentParser) -> None:
    p.add_argument("--force", action="store_true",
                   help="replace an existing file at --out that this command did not write (never an input)")


def build_parser() -> argparse.ArgumentParser:
    from . import __version__

    parser = argparse.ArgumentParser(prog="demid", description="Command line: python -m demid <command>. "
                                     "The full pipeline runs with snakemake -c2.")
    parser.add_argument("--version", action="version", version=f"demid {__version__}")
    sub = parser.add_subparsers(dest="command", required=True)

    p = sub.add_parser("fit", help="quadratic OLS fit statistics and coefficients as JSON")
    _table_arguments(p, "--responses", "comma-separated response columns")
    p.set_defaults(func=cmd_fit)

    p = sub.add_parser("validate", help="check a config and its tables without running anything")
    p.add_argument("--config", required=True, help="the study's config YAML")
    p.set_defaults(func=cmd_validate)

    p = sub.add_parser("criticize", help="what the quadratic surrogate gets wrong, why, and the gain of a fix")
    _table_arguments(p, "--response", "the response column to criticise")
    from .schema import material_property

    run_order = material_property("run_order")
    p.add_argument("--run-order", choices=run_order["enum"], default=run_order["default"],
                   help="what the run column records: the order the runs were performed in (drift is tested "
                        "unless the column follows the response or the design's standard order) or unknown "
                        "(drift is not tested); default %(default)s")
    p.set_defaults(func=cmd_criticize)

    p = sub.add_parser("check-transcription", help="hold a table against its published statistics")
    _table_arguments(p, "--response", "the response column the statistics belong to")
    p.add_argument("--published", required=True, help="published statistics, e.g. r2=0.9617,lof_f=90.33")
    p.set_defaults(func=cmd_check_transcription)

    p = sub.add_parser("design", help="a randomised run sheet (CCD, Box-Behnken, 3^k factorial) and its config")
    p.add_argument("--type", required=True, choices=["ccd", "box_behnken", "factorial"],
                   help="design family; factorial is the three-level full factorial 3^k")
    p.add_argument("--factor", action="append", default=[], metavar="NAME=LOW:HIGH",
                   help="a factor and its search range in actual units (repeat per factor, in column order); "
                        "the design's outer points (CCD axial points) sit on LOW and HIGH")
    p.add_argument("--center-runs", type=int, default=3, metavar="N",
                   help="number of centre runs in the sheet (factorial: including the grid's centre; default 3)")
    p.add_argument("--alpha", default=None, metavar="rotatable|face|VALUE",
                   help="CCD axial distance in coded units: rotatable (2^k)^(1/4) (the default), face (1) or a "
                        "number >= 1; only for --type ccd")
    p.add_argument("--seed", type=int, default=0, metavar="S", help="seed of the randomised run order (default 0)")
    p.add_argument("--blocks", type=int, default=1, metavar="B",
                   help="CCD only: run it in B blocks (2: the factorial runs, then the axial runs; centre runs shared "
                        "out), written in a block column and randomised within each block (default 1: no blocks)")
    p.add_argument("--response", action="append", default=[], metavar="NAME",
                   help="an empty response column to fill in after simulating (repeatable)")
    p.add_argument("--material", default="study", help="material key used in the config fragment")
    p.add_argument("--out", required=True, metavar="FILE.csv", help="run sheet to write")
    p.add_argument("--config-out", metavar="FILE.yaml",
                   help="also write the config fragment declaring this design (data path = --out)")
    _force_argument(p)
    p.set_defaults(func=cmd_design)
    p.error = _one_line_error
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

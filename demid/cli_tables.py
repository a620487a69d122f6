"""The command line's own reading of a table (``python -m demid fit|criticize|check-transcription``): the
columns named on the command line, the design given (``--design``, ``--alpha``) or inferred from the table's
geometry, the coding checked against it, and whether the quadratic can be fitted.  The workflow reads its
tables through :class:`~demid.spec.MaterialSpec` instead (demid.data.validate_material)."""

from __future__ import annotations

import sys

from .errors import InputError


def load_table(path: str, factors: list[str], responses: list[str]):
    """The table with the columns named on the command line, read as the workflow reads one (its warnings,
    and a column left out of --factors that looks like one, printed as warnings)."""
    from .config import reserved_column_problem
    from .data import read_table

    if not factors or not responses:
        raise InputError(f"--{'factors' if not factors else 'responses'}: no column named; give the table's "
                         "column names separated by commas")
    both = sorted(set(factors) & set(responses))
    if both:
        raise InputError(f"'{both[0]}' is given both as a factor and as a response")
    reserved = reserved_column_problem([*factors, *responses])
    if reserved:
        raise InputError(reserved)
    table, warnings = read_table(path, factors, responses)
    for w in warnings + _unlisted_factor_warnings(path, table, factors, responses):
        print(f"demid: warning: {w}", file=sys.stderr)
    return table


def _unlisted_factor_warnings(path: str, table, factors: list[str], responses: list[str]) -> list[str]:
    """A column left out of --factors that takes a few levels and differs between runs at one point of the
    listed factors: those runs are fitted as replicates, and lack of fit is judged against its effect."""
    import numpy as np

    from .csv_cells import parse_number, read_raw

    header, rows, _ = read_raw(path)
    known = {"run", "status", "block", *factors, *responses}
    points = [tuple(p) for p in np.round(table[factors].to_numpy(dtype=float), 9)]
    try:  # the table is in run order, the file perhaps not: pair each run with its own row
        row_of = {int(parse_number(r[header.index("run")])): r for r in rows}
        rows = [row_of[int(run)] for run in table["run"]]
    except (ValueError, KeyError, IndexError):
        return []
    out = []
    for j, name in enumerate(header):
        if name in known:
            continue
        try:
            values = np.array([parse_number(r[j]) for r in rows])
        except (ValueError, IndexError):
            continue
        levels = np.unique(values[np.isfinite(values)])
        if not 2 <= len(levels) <= 5 or len(levels) >= len(values) / 2:
            continue  # a response varies from run to run; a factor takes a few levels
        by_point: dict = {}
        for point, v in zip(points, values):
            by_point.setdefault(point, set()).add(v)
        if any(len(vs) > 1 for vs in by_point.values()):
            out.append(f"{path}, column '{name}': {len(levels)} levels that differ between runs at the same point "
                       f"of {', '.join(factors)}, which are fitted as replicates; if '{name}' is a factor, add it "
                       "to --factors")
    return out


def axial_distance(table, factors, alpha, design="ccd"):
    """Axial distance: given; 1 for designs without axial points; for a CCD inferred as
    (max level distance) / (factorial level distance)."""
    import numpy as np

    if alpha is not None:
        if design != "ccd":
            raise InputError(f"--alpha: only a ccd design has an axial distance, not --design {design}; leave "
                             "--alpha out")
        if not np.isfinite(alpha):
            raise InputError(f"--alpha: a CCD's axial distance is a finite number, found {alpha:g}")
        from .numbers import unusable_number

        if unusable_number(alpha):
            raise InputError(f"--alpha: {unusable_number(alpha)}")
        if not alpha >= 1:
            raise InputError(f"--alpha: a CCD's axial distance is at least 1 (1 is face-centred), found {alpha:g}")
        return alpha
    if design != "ccd":
        return 1.0
    from .design_check import infer_coding

    coding = infer_coding(table, factors, {"type": "ccd"}, "table")
    return float(abs(coding.to_coded(table[factors].to_numpy(dtype=float))).max())


def table_design(table, factors, args):
    """The design family and axial distance of ``args``: as given (``--design``; ``--alpha`` alone is a CCD's),
    or inferred from the table's geometry.  Returns (design dict, scalar alpha, note): the note says which design
    was inferred ("" when one was given); the command prints it once it has succeeded, so that an error stays one
    line (that line says "inferred" where the design is at fault)."""
    if args.design is not None or args.alpha is not None:
        design = args.design or "ccd"
        alpha = axial_distance(table, factors, args.alpha, design)
        return {"type": design, "alpha": alpha}, alpha, ""
    from .design_inference import infer_design

    inferred = infer_design(table, factors, args.data)
    note = f"demid: note: {args.data}: design inferred from the table (no --design given): {inferred.describe()}"
    return inferred.design, max(inferred.alpha), note


def design_coding(table, factors, design, alpha, source):
    """The coding of the table's runs, checked once: the declared design's levels (every cell on one of
    them, every run one of its points; run counts are not checked, a table may leave out failed runs), from
    the design's geometry, so a left-out run does not move the centre; a custom design is coded from its
    extremes.  The fit, the rank check and the criticism all use it."""
    from .design_check import check_design, factor_slip_warning
    from .design import Coding

    if design["type"] == "custom":
        x = table[factors].to_numpy(dtype=float)
        return Coding.from_levels(factors, x, alpha if not design.get("inferred") else 1.0)
    coding = check_design(table, factors, design, source, None, counts=False)[0]
    slip = factor_slip_warning(table, factors, design, coding, source)
    if slip:
        print(f"demid: warning: {slip}", file=sys.stderr)
    return coding


def require_quadratic(table, factors, response, coding, source):
    """Refuse a saturated or rank-deficient quadratic: its R² is 1 or arbitrary, its residuals meaningless."""
    import numpy as np

    from .estimability import require_estimable

    coded = coding.to_coded(table[factors].to_numpy(dtype=float))
    require_estimable(coded, np.isfinite(table[response].to_numpy(dtype=float)), None, source, response, factors)

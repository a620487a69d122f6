"""Checking a table against its design: the coding (centre and unit per factor) from the design's
geometry, every run a point of the declared or inferred design, and the point counts.  Every problem is
one ``InputError`` line naming the file, the run and the column (or the config key).  Beside
demid.design_inference, which names the family, and demid.estimability, whether the full quadratic can be
estimated from the usable runs."""

from __future__ import annotations

from itertools import combinations, product

import numpy as np
import pandas as pd

from .design import (Coding, axial_distances, box_behnken_points, ccd_points, classify_points, factor_levels,
                     model_units, rotatable_alpha, snap_to_factor_levels)
from .errors import InputError
from .precision import PRINTED_PLACE, printed_quantum
from .schema import design_with_defaults


def _level_coding(values: np.ndarray, counts: np.ndarray, levels: np.ndarray,
                  tol: float = 0.02, half_place: float = 0.0) -> tuple[float, float] | None:
    """Centre and unit that put the most runs on the nominal ``levels`` (coded units).

    Every pair of distinct values is tried against every pair of levels; ties go to the most
    symmetric placement (lowest and highest level found equally far from the centre), then the narrowest, then
    the one with the fewest runs on axial levels (beyond +-1).  A single
    mistyped cell sits on no level, so it cannot move the coding; no value is privileged by how
    often it occurs (a 3x3 factorial or a CCD with one centre run is coded like any other).  ``half_place``
    (half the column's printed place, where the text is known) widens ``tol`` per level as the check does
    (:func:`_level_tolerance`), so that a coarse print's rounded levels still place the coding.
    """
    best, best_key = None, None
    for i, j in combinations(range(len(values)), 2):
        for a, b in combinations(range(len(levels)), 2):
            unit = (values[j] - values[i]) / (levels[b] - levels[a])
            centre = values[i] - unit * levels[a]
            coded = (values - centre) / unit
            nearest = np.abs(coded[:, None] - levels[None, :]).argmin(axis=1)
            level_tol = _print_tolerance(tol, half_place, unit, levels)
            on = np.abs(coded - levels[nearest]) <= level_tol[nearest]
            # Then the narrowest placement: three values of a CCD factor are its factorial levels and the
            # centre (a CCD has no factor without factorial points), not its axial levels.  Last, the fewest
            # runs on axial levels: at alpha = 2 a CCD without its low axial run leaves four evenly spaced
            # values (-1, 0, 1, 2) that also read as -2, -1, 0, 1; its axial level is the one a single run
            # holds, not the factorial level or the centre.
            # Symmetry and width are read off the nominal levels the runs are placed on, not off the coded
            # values: those carry the print's and the float's round-off divided by the unit (1e-6 coded for a
            # factor about 1e5 units from zero with a unit of 1), which would break a tie at random.
            placed = levels[nearest][on]
            axial = on & (np.abs(levels[nearest]) > 1 + 1e-9)
            key = (int(counts[on].sum()), -abs(placed.max() + placed.min()), int(on.sum()),
                   -float(np.abs(placed).max()), -int(counts[axial].sum()))
            if best_key is None or key > best_key:
                best_key, best = key, (on, levels[nearest])
    if best is None:
        return None
    on, assigned = best
    vals, lev = values[on], assigned[on]
    # Exact printed values where the design has them: the centre run, the +-1 pair.
    centre = vals[lev == 0][0] if np.any(lev == 0) else None
    if np.any(lev == 1) and np.any(lev == -1):
        unit = (vals[lev == 1][0] - vals[lev == -1][0]) / 2.0
        centre = centre if centre is not None else (vals[lev == 1][0] + vals[lev == -1][0]) / 2.0
    else:
        unit, fitted_centre = np.polyfit(lev, vals, 1)
        centre = centre if centre is not None else fitted_centre
    return float(centre), float(unit)


def infer_coding(table: pd.DataFrame, factors: list[str], design: dict, src: str,
                 log_factors=()) -> Coding:
    """Centre and unit per factor from the design's geometry: the placement of the declared design's
    nominal levels that puts the most runs on a level (see :func:`_level_coding`)."""
    design = design_with_defaults(design)
    dtype = design["type"]
    alpha = axial_distances(design["alpha"], len(factors))
    z = model_units(table[factors].to_numpy(), factors, log_factors)
    if dtype == "custom":
        return Coding.from_levels(factors, z, alpha)
    levels = factor_levels(dtype, alpha, len(factors))
    centers, units = [], []
    for i, f in enumerate(factors):
        values, counts = np.unique(_round_to_scale(z[:, i], 11), return_counts=True)
        half_place = 0.0 if f in log_factors else 0.5 * _text_place(table, f)
        found = _level_coding(values, counts, levels[i], half_place=half_place)
        if found is None:  # one value: no pair of values to place on the levels
            raise InputError(f"the factor takes the single value {values[0]:g} in every run; a {dtype} design "
                             "varies each factor over at least two levels", source=src, column=f)
        centers.append(found[0])
        units.append(found[1])
    return Coding(tuple(factors), tuple(centers), tuple(units))


def _round_to_scale(x: np.ndarray, digits: int) -> np.ndarray:
    """x rounded to ``digits`` decimals below its largest magnitude's leading digit (12 decimals for values
    about 0.5 at digits 11): printed levels that differ only by round-off merge, whatever the factor's
    units (a Hamaker constant of 1e-20 J as much as a friction coefficient)."""
    scale = float(np.max(np.abs(x))) if x.size else 0.0
    if not np.isfinite(scale) or scale == 0.0:
        return x
    quantum = 10.0 ** (np.floor(np.log10(scale)) - digits)
    return np.round(x / quantum) * quantum


def _ccd_alpha_of_table(table: pd.DataFrame, factors: list[str], log_factors=()) -> float | None:
    """The axial distance the runs themselves show, when every factor has the five (or three) levels of
    a CCD, symmetric about the centre, with one ratio of axial to factorial half-range; else None."""
    z = model_units(table[factors].to_numpy(), factors, log_factors)
    ratios = []
    off_centre = np.zeros(z.shape, dtype=bool)
    for i in range(len(factors)):
        values = np.unique(_round_to_scale(z[:, i], 8))
        if len(values) not in (3, 5):
            return None
        spread = values[-1] - values[0]
        centre = values[len(values) // 2]
        if not spread > 0 or abs(values[0] + values[-1] - 2 * centre) > 1e-3 * spread:
            return None
        inner = values[3] - values[1] if len(values) == 5 else spread
        ratios.append(spread / inner)
        off_centre[:, i] = np.abs(z[:, i] - centre) > 1e-3 * spread
    if max(ratios) - min(ratios) > 1e-3 * max(ratios):
        return None
    # Three levels per factor without a run off the centre in one factor alone are a two-level factorial
    # with centre runs, not a face-centred CCD: no alpha would make them a CCD.
    if not np.any(off_centre.sum(axis=1) == 1):
        return None
    return float(np.mean(ratios))


def check_design(table: pd.DataFrame, factors: list[str], design: dict, src: str, config_key: str | None,
                 log_factors=(), level_tol: float = 0.02, counts: bool = True) -> tuple[Coding, np.ndarray]:
    """Check that factor values sit on the declared design's levels, every run is a point of the design
    and (``counts``) the point counts match.  ``config_key`` None: the design came from the command line."""
    design = design_with_defaults(design)
    args = (table, factors, design, src, config_key, log_factors, level_tol, counts)
    try:
        return _check_design(*args)
    except InputError as error:
        if design.get("inferred"):
            raise  # nothing was declared: the inferred design's own refusal is the line to show
        _refuse_wrong_scale(*args)
        shown = _ccd_alpha_of_table(table, factors, log_factors) if design["type"] == "ccd" else None
        declared = float(design["alpha"])
        # A wrong design.alpha puts every axial run off its level: name the key, not the first such cell.
        # Counts are not required of the probe: a wrong centre-run count is said once alpha is right.
        # Printed (rounded) levels blur the design's own value (1.41432 from 4 decimals, 1.42857 from 2):
        # the rotatable alpha is told when the runs sit on its levels too.
        if shown is not None:
            rotatable = round(rotatable_alpha(len(factors)), 5)
            shown = next((a for a in (rotatable, shown) if abs(a - shown) <= 0.05 * shown and _passes(
                table, factors, {**design, "alpha": a}, src, config_key, log_factors, level_tol, False)), None)
        if shown is None or abs(shown - declared) <= 1e-3 * shown:
            raise error
    geometry = ("the axial runs sit on the faces, at the factorial levels" if abs(shown - 1) < 1e-3 else
                f"in every factor the axial levels lie {shown:.6g} times as far from the centre as the factorial ones")
    key, fix = ((f"config key {config_key}.design.alpha", f"set design.alpha: {shown:.6g}") if config_key else
                ("--alpha", f"pass --alpha {shown:.6g}"))
    raise InputError(f"{key}: the runs form a CCD with alpha = {shown:.6g} ({geometry}), not the declared "
                     f"{declared:g}; {fix}", source=src)


def _refuse_wrong_scale(table, factors, design, src, config_key, log_factors, level_tol, counts) -> None:
    """A factor whose levels are evenly spaced on the other scale (log10 when declared linear, linear when
    declared log) puts its runs off every level: name its scale key, not the first such cell."""
    for f in factors:
        values = table[f].to_numpy(dtype=float)
        if f in log_factors:
            flipped, scale = tuple(g for g in log_factors if g != f), "linear"
        elif np.all(values > 0):
            flipped, scale = (*log_factors, f), "log"
        else:
            continue
        if _passes(table, factors, design, src, config_key, flipped, level_tol, False):
            where = f"config key {config_key}.factors.{f}.scale" if config_key else f"factor '{f}'"
            fix = (f"set scale: {scale}" if scale == "log" else "remove scale: log") if config_key else \
                "fit it in log10 units" if scale == "log" else "fit it in its own units"
            raise InputError(f"{where}: the levels of {f} are evenly spaced on a {scale} scale, not the declared "
                             f"{'log' if scale == 'linear' else 'linear'} one; {fix}", source=src)


def _said(design: dict) -> str:
    """How the design came to be checked against: declared (config, --design) or inferred from the table."""
    return "inferred" if design.get("inferred") else "declared"


def _text_place(table: pd.DataFrame, column: str) -> float:
    """The place of the finest digit the column prints, as read from the table's text (0: not read from text)."""
    return float(table.attrs.get(PRINTED_PLACE, {}).get(column, 0.0))


def _print_tolerance(level_tol: float, half_place: float, unit: float, levels: np.ndarray) -> np.ndarray:
    """Per nominal level, the coded distance a print's rounding allows: the coding is read from printed values
    too (the centre run, the factorial pair), so half a printed place moves the value, the centre and, times
    the level's distance from the centre, the unit."""
    levels = np.abs(np.asarray(levels, dtype=float))
    if not half_place or not unit:
        return np.full(levels.shape, level_tol)
    return np.maximum(level_tol, half_place / abs(unit) * (2.0 + levels))


def _level_tolerance(table: pd.DataFrame, column: str, unit: float, level_tol: float, log_scale: bool,
                     levels: np.ndarray) -> np.ndarray:
    """Per nominal level, the coded distance within which a value of one factor reads as that level: ``level_tol``
    of the factor's coded unit, or what the print's rounding allows where it rounded more than that (a CCD's
    axial level 0.851 printed as 0.85).  Read from the text where the table was (:func:`_print_tolerance`);
    otherwise half the last digit the values show, a float having lost its trailing zeros.  Log-scale factors
    keep ``level_tol``: their print is in other units."""
    if log_scale or not unit:
        return np.full(np.shape(levels), level_tol)
    place = _text_place(table, column)
    if place:
        return _print_tolerance(level_tol, 0.5 * place, unit, levels)
    quantum = printed_quantum(table[column].to_numpy(dtype=float))
    return np.full(np.shape(levels), max(level_tol, 0.5 * float(np.max(quantum, initial=0.0)) / abs(unit)))


def _passes(*args) -> bool:
    try:
        _check_design(*args)
    except InputError:
        return False
    return True


def _check_design(table: pd.DataFrame, factors: list[str], design: dict, src: str, config_key: str | None,
                  log_factors=(), level_tol: float = 0.02, counts: bool = True) -> tuple[Coding, np.ndarray]:
    dtype = design["type"]
    k = len(factors)
    alpha = axial_distances(design["alpha"], k)
    coding = infer_coding(table, factors, design, src, log_factors)
    z = model_units(table[factors].to_numpy(), factors, log_factors)
    coded = coding.to_coded(z)
    if dtype == "custom":
        return coding, np.array(["other"] * len(table))
    levels_of = factor_levels(dtype, alpha, k)
    for i, f in enumerate(factors):
        levels = levels_of[i]
        tolerance = _level_tolerance(table, f, coding.unit[i], level_tol, f in log_factors, levels)
        for r, c in zip(table["run"], coded[:, i]):
            dist = np.abs(levels - c)
            if not np.any(dist <= tolerance):
                nearest = levels[np.argmin(dist)]
                near_actual = coding.to_actual(np.where(np.arange(len(factors)) == i, nearest, 0.0))[i]
                if f in log_factors:
                    near_actual = 10 ** near_actual
                printed = table[f].to_numpy(dtype=float)[np.abs(coded[:, i] - nearest) <= level_tol]
                near_actual = printed[0] if printed.size else near_actual  # as the other runs print it
                found = table.loc[table["run"] == r, f].iloc[0]
                raise InputError(f"value {found:g} is not a level of the {_said(design)} {dtype} design "
                                 f"(coded {c:+.3f}); nearest valid level: {near_actual:.6g} (coded {nearest:+.4g})",
                                 source=src, run=int(r), column=f)
    snapped = snap_to_factor_levels(coded, levels_of)
    types = classify_points(snapped, alpha)
    _refuse_misplaced_points(table, factors, design, snapped, types, levels_of, coding, log_factors, src)
    if not counts:
        return coding, types
    if dtype == "ccd":
        expected = {"factorial": 2 ** k, "axial": 2 * k,
                    "center": int(design["center_runs"])}
        found = {t: int(np.sum(types == t)) for t in expected}
        if found["axial"] == 0:
            raise InputError(f"config key {config_key}.design: the table has no axial runs: its runs are a two-level "
                             f"factorial with {found['center']} centre run(s), on which the squared terms of the "
                             f"quadratic cannot be estimated; add the {2 * k} axial runs of a CCD, or run the 3^{k} "
                             f"factorial (design type factorial)", source=src)
        for t, n in expected.items():
            if found[t] > n and found[t] % n == 0 and t != "center":
                raise InputError(f"config key {config_key}.design: the table has {found[t]} {_POINT_WORDS[t]} runs "
                                 f"where a {k}-factor CCD has {n}: replicated points? A replicated design is not a "
                                 "plain ccd; declare design type custom to fit it as it is", source=src)
        _refuse_missing_or_repeated_points(table, factors, design, snapped, coding, log_factors, src)
        for t, n in expected.items():
            if found[t] != n:
                key, what = (("design.center_runs", "") if t == "center" else
                             ("design", f" with {_n_center_text(design)}"))
                raise InputError(f"config key {config_key}.{key}: expected {n} {_POINT_WORDS[t]} run(s) for a "
                                 f"{k}-factor CCD{what}, found {found[t]} ({len(table)} runs in the table)", source=src)
    elif dtype == "factorial":
        _refuse_incomplete_factorial(factors, snapped, config_key, src)
        n_center = int(np.sum(types == "center"))
        _refuse_centre_count(n_center, design, config_key, src)
    elif dtype == "box_behnken":
        n_edge, n_center = int(np.sum(types == "edge")), int(np.sum(types == "center"))
        edges = _expected_counts(design, k)["edge"]
        if n_edge > edges and n_edge % edges == 0:
            raise InputError(f"config key {config_key}.design: the table has {n_edge} edge-midpoint runs where a "
                             f"{k}-factor Box-Behnken design has {edges}: replicated points? A replicated "
                             "design is not a plain box_behnken; declare design type custom to fit it as it is",
                             source=src)
        _refuse_missing_or_repeated_points(table, factors, design, snapped, coding, log_factors, src)
        _refuse_centre_count(n_center, design, config_key, src)
    return coding, types


def _design_points(design: dict, k: int) -> np.ndarray:
    """The coded non-centre points of a CCD or Box-Behnken design, each once."""
    if design["type"] == "ccd":
        return ccd_points(k, axial_distances(design["alpha"], k), center_runs=0)
    return box_behnken_points(k, 0)


def _refuse_missing_or_repeated_points(table, factors, design, snapped, coding, log_factors, src,
                                       slips_only: bool = False) -> None:
    """Each factorial, axial or edge point of a CCD or Box-Behnken design is run once.  A run on another run's
    point with the design's point beside it empty is a factor value typed as another level (15 typed 5): the
    point counts still match, and the two runs would be fitted as replicates.  Name both runs, the empty point
    and, where one factor tells them apart, the column and the value that restores the design.  With
    ``slips_only`` (a table whose failed runs may be left out) only that slip is refused."""
    k = len(factors)
    key = [tuple(np.round(p, 6)) for p in snapped]
    expected = [tuple(np.round(p, 6)) for p in _design_points(design, k)]
    rows_at = {p: [i for i, q in enumerate(key) if q == p] for p in expected}
    missing = [p for p in expected if not rows_at[p]]
    repeated = [p for p in expected if len(rows_at[p]) > 1]
    if not missing and not repeated:
        return
    runs = table["run"].to_numpy()

    def shown(point) -> str:
        return ", ".join(f"{f} {_printed_level(table, f, j, snapped, point[j], coding, log_factors):.6g}"
                         for j, f in enumerate(factors))

    name = {"ccd": "CCD", "box_behnken": "Box-Behnken design"}[design["type"]]

    def runs_at(point) -> tuple[list[int], str]:
        at = [int(runs[i]) for i in rows_at[point]]
        return at, (f"{'both' if len(at) == 2 else f'all {len(at)}'} are the point ({shown(point)}), which a {name} "
                    "runs once")

    # A slip moves one run: each repeat (a pair) has an empty point beside it.  More repeats than empty points,
    # or a point run three times, is a replicated design, not a slip.
    slip_like = len(repeated) <= len(missing) and (len(repeated) == 1 or not slips_only)
    for point in repeated if slip_like else []:
        near = [p for p in missing if sum(a != b for a, b in zip(p, point)) == 1]
        if len(near) == 1 and len(rows_at[point]) == 2:
            j = next(j for j in range(k) if near[0][j] != point[j])
            value = _printed_level(table, factors[j], j, snapped, near[0][j], coding, log_factors)
            at, what = runs_at(point)
            raise InputError(f"{what}, and the design's point ({shown(near[0])}) has no run: in one of them "
                             f"{factors[j]} is likely {value:.6g}, typed as another level", source=src, run=at,
                             column=factors[j])
    if slips_only:
        return
    if repeated:
        at, what = runs_at(repeated[0])
        tail = (f"; the design's point ({shown(missing[0])})" + (f" and {len(missing) - 1} more" if len(missing) > 1
                else "") + " has no run" if missing else
                "; a replicated point makes it another design: declare design type custom to fit it as it is")
        raise InputError(f"{what}{tail}", source=src, run=at)
    more = f" and {len(missing) - 1} more" if len(missing) > 1 else ""
    raise InputError(f"the {name}'s point ({shown(missing[0])}){more} has no run ({len(table)} runs in the table); "
                     "keep a failed run in the table with status failed, or declare design type custom to fit the "
                     "runs as they are", source=src)


def factor_slip_warning(table: pd.DataFrame, factors: list[str], design: dict, coding: Coding, src: str,
                        log_factors=()) -> str | None:
    """Where runs may be left out of a table (the command line), two runs on one point beside an empty point
    are a factor value typed as another level — or a replicated point beside a run left out, which the table
    cannot tell apart: a warning, not an error."""
    design = design_with_defaults(design)
    if design["type"] not in _DESIGN_POINTS:
        return None
    levels = factor_levels(design["type"], design["alpha"], len(factors))
    coded = coding.to_coded(model_units(table[factors].to_numpy(dtype=float), factors, log_factors))
    snapped = snap_to_factor_levels(coded, levels)
    try:
        _refuse_missing_or_repeated_points(table, factors, design, snapped, coding, log_factors, src,
                                           slips_only=True)
    except InputError as slip:
        return f"{slip} (or a replicated point beside a run left out of the table)"
    return None


def _printed_level(table, f, j, snapped, level, coding, log_factors) -> float:
    """A coded level of factor ``f`` in its units, as the runs at that level print it."""
    printed = table[f].to_numpy(dtype=float)[np.isclose(snapped[:, j], level)]
    if printed.size:
        return float(printed[0])
    point = np.zeros(snapped.shape[1])
    point[j] = level
    value = coding.to_actual(point)[j]
    # the level an axial run alone holds, from an alpha printed to 5 decimals: 5 digits are all it knows
    return float(f"{10 ** value if f in log_factors else value:.5g}")


def _refuse_centre_count(n_center: int, design: dict, config_key: str, src: str) -> None:
    """A factorial's or Box-Behnken design's centre runs against ``design.center_runs``."""
    if n_center != int(design["center_runs"]):
        raise InputError(f"config key {config_key}.design.center_runs: expected {_n_center_text(design)}, "
                         f"found {n_center}", source=src)


def _n_center_text(design: dict) -> str:
    # the count as a whole number: center_runs: 3.0 passes the schema's integer type
    n = int(design["center_runs"])
    return f"{n} centre run{'s' if n != 1 else ''}"


def _refuse_incomplete_factorial(factors: list[str], snapped: np.ndarray, config_key: str, src: str) -> None:
    """A 3^k factorial has every combination of the three levels.  Runs on a subset of them are another
    design: a Box-Behnken design (the edge midpoints) is named; a two-level factorial with centre runs is
    left to the rank check, which says why its squares cannot be fitted."""
    k = len(factors)
    present = {tuple(p) for p in np.round(snapped).astype(int).tolist() if any(p)}
    full = {p for p in product((-1, 0, 1), repeat=k) if any(p)}
    missing = sorted(full - present)
    if not missing or all(0 not in p for p in present):
        return
    edges = {p for p in full if sum(v != 0 for v in p) == 2}
    if present == edges:
        raise InputError(f"config key {config_key}.design.type: the runs are the edge midpoints of a Box-Behnken "
                         f"design (two factors at their extremes, the others at the centre), not the 3^{k} "
                         f"factorial; set design type: box_behnken", source=src)
    example = ", ".join(f"{f}={v:+d}" for f, v in zip(factors, missing[0]))
    raise InputError(f"config key {config_key}.design: a 3^{k} factorial has {len(full)} non-centre points, the "
                     f"table has {len(present)}; missing {len(missing)}, e.g. the point ({example}) in coded "
                     f"units. Keep a failed run in the table with status failed, or declare the design that was "
                     f"run (design type custom fits any runs)", source=src)


_DESIGN_POINTS = {"ccd": ("factorial", "axial", "center"), "box_behnken": ("edge", "center")}
_POINT_WORDS = {"factorial": "factorial", "axial": "axial", "center": "centre", "edge": "edge-midpoint"}


def _expected_counts(design: dict, k: int) -> dict[str, int]:
    centre = int(design["center_runs"])
    if design["type"] == "ccd":
        return {"factorial": 2 ** k, "axial": 2 * k, "center": centre}
    return {"edge": 2 * k * (k - 1), "center": centre}


def _refuse_misplaced_points(table, factors, design, snapped, types, levels, coding, log_factors, src) -> None:
    """A run whose factor levels make no point of the declared design (a centre run with one factor at a
    factorial level): one line naming the run and, where exactly one factor value would restore a point
    the design is short of, that column and value (another run's level typed by mistake)."""
    allowed = _DESIGN_POINTS.get(design["type"])
    if allowed is None:
        return
    bad = np.flatnonzero(~np.isin(types, allowed))
    if not len(bad):
        return
    i = int(bad[0])
    counts = {t: int(np.sum(types == t)) for t in allowed}
    short = {t for t, n in _expected_counts(design, len(factors)).items() if counts.get(t, 0) < n}
    alpha = axial_distances(design["alpha"], len(factors))
    repairs = []
    for j, f in enumerate(factors):
        for level in levels[j]:
            point = snapped[i].copy()
            point[j] = level
            kind = classify_points(point[None, :], alpha)[0]
            # a factorial, axial or edge point appears once in the design: one already present is no repair
            present = kind != "center" and np.any(np.all(np.isclose(np.delete(snapped, i, axis=0), point), axis=1))
            if level != snapped[i, j] and kind in short and not present:
                value = coding.to_actual(point)[j]
                repairs.append((f, 10 ** value if f in log_factors else value, kind))
    where = ", ".join(f"{f} {table[f].iloc[i]:g}" for f in factors)
    names = [_POINT_WORDS[t] for t in allowed]
    article = "an" if names[0][0] in "aeiou" else "a"
    what = (f"the point ({where}) is not {article} {', '.join(names[:-1])} or {names[-1]} point of the {_said(design)} "
            f"{design['type']} design")
    run = int(table["run"].iloc[i])
    if len(repairs) == 1:
        f, value, kind = repairs[0]
        raise InputError(f"{what}; with {f} = {value:.6g} it would be the {_POINT_WORDS[kind]} run the "
                         "design is short of (another run's level typed by mistake?)", source=src, run=run, column=f)
    raise InputError(what, source=src, run=run)


def odd_level_values(table: pd.DataFrame, factors: list[str], snapped: np.ndarray, src: str) -> list[str]:
    """A factor value that differs from the value the other runs at its level have (0.5003 where four others
    read 0.5): close enough to be the level, so it is fitted as recorded, but likely a typo.  A level with one
    run (an axial point) has nothing to compare with."""
    out = []
    for j, f in enumerate(factors):
        values = table[f].to_numpy(dtype=float)
        for level in np.unique(snapped[:, j]):
            rows = np.flatnonzero(snapped[:, j] == level)
            distinct, counts = np.unique(values[rows], return_counts=True)
            if len(distinct) < 2 or counts.max() < 2 or (counts == counts.max()).sum() > 1:
                continue
            usual = distinct[np.argmax(counts)]
            for i in rows[values[rows] != usual]:
                out.append(f"{src}, run {int(table['run'].iloc[i])}, column '{f}': {values[i]:.10g}, where the other "
                           f"{int(counts.max())} runs at this level read {usual:.10g} (fitted as recorded; a typo?)")
    return out

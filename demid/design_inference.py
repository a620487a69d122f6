"""The design family a table's geometry shows, for tables that come without a declared design.

A CCD (one axial distance per factor: levels rounded to practical values give 1.404 for one factor and
1.429 for another), a Box-Behnken design, the 3^k full factorial, a two-level factorial with centre runs,
or, when the runs are none of these, a custom design.  The inferred design is then checked like a declared
one (:func:`demid.data.check_design`), so a CCD with a run off its points is still refused, and every
message says "inferred", never "declared".
"""

from __future__ import annotations

from dataclasses import dataclass
from itertools import product

import numpy as np
import pandas as pd

from .design import LEVEL_TOLERANCE, model_units
from .errors import InputError
from .precision import printed_quantum

#: Distinct values of a factor closer than this share of its range are one level printed two ways.
_SAME_LEVEL = 0.005

_NAMES = {"ccd": "central composite design (CCD)", "box_behnken": "Box-Behnken design",
          "factorial": "full factorial", "two_level": "two-level factorial", "custom": "custom design"}


@dataclass(frozen=True)
class InferredDesign:
    """The family, one axial distance per factor (1 where a family has none) and the centre runs."""

    family: str  # ccd, box_behnken, factorial, two_level or custom
    factors: tuple[str, ...]
    alpha: tuple[float, ...]
    center_runs: int

    @property
    def design(self) -> dict:
        """The design to check the table against, marked inferred for the messages.  A two-level factorial
        is checked as custom (coded from each factor's extremes, which are its +-1 levels): it has no
        structure of its own to hold the runs to."""
        dtype = "custom" if self.family == "two_level" else self.family
        return {"type": dtype, "alpha": self.alpha, "center_runs": self.center_runs, "inferred": True}

    def describe(self) -> str:
        k = len(self.factors)
        centre = f"{self.center_runs} centre run{'s' if self.center_runs != 1 else ''}"
        if self.family == "ccd":
            if max(self.alpha) - min(self.alpha) <= 1e-3 * max(self.alpha):
                axial = ("face-centred, alpha = 1" if abs(self.alpha[0] - 1) < 1e-3 else
                         f"axial distance alpha = {np.mean(self.alpha):.6g}")
            else:
                axial = "axial distance " + ", ".join(f"{a:.4g} for {f}" for f, a in zip(self.factors, self.alpha))
            return f"a {k}-factor {_NAMES['ccd']}, {axial}, {centre}"
        if self.family == "factorial":
            return f"a 3^{k} {_NAMES['factorial']}, {centre}"
        if self.family == "custom":
            return "no standard design (custom: each factor coded from its range)"
        return f"a {k}-factor {_NAMES[self.family]} with {centre}"


def infer_design(table: pd.DataFrame, factors: list[str], src: str, log_factors=()) -> InferredDesign:
    """The design family of the runs' geometry (see the module docstring).  Runs may be missing (a table
    without its failed runs): a family is kept when at most one point in ten of it (at least one) has
    no run.  A CCD whose two axial levels of one factor are not symmetric about its centre is refused."""
    factors = list(factors)
    z = model_units(table[factors].to_numpy(dtype=float), factors, log_factors)
    k = len(factors)
    placements = [_factor_placement(z[:, j], table, factors[j], src, f in log_factors)
                  for j, f in enumerate(factors)]
    if any(p is None for p in placements):
        return InferredDesign("custom", tuple(factors), (1.0,) * k, 0)
    centre = np.array([p[0] for p in placements])
    unit = np.array([p[1] for p in placements])
    alpha = tuple(float(p[2]) for p in placements)
    coded = (z - centre) / unit
    on_centre = np.all(np.abs(coded) <= 0.5, axis=1)
    n_centre = int(on_centre.sum())
    if max(alpha) > 1 + 1e-9:
        return InferredDesign("ccd", tuple(factors), alpha, n_centre)
    points = {tuple(p) for p in np.clip(np.round(coded), -1, 1).astype(int).tolist() if any(p)}
    family = _closest_three_level_family(points, k)
    if family is None:
        return InferredDesign("custom", tuple(factors), (1.0,) * k, 0)
    return InferredDesign(family, tuple(factors), (1.0,) * k, n_centre)


def _factor_placement(column: np.ndarray, table: pd.DataFrame, name: str, src: str,
                      log_scale: bool) -> tuple[float, float, float] | None:
    """(centre, unit, alpha) of one factor whose levels are those of a CCD, Box-Behnken or factorial
    design (three levels evenly spaced, or five symmetric about the centre, or four: a CCD without one of
    its axial runs); None otherwise.  One level held by a single run may be a mistyped cell: the levels
    without it are tried too, and the design check then names that cell."""
    levels, counts = _levels(column)
    tries = [(levels, counts)] + [(np.delete(levels, i), np.delete(counts, i)) for i in np.flatnonzero(counts == 1)]
    for lv, runs in tries:
        found = _placement(lv, runs, column, name, table, src, log_scale)
        if found is not None:
            return found
    return None


def _levels(column: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The factor's levels (values closer than _SAME_LEVEL of its range merged) and their run counts."""
    values = np.sort(column[np.isfinite(column)])
    spread = values[-1] - values[0] if values.size else 0.0
    groups: list[list[float]] = []
    for v in values:
        if groups and v - groups[-1][-1] <= _SAME_LEVEL * spread:
            groups[-1].append(v)
        else:
            groups.append([v])
    levels = np.array([float(np.median(g)) for g in groups])
    return levels, np.array([len(g) for g in groups])


def _placement(levels: np.ndarray, counts: np.ndarray, column: np.ndarray, name: str, table: pd.DataFrame, src: str,
               log_scale: bool) -> tuple[float, float, float] | None:
    """(centre, unit, alpha) of the levels (``counts`` runs each), or None; see :func:`_factor_placement`."""
    n = len(levels)
    if n == 3:
        unit = (levels[2] - levels[0]) / 2
        return (levels[1], unit, 1.0) if _symmetric(levels[0], levels[2], levels[1], unit, column, log_scale) \
            else None
    if n == 5:
        centre, unit = levels[2], (levels[3] - levels[1]) / 2
        if not _symmetric(levels[1], levels[3], centre, unit, column, log_scale):
            return None
        if not _symmetric(levels[0], levels[4], centre, unit, column, log_scale):
            low, high = (centre - levels[0]) / unit, (levels[4] - centre) / unit
            runs = [int(r) for r in table["run"][np.isin(column, (levels[0], levels[4]))]]
            raise InputError(f"the levels of {name} are a CCD's but its axial levels {levels[0]:.6g} and "
                             f"{levels[4]:.6g} lie {low:.4g} and {high:.4g} coded units from the centre "
                             f"{centre:.6g}: one of these axial cells is mistyped (a CCD's axial runs sit at "
                             f"the same distance on both sides)", source=src, run=runs, column=name)
        return centre, unit, (levels[4] - levels[0]) / (levels[3] - levels[1])
    if n == 4:  # a CCD whose axial run on one side was left out (failed)
        found = []
        for inner, axial, axial_runs in ((levels[:3], levels[3], counts[3]), (levels[1:], levels[0], counts[0])):
            unit = (inner[2] - inner[0]) / 2
            if _symmetric(inner[0], inner[2], inner[1], unit, column, log_scale):
                alpha = abs(axial - inner[1]) / unit
                if alpha > 1 + 2 * LEVEL_TOLERANCE:
                    found.append((axial_runs, (inner[1], unit, alpha)))
        # At alpha = 2 four evenly spaced levels read either way (-2, -1, 0, 1: centre 0 without the +2 run, or
        # centre -1 without a -3 run): the axial level is the one a single run holds, not a factorial level.
        if found:
            return min(found, key=lambda item: item[0])[1]
    return None


def _symmetric(low: float, high: float, centre: float, unit: float, column: np.ndarray, log_scale: bool) -> bool:
    """``low`` and ``high`` equally far from ``centre``, within the level tolerance of a coded unit (twice:
    both may be off) or within the printed precision of the column."""
    if not unit > 0:
        return False
    slack = 2 * LEVEL_TOLERANCE * unit
    if not log_scale:
        slack = max(slack, float(np.max(printed_quantum(column), initial=0.0)))
    return abs(low + high - 2 * centre) <= slack


def _closest_three_level_family(points: set, k: int) -> str | None:
    """The family whose non-centre points the runs' points are closest to (points outside it plus points
    of it without a run), the smaller family on a tie; None when even the closest is more than one point
    in ten (at least one) away."""
    full = {p for p in product((-1, 0, 1), repeat=k) if any(p)}
    corners = {p for p in full if 0 not in p}
    families = [("two_level", corners)]
    if k >= 3:
        families.append(("box_behnken", {p for p in full if sum(v != 0 for v in p) == 2}))
        families.append(("ccd", corners | {p for p in full if sum(v != 0 for v in p) == 1}))
    families.append(("factorial", full))
    scored = [(len(points - f) + len(f - points), len(f), name, f) for name, f in families]
    distance, _, name, family = min(scored, key=lambda s: (s[0], s[1]))
    return name if distance <= max(1, len(family) // 10) else None

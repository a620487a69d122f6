"""Identified combinations of one material: per scenario, the strict and the plausible set.

The *strict* set is the admissibility step's (its node mask on the evaluation grid, or its
Sobol points above 3 factors); the *plausible* set is the plausible set of
:mod:`demid.uncertainty.plausible` (``|ŷ − y*| ≤ ε|y*| + z·√(se² + σ²)``, the same z and
measurement σ as the plausible table) on the plausible table's grid.  Both go through the same
:func:`set_combinations`, which takes any set of points: a different plausible set is a
different argument, not different code.

Where a scenario identifies a combination and leaves its complement free, the *next-run
advice* names the other observable whose gradient lies most along the free direction(s) (least
along the identified one): measuring it cuts the band across.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from .axes import (FREE_MIN_WIDTH, IDENTIFIED_MAX_WIDTH, STRAIGHT_MAX_BEND, LocalThickness, PrincipalAxes, band_curve,
                   curve_bend, linear_statement, local_thickness, principal_axes)

if TYPE_CHECKING:
    from ..design import Coding
    from ..sampling.grid import AdmissibleSet
    from ..spec import MaterialSpec

#: Columns of ``tables/combinations.csv`` (the pipeline prepends ``material``).
COMBINATION_COLUMNS = ["scenario", "set", "direction"]  # + one loading column per factor + the two widths
WIDTH_COLUMNS = ["width_coded", "width_fraction_of_range"]
#: A factor takes part in a combination when its loading is at least this large (|cos| of 78°).
LOADING_MIN = 0.2
#: Rows of the band's curve in the JSON and the report.
CURVE_ROWS = 11
#: Below this angle (degrees) between another observable's gradient and the identified direction, it cuts
#: the band only at a shallow angle.
SHALLOW_ANGLE = 30.0
#: At most this many points of a set enter the gradient average of the advice.
ADVICE_POINTS = 2000


def admitted_points(aset: AdmissibleSet, domain) -> tuple[np.ndarray, np.ndarray]:
    """The set's points in search units (log10 for log factors) and the grid step per axis (NaN for
    sample points): grid nodes from the node mask, or the admitted Sobol points."""
    d = domain.dim
    if aset.points is not None:
        return domain.to_search(aset.points[aset.mask]), np.full(d, np.nan)
    if aset.mask.size == 0:
        return np.zeros((0, d)), np.full(d, np.nan)
    n = int(round(aset.mask.size ** (1 / d)))
    index = np.nonzero(aset.mask.reshape((n,) * d))
    axes = domain.search_axes(n)
    lo, hi = domain.search_bounds()
    return np.column_stack([axes[i][index[i]] for i in range(d)]), (hi - lo) / (n - 1)


@dataclass
class SetCombination:
    """The combinations of one set of one scenario."""

    scenario: str
    set: str                      # strict | plausible
    axes: PrincipalAxes | None
    curve: pd.DataFrame | None = None      # 2 factors: coded, along = wide factor
    wide: int | None = None
    narrow: int | None = None
    bend: float = float("nan")
    band_fraction: float = float("nan")   # median local thickness / box extent along the local normal
    band_span: float = float("nan")       # extent of the band along its wide factor / that factor's range
    local: LocalThickness | None = None   # 3+ factors: thickness along the local normal, cell by cell
    cut: str = "none"                     # which end of the box along the narrowest direction the set reaches
    statement: str = ""
    equation: dict = field(default_factory=dict)

    @property
    def identified(self) -> bool:
        """True when the set's narrowest direction is identified (2 factors: the band's local thickness)."""
        if self.axes is None:
            return False
        if np.isfinite(self.band_fraction):
            return self.band_fraction <= IDENTIFIED_MAX_WIDTH
        return bool(self.axes.identified[0])

    @property
    def free(self) -> np.ndarray:
        """Columns: the directions the set leaves (almost) open (a 2-factor band: the direction along it,
        when it spans the wide factor's range; its local tangents are in :meth:`tangents`)."""
        if self.axes is None:
            return np.zeros((0, 0))
        if self.curve is not None and np.isfinite(self.band_span):  # a 2-factor band
            return self.axes.directions[:, 1:] if self.band_span >= FREE_MIN_WIDTH else self.axes.directions[:, :0]
        return self.axes.directions[:, self.axes.free]

    def normals_at(self, points_coded: np.ndarray) -> np.ndarray | None:
        """Unit normal of the set at each point: a 2-factor band's, from the slope of its centre line;
        a curved set's in 3+ factors, that of the nearest cell of :attr:`local` (None otherwise)."""
        if self.curve is not None and len(self.curve) >= 3:
            along = self.curve["along"].to_numpy()
            slope = np.interp(points_coded[:, self.wide], along, np.gradient(self.curve["mid"].to_numpy(), along))
            out = np.zeros_like(points_coded)
            out[:, self.wide], out[:, self.narrow] = -slope, 1.0
            return out / np.linalg.norm(out, axis=1)[:, None]
        if self.local is not None:
            nearest = np.argmin(((points_coded[:, None, :] - self.local.centres[None]) ** 2).sum(axis=2), axis=1)
            return self.local.normals[nearest]
        return None


def set_combinations(points_coded: np.ndarray, lower, upper, factors, *, scenario: str, set_name: str,
                     step=None, weights=None, at_limit=()) -> SetCombination:
    """Principal axes of a set of coded points in the coded box ``[lower, upper]``, and for two
    factors the band's curve, its bend and its local thickness.  ``step``: the grid step per axis
    (coded; None or NaN for sample points); ``weights``: the volume each point stands for (equal when
    None: grid nodes, uniform sample points), used by the principal axes; ``at_limit``: per factor, the
    ends of its range that are physical limits (:func:`~demid.sampling.domain.sides_at_limit`)."""
    axes = principal_axes(points_coded, lower, upper, weights=weights, factors=factors)
    out = SetCombination(scenario, set_name, axes)
    if axes is not None:
        out.cut = _cut_side(points_coded, axes.directions[:, 0], lower, upper, at_limit)
    if axes is not None and len(factors) > 2:
        out.local = local_thickness(points_coded, axes, lower, upper)
        if out.local is not None:
            out.band_fraction = out.local.fraction
    if axes is None or len(factors) != 2:
        return out
    lo, hi = np.asarray(lower, dtype=float), np.asarray(upper, dtype=float)
    spread = (points_coded.max(axis=0) - points_coded.min(axis=0)) / (hi - lo)
    wide = int(np.argmax(spread))
    narrow = 1 - wide
    curve = band_curve(points_coded, wide, narrow)
    grid_step = np.asarray(step if step is not None else [np.nan, np.nan], dtype=float)
    across_step = grid_step[narrow] if np.isfinite(grid_step[narrow]) else 0.0
    out.curve, out.wide, out.narrow = curve, wide, narrow
    if len(curve) >= 3:
        out.bend = curve_bend(curve, axes, wide, narrow, lo, hi, across_step)
        slope = np.gradient(curve["mid"].to_numpy(), curve["along"].to_numpy())
        local = curve["width"].to_numpy() / (np.abs(slope) * (hi[wide] - lo[wide]) + (hi[narrow] - lo[narrow]))
        out.band_fraction = float(np.median(local))
        out.band_span = float((curve["along"].max() - curve["along"].min()) / (hi[wide] - lo[wide]))
    return out


def _cut_side(points: np.ndarray, normal: np.ndarray, lower, upper, at_limit=()) -> str:
    """Which ends of the box, along ``normal``, the set reaches (within :data:`BOUND_TOUCH` of the box's
    extent along it): there the set's width is the search range's, not the data's -- unless every bound that
    makes that end is a physical limit (``at_limit``, per factor), beyond which no value lies."""
    from ..sampling.domain import AT_BOUND, BOUND_TOUCH

    lo, hi = np.asarray(lower, dtype=float), np.asarray(upper, dtype=float)
    box_min = float(np.sum(np.minimum(normal * lo, normal * hi)))
    box_max = float(np.sum(np.maximum(normal * lo, normal * hi)))
    proj = points @ normal
    tol = BOUND_TOUCH * (box_max - box_min) + 1e-12
    low, high = proj.min() <= box_min + tol, proj.max() >= box_max - tol
    if at_limit:
        # the factors whose bounds move that end by more than the touch tolerance
        moving = np.abs(normal) * (hi - lo) > tol
        low = low and not all(("lower" if n > 0 else "upper") in sides
                              for n, sides, m in zip(normal, at_limit, moving) if m)
        high = high and not all(("upper" if n > 0 else "lower") in sides
                                for n, sides, m in zip(normal, at_limit, moving) if m)
    return AT_BOUND[int(low) + 2 * int(high)]


def _curve_rows(curve: pd.DataFrame, rows: int = CURVE_ROWS) -> pd.DataFrame:
    if len(curve) <= rows:
        return curve
    return curve.iloc[np.unique(np.linspace(0, len(curve) - 1, rows).round().astype(int))].reset_index(drop=True)


@dataclass
class MaterialCombinations:
    """Every scenario's combinations (strict and plausible) of one material, with the advice."""

    spec: MaterialSpec
    coding: Coding
    results: list[SetCombination]
    advice: list[str]
    lower: np.ndarray
    upper: np.ndarray
    points: dict = field(default_factory=dict, repr=False)   # (scenario, set) -> coded points (figures)

    def to_frame(self) -> pd.DataFrame:
        """``tables/combinations.csv`` without ``material``: scenario, set, direction, loadings, widths."""
        factors = self.spec.factor_names
        frames = []
        for res in self.results:
            if res.axes is None:
                continue
            frame = res.axes.to_frame()
            frame.insert(0, "set", res.set)
            frame.insert(0, "scenario", res.scenario)
            frames.append(frame)
        columns = COMBINATION_COLUMNS + list(factors) + WIDTH_COLUMNS
        if not frames:
            return pd.DataFrame(columns=columns)
        return pd.concat(frames, ignore_index=True)[columns]

    def _to_actual(self, coded: np.ndarray, i: int) -> np.ndarray:
        value = coded * self.coding.unit[i] + self.coding.center[i]
        return 10.0 ** value if self.spec.factors[i].log else value

    def in_combination(self, set_name: str = "strict") -> dict[str, dict[str, list[str]]]:
        """Per scenario: factor -> the other factors it is identified in combination with (the
        narrowest direction, when identified, with loadings of at least :data:`LOADING_MIN`)."""
        out = {}
        for res in self.results:
            if res.set != set_name or not res.identified or res.cut != "none":
                continue  # a width the search range sets is not the data's
            loads = res.axes.directions[:, 0]
            part = [f for f, v in zip(self.spec.factor_names, loads) if abs(v) >= LOADING_MIN]
            if len(part) >= 2:
                out[res.scenario] = {f: [g for g in part if g != f] for f in part}
        return out

    def sentences(self, res: SetCombination) -> str:
        """The combination of one set in words."""
        spec = self.spec
        labels = [f.label for f in spec.factors]
        if res.axes is None:
            return "no admissible point."
        frac = res.axes.width_fraction
        width = res.band_fraction if np.isfinite(res.band_fraction) else frac[0]
        if not res.identified:
            return (f"no combination is identified: the set is {100 * width:.0f} % of the range wide across its "
                    f"narrowest direction.")
        if res.axes.identified.all():
            return ("every direction is identified (a small region; widths "
                    + ", ".join(f"{100 * v:.1f} %" for v in frac) + f" of the range along its axes): {res.statement}.")
        if res.cut != "none":
            return (f"{res.statement}, but the set reaches the search range's "
                    f"{'both ends' if res.cut == 'both' else res.cut + ' end'} along this direction: its width "
                    f"there is "
                    f"the range's, not the data's (cut by the search range; the next step says whether a wider range is "
                    "advised).")
        free = res.free
        free_text = ("; free along " + ", ".join(_direction_text(free[:, j], labels) for j in range(free.shape[1]))
                     if free.shape[1] and res.curve is None else "; free along the band" if free.shape[1] else "")
        if res.curve is not None and np.isfinite(res.bend) and res.bend > STRAIGHT_MAX_BEND:
            narrow, wide = labels[res.narrow], labels[res.wide]
            return (f"a curved band: {narrow} ≈ f({wide}) along the band, "
                    f"{100 * res.band_fraction:.1f} % of the range thick{free_text}.")
        if res.local is not None and res.axes.width_fraction[0] > 2 * res.band_fraction:
            return (f"a curved set, {100 * res.band_fraction:.1f} % of the range thick along its local normal; "
                    f"the best straight approximation, {res.statement}, is {100 * frac[0]:.0f} % wide{free_text}.")
        return f"{res.statement} ({100 * width:.1f} % of the range along it){free_text}."

    def to_json(self) -> dict:
        out = {"sets": [], "advice": self.advice, "in_combination": self.in_combination(),
               "in_combination_plausible": self.in_combination("plausible"),
               "identified_max_width": IDENTIFIED_MAX_WIDTH, "free_min_width": FREE_MIN_WIDTH}
        for res in self.results:
            entry = {"scenario": res.scenario, "set": res.set, "identified": bool(res.identified), "cut": res.cut,
                     "text": self.sentences(res)}
            if res.axes is not None:
                entry.update(statement=res.statement, **res.equation,
                             width_fraction=[float(v) for v in res.axes.width_fraction],
                             centre_coded=[float(v) for v in res.axes.centre])
            if res.curve is not None and len(res.curve):
                rows = _curve_rows(res.curve)
                entry.update(bend=float(res.bend), band_fraction=float(res.band_fraction),
                             band_span=float(res.band_span),
                             curve={"along": self.spec.factor_names[res.wide],
                                    "across": self.spec.factor_names[res.narrow],
                                    "along_actual": [float(v) for v in
                                                     self._to_actual(rows["along"].to_numpy(), res.wide)],
                                    **{k: [float(v) for v in self._to_actual(rows[k].to_numpy(), res.narrow)]
                                       for k in ("lower", "mid", "upper")}})
            out["sets"].append(entry)
        return out


def _direction_text(vector: np.ndarray, labels: list[str]) -> str:
    text = ""
    for v, lab in zip(vector, labels):
        if abs(v) < 0.005:
            continue
        term = f"{abs(v):.2f}·{lab}"
        text += ("−" + term if v < 0 else term) if not text else f" {'−' if v < 0 else '+'} {term}"
    return "(" + text + ")"


def coded_box(spec: MaterialSpec, coding: Coding) -> tuple[np.ndarray, np.ndarray]:
    lo, hi = spec.domain.search_bounds()
    return coding.to_coded(lo[None, :])[0], coding.to_coded(hi[None, :])[0]


def gradient_coded(surrogate, domain, coding, points_search: np.ndarray) -> np.ndarray:
    """Gradient of a surrogate at points (search units) with respect to the coded factors."""
    unit = np.asarray(coding.unit, dtype=float)
    out = np.empty_like(points_search)
    for i in range(points_search.shape[1]):
        h = 1e-4 * unit[i]
        up, down = points_search.copy(), points_search.copy()
        up[:, i] += h
        down[:, i] -= h
        out[:, i] = (surrogate.predict(domain.to_actual(up)) - surrogate.predict(domain.to_actual(down))) / (2 * h)
    return out * unit


def break_ridge_advice(res: SetCombination, points_search: np.ndarray, surrogates: dict, spec: MaterialSpec,
                       coding: Coding, observables, ranking: pd.DataFrame | None = None) -> str:
    """Which other observable cuts an identified band across: the one whose gradient (coded units,
    averaged over the set's points) lies most along the free directions.  "" when the scenario has
    no identified combination with a free complement, or no other observable."""
    free = res.free
    if not res.identified or res.cut != "none" or free.shape[1] == 0 or len(points_search) == 0:
        return ""
    others = [r for r in spec.response_names if r not in observables and r in surrogates]
    if not others:
        return ""
    pick = np.linspace(0, len(points_search) - 1, min(ADVICE_POINTS, len(points_search))).round().astype(int)
    pts = points_search[np.unique(pick)]
    scores = {}
    for r in others:
        g = gradient_coded(surrogates[r], spec.domain, coding, pts)
        norm = np.linalg.norm(g, axis=1)
        ok = norm > 0
        if not ok.any():
            continue
        normal = res.normals_at(coding.to_coded(pts))
        # the gradient's part along the set (orthogonal to its local normal), or along the free directions
        along = (np.linalg.norm(g - np.sum(g * normal, axis=1)[:, None] * normal, axis=1) if normal is not None
                 else np.linalg.norm(g @ free, axis=1))
        scores[r] = float(np.median(along[ok] / norm[ok]))
    if not scores:
        return ""
    best = max(scores, key=scores.get)
    angle = float(np.degrees(np.arcsin(np.clip(scores[best], 0, 1))))
    label = spec.response_labels.get(best, best)
    scen = next((sc.label for sc in spec.scenarios if sc.name == res.scenario), res.scenario)
    target = spec.targets.get(best)
    gain = ""
    if ranking is not None and len(ranking) and target is not None:
        wanted = frozenset(list(observables) + [best])
        rows = ranking[[frozenset(str(o).split("+")) == wanted for o in ranking["observables"]]]
        if len(rows) and "information_gain_bits" in rows.columns and np.isfinite(rows["information_gain_bits"].iloc[0]):
            gain = f"; with it the ranking gives {float(rows['information_gain_bits'].iloc[0]):.2f} bits"
    if target is not None and any(set(observables) | {best} <= set(sc.observables) for sc in spec.scenarios):
        return ""  # a scenario of the study already adds it: its own set says what it buys, no next step
    measure = "adding its measurement" if target is not None else "measuring it (it has no target yet)"
    rest = ", ".join(f"{spec.response_labels.get(r, r)} {np.degrees(np.arcsin(np.clip(s, 0, 1))):.0f}°"
                     for r, s in scores.items() if r != best)
    return (f"*{scen}* identifies a combination and leaves its complement free: {label} changes most along the set "
            f"(its gradient lies {angle:.0f}° off the identified direction"
            + (f"; {rest}" if rest else "") + f"), so {measure} "
            + ("would break the ridge" if angle >= SHALLOW_ANGLE else
               f"is the best of the others at hand, but it cuts the band at a shallow angle: it shortens the band "
               f"where its curvature differs, and a test that changes along the band would break the ridge")
            + f"{gain}.")


def material_combinations(surrogates: dict, spec: MaterialSpec, coding: Coding, strict: dict[str, AdmissibleSet],
                          plausible: dict[str, AdmissibleSet], ranking: pd.DataFrame | None = None
                          ) -> MaterialCombinations:
    """Combinations of every scenario's strict and plausible set, and the break-the-ridge advice
    (from the plausible set when it has points, else the strict one)."""
    from ..sampling.domain import sides_at_limit

    domain = spec.domain
    lower, upper = coded_box(spec, coding)
    factors = spec.factor_names
    labels = [f.label for f in spec.factors]
    logs = [f.log for f in spec.factors]
    at_limit = [sides_at_limit((f.lower, f.upper), f.limits) for f in spec.factors]
    results, advice, clouds = [], [], {}
    for sc in spec.scenarios:
        searched = {}
        for name, sets in (("strict", strict), ("plausible", plausible)):
            aset = sets.get(sc.name)
            if aset is None:
                continue
            points, step = admitted_points(aset, domain)
            coded = coding.to_coded(points) if len(points) else points
            res = set_combinations(coded, lower, upper, factors, scenario=sc.name, set_name=name,
                                   step=step / np.asarray(coding.unit), at_limit=at_limit)
            if res.axes is not None:
                a, c, w, text = linear_statement(res.axes.directions[:, 0], res.axes.centre, res.axes.widths[0],
                                                 coding, labels, logs)
                res.statement = text
                res.equation = {"coefficients_search_units": [float(v) for v in a], "constant": c, "half_width": w}
            results.append(res)
            clouds[(sc.name, name)] = coded
            searched[name] = (res, points)
        # the plausible set when it identifies the combination, else the strict one
        use = next((searched[k] for k in ("plausible", "strict") if k in searched and searched[k][0].identified),
                   None)
        if use is not None:
            line = break_ridge_advice(use[0], use[1], surrogates, spec, coding, sc.observables, ranking)
            if line:
                advice.append(line)
    return MaterialCombinations(spec, coding, results, advice, lower, upper, clouds)


def plausible_sets(surrogates: dict, spec: MaterialSpec, *, z: float, n: int,
                   judged: dict | None = None) -> dict[str, AdmissibleSet]:
    """Every scenario's plausible set on an n-grid (n Sobol points above 3 factors), as the plausible table
    evaluates it: its z, each observable's own tolerance and measurement band, σ and discrepancy δ
    (:class:`~demid.scenario.JudgedScenario`; ``judged``: the scenarios already judged at ``z``)."""
    from ..scenario import judged_scenarios

    judged = judged_scenarios(spec, surrogates, z) if judged is None else judged
    return {name: scenario.plausible_set(n) for name, scenario in judged.items()}

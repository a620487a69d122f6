"""What a set of parameter points identifies: its principal axes and, for thin bands, its curve.

A calibration rarely pins each factor alone; it pins a *combination*.  Given any set — a
boolean mask over grid nodes or sample points, or weighted points — in **coded units** (the
design's coding: ±1 = factorial levels, log10 for log-scaled factors), this module gives:

* **Principal axes** (:func:`principal_axes`): the eigenvectors of the set's covariance over
  its volume (each point weighted by the volume it stands for), narrowest first.  Loadings are
  unit length, sign fixed so that the largest loading is positive.  The **width** along an axis
  is ``√12·σ``: the full extent of a uniform slab with the same variance, so a straight band of
  thickness t has width t along its normal, and the width does not hinge on one extreme point.
  ``width_fraction_of_range`` divides it by the box's own extent along that direction
  (``Σ_i |v_i|·range_i``, coded): 1 for a set that fills the box, about 0 for a thin band.
* **The band's curve** (:func:`band_curve`, two factors): for each value of the wide factor,
  the lowest, highest and mid value of the narrow one (exact per grid column); a curved band
  is stated as "γ ≈ f(μ_r) along the band" with this table.
* **A statement in actual units** (:func:`linear_statement`) where the band is straight enough
  (its centre line strays from the straight line by less than a quarter of the band's width):
  ``a_1·s_1 + a_2·s_2 = c ± w`` with ``s`` the factor in search units (log10 for log factors)
  and ``a`` of unit length.

A direction is **identified** when its width is at most :data:`IDENTIFIED_MAX_WIDTH` of the box's
extent along it (the per-factor verdict's threshold), and **free** from
:data:`FREE_MIN_WIDTH` on.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from ..sampling.domain import IDENTIFIED_MAX_WIDTH, UNRESOLVED_MIN_WIDTH

#: The per-factor verdicts' thresholds (:mod:`demid.sampling.domain`): identified up to 10 %, unresolved
#: ("free") from 90 % of the range along the direction, so that "identified in combination" and "identified"
#: mean the same width.
FREE_MIN_WIDTH = UNRESOLVED_MIN_WIDTH
#: A band is stated as a straight combination when its centre line strays from the line by at
#: most this fraction of the band's width.
STRAIGHT_MAX_BEND = 0.25
#: Width of a uniform slab per standard deviation: full width = √12 σ.
UNIFORM_WIDTH_PER_SD = float(np.sqrt(12.0))


@dataclass(frozen=True)
class PrincipalAxes:
    """Principal axes of a set in coded units, narrowest first."""

    factors: tuple[str, ...]
    centre: np.ndarray          # weighted mean, coded
    directions: np.ndarray      # columns, unit length
    widths: np.ndarray          # √12·σ along each direction, coded
    box_extent: np.ndarray      # extent of the coded box along each direction
    n_points: int

    @property
    def width_fraction(self) -> np.ndarray:
        return self.widths / self.box_extent

    @property
    def identified(self) -> np.ndarray:
        return self.width_fraction <= IDENTIFIED_MAX_WIDTH

    @property
    def free(self) -> np.ndarray:
        return self.width_fraction >= FREE_MIN_WIDTH

    def to_frame(self) -> pd.DataFrame:
        """One row per direction: ``direction`` (1 = narrowest), one loading column per factor,
        ``width_coded``, ``width_fraction_of_range``."""
        frame = pd.DataFrame({"direction": np.arange(1, len(self.factors) + 1)})
        for i, f in enumerate(self.factors):
            frame[f] = self.directions[i]
        frame["width_coded"] = self.widths
        frame["width_fraction_of_range"] = self.width_fraction
        return frame


def _orient(vectors: np.ndarray) -> np.ndarray:
    out = vectors.copy()
    for j in range(out.shape[1]):
        if out[np.argmax(np.abs(out[:, j]) - 1e-9 * np.arange(out.shape[0])), j] < 0:
            out[:, j] = -out[:, j]
    return out


def principal_axes(points: np.ndarray, lower, upper, weights=None, factors=None) -> PrincipalAxes | None:
    """Principal axes of the set given by ``points`` (m x d, coded) with ``weights`` (volume per
    point; equal when None) inside the coded box ``[lower, upper]``.  None for an empty set."""
    points = np.asarray(points, dtype=float)
    d = points.shape[1]
    factors = tuple(factors) if factors is not None else tuple(f"x{i + 1}" for i in range(d))
    w = np.ones(len(points)) if weights is None else np.asarray(weights, dtype=float)
    if len(points) == 0 or w.sum() <= 0:
        return None
    w = w / w.sum()
    centre = w @ points
    dev = points - centre
    cov = (dev * w[:, None]).T @ dev
    values, vectors = np.linalg.eigh(cov)  # ascending: narrowest first
    vectors = _orient(vectors)
    widths = UNIFORM_WIDTH_PER_SD * np.sqrt(np.clip(values, 0.0, None))
    ranges = np.asarray(upper, dtype=float) - np.asarray(lower, dtype=float)
    extent = np.abs(vectors).T @ ranges
    return PrincipalAxes(factors, centre, vectors, widths, extent, int(len(points)))


def band_curve(points: np.ndarray, along: int, across: int, max_columns: int = 4096) -> pd.DataFrame:
    """The band's centre line: for each value of coordinate ``along`` (each grid column, or one of
    ``max_columns`` equal bins when the points are not on a grid), the lowest, highest and mid
    value of coordinate ``across`` among the set's points, and the width (highest − lowest)."""
    points = np.asarray(points, dtype=float)
    if len(points) == 0:
        return pd.DataFrame(columns=["along", "lower", "mid", "upper", "width"])
    x, y = points[:, along], points[:, across]
    values, index = np.unique(np.round(x, 12), return_inverse=True)
    if len(values) > max_columns:  # scattered points: bins
        edges = np.linspace(x.min(), x.max(), max_columns + 1)
        index = np.clip(np.searchsorted(edges, x, side="right") - 1, 0, max_columns - 1)
    lo = np.full(index.max() + 1, np.inf)
    hi = np.full(index.max() + 1, -np.inf)
    np.minimum.at(lo, index, y)
    np.maximum.at(hi, index, y)
    pos = np.bincount(index, weights=x) / np.bincount(index)
    keep = np.isfinite(lo)
    frame = pd.DataFrame({"along": pos[keep], "lower": lo[keep], "upper": hi[keep]})
    frame["mid"] = (frame["lower"] + frame["upper"]) / 2
    frame["width"] = frame["upper"] - frame["lower"]
    return frame[["along", "lower", "mid", "upper", "width"]].reset_index(drop=True)


def curve_bend(curve: pd.DataFrame, axes: PrincipalAxes, along: int, across: int, lower, upper,
               step: float) -> float:
    """Largest distance of the band's centre line from the straight line through the set's centre
    along the narrowest direction, as a fraction of the band's width; columns where the band is cut
    by the box (within a grid step of a bound) are left out, their mid-points shift with the cut."""
    normal = axes.directions[:, 0]
    lo, hi = np.asarray(lower, dtype=float), np.asarray(upper, dtype=float)
    clear = (curve["lower"] > lo[across] + 1.5 * step) & (curve["upper"] < hi[across] - 1.5 * step)
    rows = curve[clear] if clear.sum() >= 3 else curve
    if not len(rows) or axes.widths[0] <= 0:
        return float("nan")
    mids = np.zeros((len(rows), len(normal)))
    mids[:, along] = rows["along"].to_numpy()
    mids[:, across] = rows["mid"].to_numpy()
    offset = (mids - axes.centre) @ normal
    return float(np.max(np.abs(offset)) / axes.widths[0])


def linear_statement(normal: np.ndarray, centre: np.ndarray, width: float, coding, labels: list[str],
                     log: list[bool], digits: int = 3) -> tuple[np.ndarray, float, float, str]:
    """The combination ``normal·x = normal·centre ± width/2`` (coded x) in search units
    (x_i = (s_i − centre_i)/unit_i): coefficients ``a`` of unit length with the largest positive,
    the constant c and the half-width w, and the sentence ``μ_r + 1.63·log10 γ = 2.37 ± 0.1`` (the
    same equation divided by the coefficient of the factor that loads most in coded units)."""
    unit = np.asarray(coding.unit, dtype=float)
    mid = np.asarray(coding.center, dtype=float)
    a = normal / unit
    c = float(normal @ centre + np.sum(normal * mid / unit))
    w = width / 2
    scale = float(np.linalg.norm(a))
    if a[np.argmax(np.abs(a))] < 0:
        scale = -scale
    a, c, w = a / scale, c / scale, abs(w / scale)
    # written with the coefficient of the factor that loads most (coded) equal to 1
    lead = float(a[np.argmax(np.abs(normal))])
    shown, c_shown, w_shown = a / lead, c / lead, abs(w / lead)
    terms = []
    order = [int(np.argmax(np.abs(normal)))] + [i for i in range(len(a)) if i != int(np.argmax(np.abs(normal)))]
    for coef, label, lg in ((shown[i], labels[i], log[i]) for i in order):
        if abs(coef) < 0.5 * 10 ** -digits:
            continue
        name = f"log10 {label}" if lg else label
        sign = "−" if coef < 0 else "+"
        terms.append((sign, name if abs(abs(coef) - 1) < 1e-12 else f"{abs(coef):.{digits}g}·{name}"))
    text = ""
    for i, (sign, term) in enumerate(terms):
        text += (("−" if sign == "−" else "") + term) if i == 0 else f" {sign} {term}"
    from ..precision import pm_text

    return a, c, w, f"{text} = {pm_text(c_shown, w_shown)}"  # the constant to the digits its half-width supports


@dataclass(frozen=True)
class LocalThickness:
    """A curved set's thickness cell by cell: the set is cut into cells along its wide principal
    axes, and in each cell the narrowest local axis gives the local normal and width."""

    centres: np.ndarray        # cells x d, coded
    normals: np.ndarray        # cells x d, unit
    widths: np.ndarray         # √12·σ along the local normal, coded
    fractions: np.ndarray      # width / box extent along the local normal
    counts: np.ndarray         # points per cell

    @property
    def fraction(self) -> float:
        """Median local width fraction, each cell weighted by its points (its volume)."""
        order = np.argsort(self.fractions)
        cum = np.cumsum(self.counts[order])
        return float(self.fractions[order][np.searchsorted(cum, cum[-1] / 2)])


#: Cells per wide axis of :func:`local_thickness`, and the fewest points a cell needs.
LOCAL_CELLS = 8
LOCAL_MIN_POINTS = 30


def local_thickness(points: np.ndarray, axes: PrincipalAxes, lower, upper, cells: int = LOCAL_CELLS
                    ) -> LocalThickness | None:
    """Thickness of a thin curved set (a sheet in 3+ factors) along its local normal: cells of equal
    size over the set's extent on principal axes 2..d, a principal-axis analysis in each.  None when
    no cell holds :data:`LOCAL_MIN_POINTS` points."""
    points = np.asarray(points, dtype=float)
    ranges = np.asarray(upper, dtype=float) - np.asarray(lower, dtype=float)
    coords = (points - axes.centre) @ axes.directions[:, 1:]
    lo, hi = coords.min(axis=0), coords.max(axis=0)
    index = np.clip(((coords - lo) / np.where(hi > lo, hi - lo, 1) * cells).astype(int), 0, cells - 1)
    key = np.ravel_multi_index(index.T, (cells,) * index.shape[1])
    order = np.argsort(key, kind="stable")
    starts = np.flatnonzero(np.r_[True, np.diff(key[order]) != 0])
    rows = []
    for part in np.split(order, starts[1:]):
        if len(part) < LOCAL_MIN_POINTS:
            continue
        cell = points[part]
        centre = cell.mean(axis=0)
        values, vectors = np.linalg.eigh(np.cov((cell - centre).T, bias=True))
        normal = vectors[:, 0]
        width = UNIFORM_WIDTH_PER_SD * np.sqrt(max(values[0], 0.0))
        rows.append((centre, normal, width, width / float(np.abs(normal) @ ranges), len(part)))
    if not rows:
        return None
    centres, normals, widths, fractions, counts = (np.array(col) for col in zip(*rows))
    return LocalThickness(centres, normals, widths, fractions, counts)

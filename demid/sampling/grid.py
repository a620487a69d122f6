"""Grid estimator of an admissible set: feasible fraction and spans (up to 3 factors).

The feasible fraction is computed cell by cell on the grid: a cell whose
corner residual intervals (widened by a curvature margin) lie inside the band
counts fully, one whose interval misses the band for some observable counts
zero, and only the cells in between (the set boundary) are resampled on a
finer sub-grid.  This keeps the cost of a uniform grid while resolving thin
sets (ridges, narrow bands) that node counting alone would miss or mis-measure.
:func:`fraction_with_error` adds an error estimate from two resolutions.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from itertools import product
from math import factorial
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from ..formulas import relative_error
from .residuals import _fields, residual_evaluator, relative_residuals

if TYPE_CHECKING:
    from .domain import Domain
    from ..surrogate import Surrogate


def predict_grid(surrogates: dict[str, Surrogate], domain: Domain, n: int) -> pd.DataFrame:
    """Surrogate predictions at every evaluation point (grid node, or Sobol point above 3 factors)."""
    from ..surrogate import predict_all

    points = domain.sample(n)
    frame = pd.DataFrame(points, columns=list(domain.factors), copy=False)  # the points are this frame's own
    for name, values in predict_all(surrogates, points).items():
        frame[name] = values
    return frame


@dataclass
class AdmissibleSet:
    """Result of one scenario: fraction, spans, node mask and the closest approach."""

    observables: tuple[str, ...]
    tolerance: float
    factors: tuple[str, ...]
    fraction: float
    node_fraction: float
    n_nodes: int
    n_admissible_nodes: int
    n_refined_cells: int
    lower: np.ndarray
    upper: np.ndarray
    mask: np.ndarray = field(repr=False)
    cell_fraction: np.ndarray = field(default=None, repr=False)
    best_error: float = np.nan
    best_point: np.ndarray = field(default_factory=lambda: np.array([]))
    evaluations: int = 0
    points: np.ndarray | None = field(default=None, repr=False)  # sample points (Sobol evaluation only)
    fraction_ci: tuple[float, float] | None = None
    fraction_error: float = np.nan     # absolute error estimate of ``fraction`` (exact sets)
    method: str = ""
    exact: object = field(default=None, repr=False)  # the :class:`~demid.sampling.exact.ExactSet`, if exact
    at_bound: tuple[str, ...] = ()  # per factor, the ends of the search range the spans reach (evaluate_set)

    @property
    def empty(self) -> bool:
        return self.fraction == 0 and self.n_admissible_nodes == 0

    @property
    def width(self) -> np.ndarray:
        return self.upper - self.lower

    def to_frame(self) -> pd.DataFrame:
        frame = pd.DataFrame({
            "observables": "+".join(self.observables),
            "tolerance": self.tolerance,
            "feasible_fraction_pct": 100.0 * self.fraction,
            "factor": list(self.factors),
            "lower": self.lower,
            "upper": self.upper,
            "width": self.width,
            "node_fraction_pct": 100.0 * self.node_fraction,
            "n_admissible_nodes": self.n_admissible_nodes,
            "best_max_rel_error": self.best_error,
            "fraction_error_pct": 100.0 * self.fraction_error,
        })
        if self.at_bound:
            frame["at_bound"] = list(self.at_bound)
        return frame


def _corner_views(arr: np.ndarray):
    """Yield the 2**d corner views of every grid cell of an n**d node array."""
    d = arr.ndim
    for offs in product((0, 1), repeat=d):
        yield arr[tuple(slice(o, o + s - 1) for o, s in zip(offs, arr.shape))]


def cell_range(values: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Smallest and largest corner value of every grid cell of a node array.

    The minimum over a cell's 2**d corners is taken one axis at a time (d passes over the grid
    instead of 2**d - 1 over stacked copies): the same numbers, a fraction of the memory traffic.
    """
    lo = hi = values
    for axis in range(values.ndim):
        first = tuple(slice(None, -1) if a == axis else slice(None) for a in range(values.ndim))
        second = tuple(slice(1, None) if a == axis else slice(None) for a in range(values.ndim))
        lo = np.minimum(lo[first], lo[second])
        hi = np.maximum(hi[first], hi[second])
    return lo, hi


def _curvature_margin(values: np.ndarray) -> float:
    """Bound on how far a smooth field can leave its corner range inside a cell (1/8 sum |d2|)."""
    margin = 0.0
    for axis in range(values.ndim):
        if values.shape[axis] >= 3:
            d2 = np.diff(values, n=2, axis=axis)
            margin += float(np.max(np.abs(d2))) / 8.0
    return margin


def _box_cdf(t: np.ndarray, widths: np.ndarray) -> np.ndarray:
    """P(V_1 + ... + V_d <= t) for independent V_i ~ U(0, widths_i); widths shape (d, m).

    Inclusion-exclusion formula for sums of uniforms; widths are floored at 1e-4 of
    their sum so that the alternating sum stays well conditioned (the floor moves the
    distribution by less than 1e-4 of its width).
    """
    d = widths.shape[0]
    total = widths.sum(axis=0)
    w = np.maximum(widths, 1e-4 * total + 1e-300)
    total = w.sum(axis=0)
    t = np.clip(t, 0.0, total)
    acc = np.zeros_like(t)
    for subset in product((0, 1), repeat=d):
        shift = sum(w[i] for i in range(d) if subset[i]) if any(subset) else 0.0
        acc += (-1) ** sum(subset) * np.maximum(t - shift, 0.0) ** d
    return np.clip(acc / (factorial(d) * np.prod(w, axis=0)), 0.0, 1.0)


def plane_band_fraction(center: np.ndarray, increments: np.ndarray, eps: float) -> np.ndarray:
    """Fraction of a box on which ``|center + sum_i a_i u_i| <= eps``, u uniform on [-1/2, 1/2]^d.

    ``increments`` (d, m) are the changes a_i of the linear field across the box along
    each axis.  Exact for linear fields (verified against Monte Carlo in the tests).
    """
    widths = np.abs(increments)
    start = center - widths.sum(axis=0) / 2.0
    flat = widths.sum(axis=0) == 0
    if not flat.any():
        return _box_cdf(eps - start, widths) - _box_cdf(-eps - start, widths)
    # A constant field is inside the band everywhere or nowhere (the CDF formula would give 0/0).
    out = (np.abs(center) <= eps).astype(float)
    sloped = ~flat
    out[sloped] = (_box_cdf(eps - start[sloped], widths[:, sloped])
                   - _box_cdf(-eps - start[sloped], widths[:, sloped]))
    return out


@dataclass
class CellCount:
    cells: np.ndarray
    fraction: float
    evaluations: int
    analytic_cells: int
    sampled_cells: int
    span_lower: np.ndarray  # search units, over admissible sub-sample points (inf when none)
    span_upper: np.ndarray


def cell_count(resid: np.ndarray, eps: float, domain: Domain, step: np.ndarray, evaluate,
                subdivisions: int) -> CellCount:
    """Admissible fraction of the grid's cells, second-order accurate at the set boundary.

    Cells are classified from corner ranges widened by the curvature margin (as in
    :func:`admissible_set`).  A boundary cell in which exactly one observable is active
    and whose corners straddle a band edge is measured analytically from the plane
    through its corners (no new evaluations); cells where several observables are
    active, or where the band may only dip in between the corners, are sub-sampled.
    """
    k, shape = resid.shape[0], resid.shape[1:]
    d = len(shape)
    cells = tuple(m - 1 for m in shape)
    inside = np.ones(cells, dtype=bool)
    outside = np.zeros(cells, dtype=bool)
    n_active = np.zeros(cells, dtype=np.int8)
    which = np.zeros(cells, dtype=np.int16)
    suspicious = np.zeros(cells, dtype=bool)
    for j, r in enumerate(resid):
        lo, hi = cell_range(r)
        m = _curvature_margin(r)
        in_j = (lo - m >= -eps) & (hi + m <= eps)
        out_j = (hi + m < -eps) | (lo - m > eps)
        active = ~in_j & ~out_j
        inside &= in_j
        outside |= out_j
        n_active += active
        which[active] = j
        # The plane through the corners only sees a band edge that the corners straddle: where all
        # corners lie on one side of both edges (the set may only dip in or out between them, e.g. at
        # a vertex in mid-cell), the plane is blind to it and the cell is sub-sampled.
        corners_inside = (lo >= -eps) & (hi <= eps)
        suspicious |= active & ((hi < -eps) | (lo > eps) | corners_inside)
    frac = inside.astype(float)
    candidate = ~inside & ~outside
    analytic = candidate & (n_active == 1) & ~suspicious
    for j in range(k):
        sel = analytic & (which == j)
        if not sel.any():
            continue
        corners = [v[sel] for v in _corner_views(resid[j])]
        offsets = list(product((0, 1), repeat=d))
        center = np.mean(corners, axis=0)
        increments = np.stack([
            np.mean([c for c, o in zip(corners, offsets) if o[i] == 1], axis=0)
            - np.mean([c for c, o in zip(corners, offsets) if o[i] == 0], axis=0)
            for i in range(d)])
        frac[sel] = plane_band_fraction(center, increments, eps)

    sampled = candidate & ~analytic
    idx = np.argwhere(sampled)
    evaluations = 0
    span_lo = np.full(d, np.inf)
    span_hi = np.full(d, -np.inf)
    if len(idx):
        lo_u, _ = domain.search_bounds()
        sub = (np.arange(subdivisions) + 0.5) / subdivisions
        offs = np.column_stack([g.ravel() for g in np.meshgrid(*[sub] * d, indexing="ij")])
        chunk = max(1, 131_072 // len(offs))
        for start in range(0, len(idx), chunk):
            part = idx[start:start + chunk]
            u = (lo_u + (part[:, None, :] + offs[None, :, :]) * step).reshape(-1, d)
            r = evaluate(domain.to_actual(u))
            evaluations += r.size
            ok_flat = np.all(np.abs(r) <= eps, axis=0)
            ok = ok_flat.reshape(len(part), len(offs))
            frac[tuple(part.T)] = ok.mean(axis=1)
            if ok_flat.any():
                span_lo = np.minimum(span_lo, u[ok_flat].min(axis=0))
                span_hi = np.maximum(span_hi, u[ok_flat].max(axis=0))
    return CellCount(frac, float(frac.mean()), evaluations, int(analytic.sum()), int(len(idx)), span_lo, span_hi)


def _refine_span_ends(cell_frac, span_lo, span_hi, lo_u, hi_u, step, domain, evaluate, eps, s):
    """Sub-sample the outermost occupied cell slab on each side of each axis.

    Cells measured by the plane rule hold admissible points between the nodes; where
    such a cell lies beyond the node-based span, the span end is found on an s-point
    sub-grid of that slab (accuracy step/s, as for sampled cells).
    """
    d = cell_frac.ndim
    occupied = np.argwhere(cell_frac > 0)
    if not len(occupied):
        return span_lo, span_hi
    sub = (np.arange(s) + 0.5) / s
    span_lo, span_hi = span_lo.copy(), span_hi.copy()
    for i in range(d):
        for side in (0, 1):
            edge = occupied[:, i].max() if side else occupied[:, i].min()
            cell_lo = lo_u[i] + edge * step[i]
            if side == 0 and (span_lo[i] <= cell_lo + 1e-12 * abs(step[i]) or span_lo[i] <= lo_u[i]):
                continue
            if side == 1 and (span_hi[i] >= cell_lo + step[i] - 1e-12 * abs(step[i]) or span_hi[i] >= hi_u[i]):
                continue
            cells = occupied[occupied[:, i] == edge]
            offs = np.column_stack([g.ravel() for g in np.meshgrid(*[sub] * d, indexing="ij")])
            chunk = max(1, 131_072 // len(offs))
            for start in range(0, len(cells), chunk):
                part = cells[start:start + chunk]
                u = (lo_u + (part[:, None, :] + offs[None, :, :]) * step).reshape(-1, d)
                ok = np.all(np.abs(evaluate(domain.to_actual(u))) <= eps, axis=0)
                if ok.any():
                    span_lo = np.minimum(span_lo, u[ok].min(axis=0))
                    span_hi = np.maximum(span_hi, u[ok].max(axis=0))
    return span_lo, span_hi


def admissible_set(surrogates: dict[str, Surrogate], domain: Domain, observables, targets: dict[str, float],
                   tolerance: float, n: int, grid_predictions: pd.DataFrame | None = None,
                   subdivisions: int | None = None) -> AdmissibleSet:
    """Evaluate eq. (2)-(4) on an n-per-axis grid with boundary-cell refinement."""
    observables = tuple(observables)
    d = domain.dim
    shape = (n,) * d
    if grid_predictions is None:
        grid_predictions = predict_grid({o: surrogates[o] for o in observables}, domain, n)
    preds = {o: grid_predictions[o].to_numpy() for o in observables}
    resid = relative_residuals(preds, targets, observables).reshape((len(observables),) + shape)
    eps = float(tolerance)
    worst = np.max(np.abs(resid), axis=0)
    mask = worst <= eps

    lo_u, hi_u = domain.search_bounds()
    step = (hi_u - lo_u) / (n - 1)

    def evaluate(x):
        return np.stack([relative_error(surrogates[o].predict(x), targets[o]) for o in observables])

    count = cell_count(resid, eps, domain, step, evaluate, subdivisions or (16 if d <= 2 else 4))
    cell_frac = count.cells
    evaluations = n ** d * len(observables) + count.evaluations
    span_lo, span_hi = count.span_lower.copy(), count.span_upper.copy()
    cand_idx = np.argwhere((cell_frac > 0) & (cell_frac < 1))

    axes_u = domain.search_axes(n)
    if mask.any():
        for i in range(d):
            present = np.any(mask, axis=tuple(j for j in range(d) if j != i))
            where = np.flatnonzero(present)
            span_lo[i] = min(span_lo[i], axes_u[i][where[0]])
            span_hi[i] = max(span_hi[i], axes_u[i][where[-1]])
    span_lo, span_hi = _refine_span_ends(cell_frac, span_lo, span_hi, lo_u, hi_u, step, domain, evaluate, eps,
                                         subdivisions or 16)
    if not np.isfinite(span_lo).all() and (cell_frac > 0).any():
        # A band thinner than the grid spacing: no node or sub-point is admissible, but the
        # plane rule measured it; bound the span by the extent of the cells that hold it.
        cells = np.argwhere(cell_frac > 0)
        span_lo = lo_u + cells.min(axis=0) * step
        span_hi = lo_u + (cells.max(axis=0) + 1) * step
    if np.isfinite(span_lo).all():
        lower = domain.to_actual(span_lo)[0]
        upper = domain.to_actual(span_hi)[0]
    else:
        lower = upper = np.full(d, np.nan)

    best = int(np.argmin(worst))
    best_point = domain.to_actual(np.array([ax[i] for ax, i in zip(axes_u, np.unravel_index(best, shape))]))[0]
    return AdmissibleSet(
        observables=observables, tolerance=eps, factors=tuple(domain.factors),
        fraction=float(cell_frac.mean()), node_fraction=float(mask.mean()),
        n_nodes=int(mask.size), n_admissible_nodes=int(mask.sum()), n_refined_cells=int(len(cand_idx)),
        lower=lower, upper=upper, mask=mask.ravel(), cell_fraction=cell_frac, best_error=float(worst.ravel()[best]),
        best_point=best_point, evaluations=int(evaluations),
    )


# =========================================================================== fraction with error
@dataclass(frozen=True)
class FractionEstimate:
    """A feasible fraction with its numerical error (fractions of Omega, not percent).

    ``fraction`` is the cell estimate on the n-grid; ``error`` is its difference to the
    same estimate on the nested (n+1)/2 grid plus the root-sum-square of the cell-level
    differences (conservative: 3-6x the true error on annuli).  When the grid result of
    :func:`admissible_set` is passed as ``reference``, ``grid_fraction`` repeats it and
    ``grid_error = |grid_fraction - fraction| + error`` bounds its error.
    """

    fraction: float
    error: float
    coarse_fraction: float
    n: int
    evaluations: int
    analytic_cells: int
    sampled_cells: int
    grid_fraction: float = np.nan
    grid_error: float = np.nan

    @property
    def relative_error(self) -> float:
        return self.error / self.fraction if self.fraction > 0 else (0.0 if self.error == 0 else np.inf)


def fraction_with_error(surrogates: dict[str, Surrogate], domain: Domain, observables,
                        targets: dict[str, float], tolerance: float, n: int, *, z: float = 0.0,
                        sigma: dict[str, float] | None = None, subdivisions: int | None = None,
                        grid_predictions: pd.DataFrame | None = None,
                        reference: AdmissibleSet | None = None) -> FractionEstimate:
    """Feasible fraction (strict, or plausible when ``z > 0``) with a numerical error estimate.

    Grid nodes give the residual fields; boundary cells are measured by the plane rule of
    :func:`cell_count` (second order, no new evaluations) or sub-sampled.  The error
    compares with the nested (n+1)/2 grid (every second node: no new node evaluations),
    see :class:`FractionEstimate`.  ``n`` is rounded up to odd; ``grid_predictions``, if
    given, must be :func:`predict_grid` on that n.  Verified on annuli and spherical
    shells of exact volume (``benchmarks/admissibility.py``).
    """
    observables = tuple(observables)
    n = int(n) + (1 - int(n) % 2)
    d = domain.dim
    eps = float(tolerance)
    fields = _fields(surrogates, observables, targets, eps, z, sigma)
    if grid_predictions is None or z > 0:
        grid_predictions = predict_grid(fields, domain, n)
    resid = np.stack([relative_error(grid_predictions[o].to_numpy(), targets[o])
                      for o in observables]).reshape((len(observables),) + (n,) * d)
    evaluate = residual_evaluator(fields, observables, targets)
    s = subdivisions or (16 if d <= 2 else 4)
    lo_u, hi_u = domain.search_bounds()
    step = (hi_u - lo_u) / (n - 1)
    fine = cell_count(resid, eps, domain, step, evaluate, s)
    coarse_resid = resid[(slice(None),) + (slice(None, None, 2),) * d]
    coarse = cell_count(coarse_resid, eps, domain, 2 * step, evaluate, s)
    # Cell-level discrepancies between the two grids do not cancel by luck: adding their
    # root-sum-square to the global difference keeps the estimate above the true error
    # (3-6x on annuli) where the global difference alone sometimes fell below it.
    blocks = fine.cells.reshape(tuple(x for m in fine.cells.shape for x in (m // 2, 2)))
    delta = coarse.cells - blocks.mean(axis=tuple(range(1, 2 * d, 2)))
    error = abs(fine.fraction - coarse.fraction) + float(np.sqrt(np.sum(delta ** 2))) / delta.size
    grid_fraction = grid_error = np.nan
    if reference is not None:
        grid_fraction = float(reference.fraction)
        grid_error = abs(grid_fraction - fine.fraction) + error
    return FractionEstimate(
        fraction=fine.fraction, error=error, coarse_fraction=coarse.fraction, n=n,
        evaluations=int(resid.size + fine.evaluations + coarse.evaluations),
        analytic_cells=fine.analytic_cells, sampled_cells=fine.sampled_cells,
        grid_fraction=grid_fraction, grid_error=grid_error)

"""Admissible parameter sets, feasible fractions and spans (eq. 2-4 of the paper).

A point x of the search domain Omega is admissible for the observable set O at
tolerance eps when every relative residual r_k = (y_k(x) - y_k*) / |y_k*|,
k in O, lies in [-eps, eps].

The feasible fraction is computed cell by cell on the grid: a cell whose
corner residual intervals (widened by a curvature margin) lie inside the band
counts fully, one whose interval misses the band for some observable counts
zero, and only the cells in between (the set boundary) are resampled on a
finer sub-grid.  This keeps the cost of a uniform grid while resolving thin
sets (ridges, narrow bands) that node counting alone would miss or mis-measure.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from itertools import product
from math import factorial

import numpy as np
import pandas as pd

from .config import targets as material_targets
from .design import model_units
from .surrogate import Surrogate

#: Up to this many factors Omega is evaluated on a full grid; beyond it on scrambled Sobol points.
MAX_GRID_DIM = 3


@dataclass(frozen=True)
class Domain:
    """The search domain Omega: a box in search units (actual, or log10 for log factors)."""

    factors: tuple[str, ...]
    lower: tuple[float, ...]
    upper: tuple[float, ...]
    log: tuple[bool, ...] = ()

    def __post_init__(self):
        if not self.log:
            object.__setattr__(self, "log", tuple(False for _ in self.factors))

    @classmethod
    def from_config(cls, factors_cfg: dict) -> "Domain":
        names = tuple(factors_cfg)
        return cls(names, tuple(float(factors_cfg[f]["lower"]) for f in names),
                   tuple(float(factors_cfg[f]["upper"]) for f in names),
                   tuple(factors_cfg[f].get("scale", "linear") == "log" for f in names))

    @property
    def dim(self) -> int:
        return len(self.factors)

    def search_bounds(self) -> tuple[np.ndarray, np.ndarray]:
        lo, hi = self.to_search(np.array([self.lower, self.upper]))
        return lo, hi

    def to_actual(self, u: np.ndarray) -> np.ndarray:
        u = np.array(u, dtype=float, copy=True, ndmin=2)
        for i, lg in enumerate(self.log):
            if lg:
                u[:, i] = 10.0 ** u[:, i]
        return u

    def to_search(self, x: np.ndarray) -> np.ndarray:
        return model_units(x, self.factors, [f for f, lg in zip(self.factors, self.log) if lg])

    def search_axes(self, n: int) -> list[np.ndarray]:
        lo, hi = self.search_bounds()
        return [np.linspace(a, b, n) for a, b in zip(lo, hi)]

    def axes(self, n: int) -> list[np.ndarray]:
        """Grid axes in actual units (log-spaced for log factors)."""
        return [10.0 ** ax if lg else ax for ax, lg in zip(self.search_axes(n), self.log)]

    def sobol(self, n: int, seed: int = 0) -> np.ndarray:
        """2**ceil(log2 n) scrambled Sobol points, uniform in search units, returned in actual units."""
        from scipy.stats import qmc

        lo, hi = self.search_bounds()
        m = max(1, int(np.ceil(np.log2(max(n, 2)))))
        return self.to_actual(lo + qmc.Sobol(self.dim, scramble=True, rng=np.random.default_rng(seed))
                              .random_base2(m) * (hi - lo))

    def sample(self, n: int) -> np.ndarray:
        """The evaluation points: the n-per-axis grid up to 3 factors, n Sobol points beyond."""
        return self.grid(n) if self.dim <= MAX_GRID_DIM else self.sobol(n)

    def grid(self, n: int) -> np.ndarray:
        """All grid nodes in actual units, shape (n**d, d), 'ij' (C) order."""
        axes = self.axes(n)
        out = np.empty((n ** self.dim, self.dim))
        for i, ax in enumerate(axes):
            inner = n ** (self.dim - i - 1)
            out[:, i] = np.tile(np.repeat(ax, inner), n ** i)
        return out


def predict_grid(surrogates: dict[str, Surrogate], domain: Domain, n: int) -> pd.DataFrame:
    """Surrogate predictions at every evaluation point (grid node, or Sobol point above 3 factors)."""
    points = domain.sample(n)
    frame = pd.DataFrame(points, columns=list(domain.factors))
    for name, sur in surrogates.items():
        frame[name] = sur.predict(points)
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

    @property
    def empty(self) -> bool:
        return self.fraction == 0 and self.n_admissible_nodes == 0

    @property
    def width(self) -> np.ndarray:
        return self.upper - self.lower

    def to_frame(self) -> pd.DataFrame:
        return pd.DataFrame({
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
        })


def relative_residuals(predictions: dict[str, np.ndarray], targets: dict[str, float],
                       observables) -> np.ndarray:
    """Array (k, n) of (y_k - y_k*) / |y_k*|."""
    return np.stack([(np.asarray(predictions[o], dtype=float) - targets[o]) / abs(targets[o])
                     for o in observables])


def _corner_views(arr: np.ndarray):
    """Yield the 2**d corner views of every grid cell of an n**d node array."""
    d = arr.ndim
    for offs in product((0, 1), repeat=d):
        yield arr[tuple(slice(o, o + s - 1) for o, s in zip(offs, arr.shape))]


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
        views = list(_corner_views(r))
        lo = np.minimum.reduce(views)
        hi = np.maximum.reduce(views)
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
        return np.stack([(surrogates[o].predict(x) - targets[o]) / abs(targets[o]) for o in observables])

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


def sobol_admissible_set(surrogates: dict[str, Surrogate], domain: Domain, observables, targets: dict[str, float],
                         tolerance: float, n: int, sample: pd.DataFrame | None = None) -> AdmissibleSet:
    """Eq. (2)-(4) for more than 3 factors: randomised-QMC fraction with a confidence interval
    (:func:`demid.uncertainty.sobol_fraction`), spans polished to the boundary, and the admissible
    points of the evaluation sample for figures."""
    from .uncertainty import sobol_fraction

    observables = tuple(observables)
    if sample is None:
        sample = predict_grid({o: surrogates[o] for o in observables}, domain, n)
    points = sample[list(domain.factors)].to_numpy()
    resid = relative_residuals({o: sample[o].to_numpy() for o in observables}, targets, observables)
    worst = np.max(np.abs(resid), axis=0)
    mask = worst <= tolerance
    est = sobol_fraction(surrogates, domain, observables, targets, tolerance, n, seed=0)
    best = int(np.argmin(worst))
    return AdmissibleSet(
        observables=observables, tolerance=float(tolerance), factors=tuple(domain.factors), fraction=est.fraction,
        node_fraction=float(mask.mean()), n_nodes=int(mask.size), n_admissible_nodes=int(mask.sum()),
        n_refined_cells=0, lower=np.asarray(est.lower), upper=np.asarray(est.upper), mask=mask,
        best_error=float(worst[best]), best_point=points[best], evaluations=int(est.evaluations + resid.size),
        points=points, fraction_ci=(est.ci_lower, est.ci_upper))


def evaluate_scenarios(surrogates: dict[str, Surrogate], material_cfg: dict, n: int,
                       grid_predictions: pd.DataFrame | None = None) -> tuple[pd.DataFrame, dict[str, AdmissibleSet]]:
    """Every configured scenario of a material: long table (one row per scenario x factor) and the sets."""
    domain = Domain.from_config(material_cfg["factors"])
    targets = material_targets(material_cfg)
    frames, sets = [], {}
    for name, scen in (material_cfg.get("scenarios") or {}).items():
        if domain.dim > MAX_GRID_DIM:
            result = sobol_admissible_set(surrogates, domain, scen["observables"], targets, scen["tolerance"], n,
                                          grid_predictions)
        else:
            result = admissible_set(surrogates, domain, scen["observables"], targets, scen["tolerance"], n,
                                    grid_predictions=grid_predictions)
        frame = result.to_frame()
        frame.insert(0, "scenario", name)
        frames.append(frame)
        sets[name] = result
    columns = ["scenario", "observables", "tolerance", "feasible_fraction_pct", "factor", "lower", "upper",
               "width", "node_fraction_pct", "n_admissible_nodes", "best_max_rel_error"]
    table = pd.concat(frames, ignore_index=True) if frames else pd.DataFrame(columns=columns)
    return table[columns], sets

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

import numpy as np
import pandas as pd

from .surrogate import Surrogate


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
        lo = np.array([np.log10(v) if lg else v for v, lg in zip(self.lower, self.log)], dtype=float)
        hi = np.array([np.log10(v) if lg else v for v, lg in zip(self.upper, self.log)], dtype=float)
        return lo, hi

    def to_actual(self, u: np.ndarray) -> np.ndarray:
        u = np.array(u, dtype=float, copy=True, ndmin=2)
        for i, lg in enumerate(self.log):
            if lg:
                u[:, i] = 10.0 ** u[:, i]
        return u

    def to_search(self, x: np.ndarray) -> np.ndarray:
        x = np.array(x, dtype=float, copy=True, ndmin=2)
        for i, lg in enumerate(self.log):
            if lg:
                x[:, i] = np.log10(x[:, i])
        return x

    def search_axes(self, n: int) -> list[np.ndarray]:
        lo, hi = self.search_bounds()
        return [np.linspace(a, b, n) for a, b in zip(lo, hi)]

    def axes(self, n: int) -> list[np.ndarray]:
        """Grid axes in actual units (log-spaced for log factors)."""
        return [10.0 ** ax if lg else ax for ax, lg in zip(self.search_axes(n), self.log)]

    def grid(self, n: int) -> np.ndarray:
        """All grid nodes in actual units, shape (n**d, d), 'ij' (C) order."""
        mesh = np.meshgrid(*self.axes(n), indexing="ij")
        return np.column_stack([m.ravel() for m in mesh])


def predict_grid(surrogates: dict[str, Surrogate], domain: Domain, n: int) -> pd.DataFrame:
    """Surrogate predictions at every grid node: factor columns then one column per response."""
    points = domain.grid(n)
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

    # Classify cells from the corner ranges of every observable's residual.
    inside = np.ones((n - 1,) * d, dtype=bool)
    outside = np.zeros((n - 1,) * d, dtype=bool)
    for r in resid:
        lo = hi = None
        for view in _corner_views(r):
            lo = view.copy() if lo is None else np.minimum(lo, view)
            hi = view.copy() if hi is None else np.maximum(hi, view)
        m = _curvature_margin(r)
        inside &= (lo - m >= -eps) & (hi + m <= eps)
        outside |= (hi + m < -eps) | (lo - m > eps)
    candidate = ~inside & ~outside
    cell_frac = inside.astype(float)

    lo_u, hi_u = domain.search_bounds()
    step = (hi_u - lo_u) / (n - 1)
    s = subdivisions or (16 if d <= 2 else 4)
    sub = (np.arange(s) + 0.5) / s
    offsets = np.column_stack([m.ravel() for m in np.meshgrid(*[sub] * d, indexing="ij")])
    cand_idx = np.argwhere(candidate)
    evaluations = n ** d * len(observables)
    span_lo = np.full(d, np.inf)
    span_hi = np.full(d, -np.inf)
    chunk = max(1, 2_000_000 // len(offsets))
    for start in range(0, len(cand_idx), chunk):
        idx = cand_idx[start:start + chunk]
        u = (lo_u + idx[:, None, :] * step + offsets[None, :, :] * step).reshape(-1, d)
        x = domain.to_actual(u)
        ok = np.ones(len(x), dtype=bool)
        for o in observables:
            ok &= np.abs((surrogates[o].predict(x) - targets[o]) / abs(targets[o])) <= eps
        evaluations += len(x) * len(observables)
        ok2 = ok.reshape(len(idx), len(offsets))
        cell_frac[tuple(idx.T)] = ok2.mean(axis=1)
        if ok.any():
            span_lo = np.minimum(span_lo, u[ok].min(axis=0))
            span_hi = np.maximum(span_hi, u[ok].max(axis=0))

    axes_u = domain.search_axes(n)
    if mask.any():
        for i in range(d):
            present = np.any(mask, axis=tuple(j for j in range(d) if j != i))
            where = np.flatnonzero(present)
            span_lo[i] = min(span_lo[i], axes_u[i][where[0]])
            span_hi[i] = max(span_hi[i], axes_u[i][where[-1]])
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


def evaluate_scenarios(surrogates: dict[str, Surrogate], material_cfg: dict, n: int,
                       grid_predictions: pd.DataFrame | None = None) -> tuple[pd.DataFrame, dict[str, AdmissibleSet]]:
    """Every configured scenario of a material: long table (one row per scenario x factor) and the sets."""
    domain = Domain.from_config(material_cfg["factors"])
    targets = {r: float(c["target"]) for r, c in material_cfg["responses"].items() if "target" in c}
    frames, sets = [], {}
    for name, scen in (material_cfg.get("scenarios") or {}).items():
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

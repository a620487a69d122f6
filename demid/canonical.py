"""Canonical analysis of a fitted quadratic, as R's rsm ``canonical()`` with its threshold.

In coded units the surface is ``y = b0 + x'b + x'Bx`` (B symmetric: the pure quadratic
coefficients on its diagonal, half of each two-factor interaction off it).  Its eigenvalues
λ and unit eigenvectors (columns, largest λ first, as R's ``eigen``) give the canonical form
``y = y_s + Σ λ_i w_i²`` about the stationary point ``x_s = −½ B⁻¹ b``.

The stationary point ``x_s`` is reported whatever the eigenvalues (NaN for a singular B), with
``inside``: whether it lies within the runs' coded bounding box.  As rsm does, eigenvalues with
``|λ| < threshold`` (default 0.1·max|λ|) count as zero, and a ridge also gets rsm's stationary
point ``x_r = −½ Σ_{|λ_i| ≥ threshold} (v_iᵀb / λ_i) v_i``, the point of the ridge nearest the
design centre (clipped to the box: the ridge point restricted to the region).  The kind:

* no small eigenvalue: **maximum** (all λ < 0), **minimum** (all > 0) or **saddle point**;
* a small eigenvalue: a **ridge** along its eigenvector v.  Along the ridge from ``x_r`` the
  surface changes as ``g t + λ t²`` with slope ``g = vᵀb``.  When the slope carries the response
  further over the region's radius R than a curvature at the threshold would (``|g|·R >
  threshold·R²``) the ridge is **rising** (falling, for a maximum-like surface: the response keeps
  changing along it and the optimum lies outside the region), otherwise **stationary** (the
  response is flat along it: a line of near-optima); a ridge whose x_s lies inside the region is
  stationary, as the textbooks define it.

Verified against Montgomery, *Design and Analysis of Experiments*, Example 11.2
(a maximum) and closed-form saddles and ridges (``tests/combinations/test_canonical.py``), and on the
printed data and analyses of Lawson's trebuchet (a saddle), Myers, Montgomery & Anderson-Cook's Table 6.2
and Box, Hunter & Hunter's CO emissions (rising ridges) (``tests/combinations/test_canonical_published.py``).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .sampling.domain import search_to_actual

#: rsm's default: eigenvalues below this fraction of the largest |eigenvalue| count as zero.
DEFAULT_THRESHOLD_FRACTION = 0.1


def quadratic_parts(terms, coefficients, k: int) -> tuple[float, np.ndarray, np.ndarray]:
    """``(b0, b, B)`` of a polynomial given by exponent tuples ``terms`` (degree ≤ 2 used)."""
    b0, b, big_b = 0.0, np.zeros(k), np.zeros((k, k))
    for term, coef in zip(terms, coefficients):
        idx = [i for i, p in enumerate(term) for _ in range(p)]
        if not idx:
            b0 += float(coef)
        elif len(idx) == 1:
            b[idx[0]] += coef
        elif len(idx) == 2:
            i, j = idx
            if i == j:
                big_b[i, i] += coef
            else:
                big_b[i, j] += coef / 2
                big_b[j, i] += coef / 2
    return b0, b, big_b


@dataclass(frozen=True)
class Canonical:
    """One surface's canonical analysis (coded units unless named ``actual``)."""

    eigenvalues: np.ndarray        # largest first
    eigenvectors: np.ndarray       # columns, unit length, first nonzero loading positive
    threshold: float
    stationary_coded: np.ndarray   # x_s = −½ B⁻¹ b (NaN when B is singular)
    stationary_actual: np.ndarray
    value: float                   # predicted response at x_s
    kind: str                      # maximum, minimum, saddle point, stationary ridge, rising ridge
    inside: bool                   # x_s within the runs' coded box
    ridge_directions: np.ndarray   # columns: eigenvectors of the near-zero eigenvalues (k x 0 without ridge)
    ridge_slopes: np.ndarray       # vᵀb along each ridge direction
    ridge_point_coded: np.ndarray = None   # x_r (rsm's stationary point with the threshold), within the box
    ridge_point_actual: np.ndarray = None
    ridge_value: float = float("nan")

    @property
    def is_ridge(self) -> bool:
        return self.ridge_directions.shape[1] > 0

    def to_json(self) -> dict:
        out = {"stationary_coded": _floats(self.stationary_coded),
               "stationary_actual": _floats(self.stationary_actual),
               "eigenvalues": _floats(self.eigenvalues),
               "eigenvectors": [_floats(col) for col in self.eigenvectors.T],
               "kind": self.kind, "inside": bool(self.inside), "threshold": float(self.threshold),
               "predicted": float(self.value)}
        if self.is_ridge:
            out["ridge_directions"] = [_floats(col) for col in self.ridge_directions.T]
            out["ridge_slopes"] = _floats(self.ridge_slopes)
            out["ridge_point_coded"] = _floats(self.ridge_point_coded)
            out["ridge_point_actual"] = _floats(self.ridge_point_actual)
            out["ridge_predicted"] = float(self.ridge_value)
        return out


def _floats(values) -> list:
    return [float(v) for v in np.asarray(values, dtype=float)]


def _orient(vectors: np.ndarray) -> np.ndarray:
    """Eigenvectors up to sign: each column's largest loading made positive (reproducible output)."""
    out = vectors.copy()
    for j in range(out.shape[1]):
        if out[np.argmax(np.abs(out[:, j])), j] < 0:
            out[:, j] = -out[:, j]
    return out


def canonical_analysis(b0: float, b: np.ndarray, big_b: np.ndarray, *, region_lower, region_upper,
                       to_actual=None, threshold: float | None = None) -> Canonical:
    """Canonical analysis of ``b0 + x'b + x'Bx`` over the coded box ``[region_lower, region_upper]``.

    ``to_actual`` maps coded points (n x k) to actual units (identity when None); ``threshold``
    defaults to :data:`DEFAULT_THRESHOLD_FRACTION` of the largest |eigenvalue|.
    """
    b, big_b = np.asarray(b, dtype=float), np.asarray(big_b, dtype=float)
    lo, hi = np.asarray(region_lower, dtype=float), np.asarray(region_upper, dtype=float)
    values, vectors = np.linalg.eigh(big_b)
    order = np.argsort(values)[::-1]
    values, vectors = values[order], _orient(vectors[:, order])
    largest = float(np.max(np.abs(values))) if values.size else 0.0
    if threshold is None:
        threshold = DEFAULT_THRESHOLD_FRACTION * largest
    big = np.abs(values) >= threshold if largest > 0 else np.zeros(values.size, dtype=bool)

    def surface(x):
        return float(b0 + x @ b + x @ big_b @ x)

    def actual_of(x):
        return np.asarray(to_actual(x[None, :])[0] if to_actual is not None else x, dtype=float)

    def within(x):
        return bool(np.all(np.isfinite(x)) and np.all(x >= lo - 1e-9) and np.all(x <= hi + 1e-9))

    singular = largest == 0 or np.min(np.abs(values)) <= 1e-12 * largest
    xs = np.full(b.size, np.nan) if singular else -0.5 * vectors @ ((vectors.T @ b) / values)
    small = ~big
    slopes = vectors[:, small].T @ b
    common = dict(eigenvalues=values, eigenvectors=vectors, threshold=float(threshold), stationary_coded=xs,
                  stationary_actual=actual_of(xs), value=surface(xs) if not singular else float("nan"),
                  inside=within(xs), ridge_directions=vectors[:, small], ridge_slopes=slopes)
    if not small.any():
        kind = "maximum" if np.all(values < 0) else "minimum" if np.all(values > 0) else "saddle point"
        return Canonical(kind=kind, **common)
    # rsm's stationary point with the threshold: the ridge point nearest the design centre, kept in the box
    xr = -0.5 * vectors[:, big] @ ((vectors[:, big].T @ b) / values[big]) if big.any() else np.zeros(b.size)
    xr = np.clip(xr, lo, hi)
    radius = float(np.linalg.norm(hi - lo) / 2)
    # rising when the slope along the ridge moves the response over the region more than a curvature at
    # the threshold would; a stationary point inside the region is a stationary ridge (the textbook's rule)
    rising = np.abs(slopes) * radius > max(threshold, 1e-300) * radius ** 2
    kind = "rising ridge" if np.any(rising) and not common["inside"] else "stationary ridge"
    return Canonical(kind=kind, ridge_point_coded=xr, ridge_point_actual=actual_of(xr), ridge_value=surface(xr),
                     **common)


def fit_canonical(fit, threshold: float | None = None) -> Canonical:
    """Canonical analysis of a :class:`~demid.surrogate.SurrogateFit`:
    its coded coefficients, its runs' coded bounding box as the region, actual units through its
    coding (10** for log-scaled factors)."""
    k = len(fit.factors)
    b0, b, big_b = quadratic_parts(fit.terms, fit.results.params.to_numpy(), k)
    coded_runs = np.asarray(fit.results.model.exog, dtype=float)
    linear = [next((j for j, t in enumerate(fit.terms) if sum(t) == 1 and t[i] == 1), None) for i in range(k)]
    if all(j is not None for j in linear):
        runs = coded_runs[:, linear]
        lo, hi = runs.min(axis=0), runs.max(axis=0)
    else:
        lo, hi = -np.ones(k), np.ones(k)
    logs = [f in fit.log_factors for f in fit.factors]

    def to_actual(coded):
        with np.errstate(over="ignore"):  # a stationary point far outside may overflow 10**: inf says so
            return search_to_actual(fit.coding.to_actual(coded), logs)

    return canonical_analysis(b0, b, big_b, region_lower=lo, region_upper=hi, to_actual=to_actual,
                              threshold=threshold)

"""Real roots of univariate polynomials on [0, 1], lines cut at them, and the resultants and Chebyshev roots
the exact planes find their breakpoints with (:mod:`demid.sampling.exact`).

Coefficients are ascending (``coef[..., e]`` multiplies ``t**e``) and every function is batched over the
leading axes.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

_ROOT_IMAG_TOL = 1e-6    # accepted imaginary part of a breakpoint (extra breakpoints are harmless)


# =========================================================================== lines
def real_roots_unit(coef: np.ndarray) -> np.ndarray:
    """Real roots in [0, 1] of polynomials with ascending coefficients ``coef`` (..., D+1).

    Returns (..., D) with NaN for roots that are complex or outside [0, 1].
    """
    degree = coef.shape[-1] - 1
    if degree == 0:
        return np.empty(coef.shape[:-1] + (0,))
    if degree <= 2:
        roots = _quadratic_roots(coef)
    else:
        roots = _companion_roots(coef)
    return np.where((roots >= 0.0) & (roots <= 1.0), roots, np.nan)


def _quadratic_roots(coef: np.ndarray) -> np.ndarray:
    """Both roots of c0 + c1 t + c2 t^2 by the cancellation-free formula (c2 = 0 allowed)."""
    c0, c1 = coef[..., 0], coef[..., 1]
    if coef.shape[-1] == 2:
        with np.errstate(divide="ignore", invalid="ignore"):
            root = -c0 / c1
        return np.where(np.isfinite(root), root, np.nan)[..., None]
    c2 = coef[..., 2]
    with np.errstate(divide="ignore", invalid="ignore"):
        disc = c1 * c1 - 4.0 * c2 * c0
        q = -0.5 * (c1 + np.copysign(np.sqrt(disc), c1))
        roots = np.stack([q / c2, c0 / q], axis=-1)
    roots[disc < 0] = np.nan
    roots[~np.isfinite(roots)] = np.nan
    return roots


def _companion_roots(coef: np.ndarray, imag_tol: float = 1e-7) -> np.ndarray:
    """Real roots of higher-degree polynomials: companion eigenvalues, then two Newton steps."""
    shape, degree = coef.shape[:-1], coef.shape[-1] - 1
    flat = coef.reshape(-1, degree + 1)
    out = np.full((len(flat), degree), np.nan)
    scale = np.max(np.abs(flat), axis=1, keepdims=True)
    scaled = np.divide(flat, scale, out=np.zeros_like(flat), where=scale > 0)
    significant = np.abs(scaled) > 1e-14
    effective = np.where(significant.any(axis=1), degree - np.argmax(significant[:, ::-1], axis=1), 0)
    for deg in range(1, degree + 1):
        rows = np.flatnonzero(effective == deg)
        if not len(rows):
            continue
        monic = scaled[rows, :deg] / scaled[rows, deg:deg + 1]
        comp = np.zeros((len(rows), deg, deg))
        comp[:, np.arange(1, deg), np.arange(deg - 1)] = 1.0
        comp[:, :, -1] = -monic
        eig = np.linalg.eigvals(comp)
        real = np.where(np.abs(eig.imag) <= imag_tol * np.maximum(1.0, np.abs(eig.real)), eig.real, np.nan)
        for _ in range(2):
            value = horner(scaled[rows, :deg + 1][:, None, :], real)[:, 0, :]
            slope = horner((scaled[rows, 1:deg + 1] * np.arange(1, deg + 1))[:, None, :], real)[:, 0, :]
            with np.errstate(divide="ignore", invalid="ignore"):
                step = np.where(slope != 0, value / slope, 0.0)
            real = real - np.where(np.abs(step) < 1e-6, step, 0.0)
        out[rows, :deg] = real
    return out.reshape(shape + (degree,))


def horner(coef: np.ndarray, t: np.ndarray) -> np.ndarray:
    """Values (N, K, R) of K polynomials per line (coef (N, K, D+1)) at R points per line (t (N, R))."""
    out = np.broadcast_to(coef[:, :, -1:], coef.shape[:2] + (t.shape[1],)).copy()
    for e in range(coef.shape[2] - 2, -1, -1):
        out *= t[:, None, :]
        out += coef[:, :, e:e + 1]
    return out


@dataclass(frozen=True)
class Lines:
    """Lines cut into pieces at the roots of every ``g_k -+ eps``: ``edges`` (N, R+2), ``admissible`` (N, R+1)."""

    edges: np.ndarray
    admissible: np.ndarray

    @classmethod
    def cut(cls, coef: np.ndarray, eps: float) -> "Lines":
        n, k = coef.shape[:2]
        shifted = np.concatenate([coef, coef], axis=1)
        shifted[:, :k, 0] -= eps
        shifted[:, k:, 0] += eps
        roots = real_roots_unit(shifted).reshape(n, -1)
        edges = np.concatenate([np.zeros((n, 1)), np.where(np.isnan(roots), 1.0, roots), np.ones((n, 1))], axis=1)
        edges.sort(axis=1)
        mids = 0.5 * (edges[:, 1:] + edges[:, :-1])
        worst = np.max(np.abs(horner(coef, mids)), axis=1)
        return cls(edges, (worst <= eps) & (edges[:, 1:] > edges[:, :-1]))

    @property
    def length(self) -> np.ndarray:
        return np.sum(np.diff(self.edges, axis=1) * self.admissible, axis=1)

    @property
    def feasible(self) -> np.ndarray:
        return self.length > 0

    @property
    def first(self) -> np.ndarray:
        return np.min(np.where(self.admissible, self.edges[:, :-1], np.inf), axis=1)

    @property
    def last(self) -> np.ndarray:
        return np.max(np.where(self.admissible, self.edges[:, 1:], -np.inf), axis=1)

    def nearest(self, t: float) -> tuple[np.ndarray, np.ndarray]:
        """Per line: distance from coordinate ``t`` to the admissible intervals (inf if none), and the point."""
        closest = np.clip(t, self.edges[:, :-1], self.edges[:, 1:])
        gap = np.where(self.admissible, np.abs(closest - t), np.inf)
        best = np.argmin(gap, axis=1)
        rows = np.arange(len(best))
        return gap[rows, best], closest[rows, best]


def line_coefficients(tensor: np.ndarray, axis: int, points: np.ndarray) -> np.ndarray:
    """Ascending coefficients (N, K, D+1) along lines parallel to ``axis`` through ``points`` (N, d)."""
    d = tensor.ndim - 1
    powers = np.arange(tensor.shape[1])
    letters = "abcdefgh"[:d]
    operands, subscripts = [], []
    for i in range(d):
        if i != axis:
            operands.append(points[:, i][:, None] ** powers)
            subscripts.append("n" + letters[i])
    spec = ",".join(subscripts + ["k" + letters]) + "->nk" + letters[axis]
    if not subscripts:
        return np.broadcast_to(tensor, (len(points),) + tensor.shape).copy()
    return np.einsum(spec, *operands, tensor)


# =========================================================================== planes
def sylvester_det(f: np.ndarray, g: np.ndarray) -> np.ndarray:
    """Resultants (batched over leading axes) of polynomials with ascending coefficients f (..., p+1), g (..., q+1)."""
    p, q = f.shape[-1] - 1, g.shape[-1] - 1
    size = p + q
    if size == 0:
        return np.ones(f.shape[:-1])
    mat = np.zeros(f.shape[:-1] + (size, size))
    for i in range(q):
        mat[..., i, i:i + p + 1] = f[..., ::-1]
    for i in range(p):
        mat[..., q + i, i:i + q + 1] = g[..., ::-1]
    return np.linalg.det(mat)


def chebyshev_roots(coef: np.ndarray) -> np.ndarray:
    """Near-real roots in [-1, 1] of Chebyshev series (rows of ``coef``), NaN padded; colleague matrices."""
    n_rows, size = coef.shape
    out = np.full((n_rows, max(size - 1, 0)), np.nan)
    scale = np.max(np.abs(coef), axis=1, keepdims=True)
    scaled = np.divide(coef, scale, out=np.zeros_like(coef), where=scale > 0)
    scaled[np.abs(scaled) < 1e-11] = 0.0  # interpolation noise: not a degree
    nonzero = scaled != 0
    degree = np.where(nonzero.any(axis=1), size - 1 - np.argmax(nonzero[:, ::-1], axis=1), 0)
    for deg in range(1, size):
        rows = np.flatnonzero(degree == deg)
        if not len(rows):
            continue
        c = scaled[rows, :deg + 1]
        if deg == 1:
            out[rows, 0] = -c[:, 0] / c[:, 1]
            continue
        # numpy's chebcompanion, batched: symmetric colleague matrix minus a last-column update
        scl = np.array([1.0] + [np.sqrt(0.5)] * (deg - 1))
        mat = np.zeros((deg, deg))
        mat[np.arange(1, deg), np.arange(deg - 1)] = 0.5
        mat[np.arange(deg - 1), np.arange(1, deg)] = 0.5
        mat[0, 1] = mat[1, 0] = np.sqrt(0.5)
        mats = np.repeat(mat[None], len(rows), axis=0)
        mats[:, :, -1] -= (c[:, :-1] / c[:, -1:]) * (scl / scl[-1]) * 0.5
        eig = np.linalg.eigvals(mats)
        out[rows, :deg] = np.where(np.abs(eig.imag) <= _ROOT_IMAG_TOL, eig.real, np.nan)
    return np.where(np.abs(out) <= 1.0, out, np.nan)


def ragged(owners: np.ndarray, values: np.ndarray, n_owners: int) -> np.ndarray:
    """Sorted, de-duplicated values per owner as a NaN-padded array (n_owners, width)."""
    keep = np.isfinite(values)
    owners, values = owners[keep], values[keep]
    order = np.lexsort((values, owners))
    owners, values = owners[order], values[order]
    fresh = np.ones(len(values), dtype=bool)
    fresh[1:] = (owners[1:] != owners[:-1]) | (values[1:] - values[:-1] > 1e-14)
    owners, values = owners[fresh], values[fresh]
    counts = np.bincount(owners, minlength=n_owners)
    out = np.full((n_owners, max(int(counts.max()), 1)), np.nan)
    start = np.concatenate([[0], np.cumsum(counts)[:-1]])
    out[owners, np.arange(len(owners)) - start[owners]] = values
    return out

"""Exact admissible sets of polynomial surrogates: roots along lines, span ends by bisection.

The admissible set is ``A = {z in box : max_k |p_k(z) - y_k| / |y_k| <= eps}`` for
polynomials ``p_k`` in model coordinates ``z`` (actual units, or log10 for log-scale
factors).  All work happens in unit coordinates ``u in [0, 1]^d`` with
``z = lower + (upper - lower) * u``: the box is the unit cube, the feasible fraction is a
volume, and the distance from a reference point in fractions of the search range is a plain
Euclidean distance.

*Lines.*  Along a line parallel to an axis each residual ``g_k = (p_k - y_k) / |y_k|`` is a
univariate polynomial; the roots of ``g_k -+ eps`` split the line into pieces on which
admissibility is constant, so the admissible intervals are exact (one midpoint test per
piece).

*Planes.*  The pieces of the lines along one axis change their structure only at
*breakpoints* of the other coordinate: where a root enters through a box edge, where two roots
of one curve merge (a tangent parallel to the lines) and where the curves of two observables
cross.  These are the roots of univariate polynomials and of resultants (Sylvester
determinants, interpolated exactly at Chebyshev nodes), so nothing between two breakpoints
can be missed, however thin.  Between breakpoints the admissible length is smooth up to
square-root ends, which the substitution ``s = s0 + h (1 - cos(pi v)) / 2`` removes;
adaptive Gauss-Kronrod (7-15) quadrature then converges fast and estimates its error.  A span end is the first breakpoint bounding a feasible piece, polished by
bisection on "the line at x_j = t holds an admissible interval".  The fraction is computed
along both axes; the two results are independent and their difference enters the error.

*Three factors* are handled by slices: each slice is an exact plane; spans and the reference
distance minimise exact slice quantities over the slicing coordinate (a scan that includes the
slice through an admissible seed point, then repeated sampling of the bracket around the best
slice), and the fraction integrates exact slice areas adaptively over the widest span.  The
exact plane computations make thin features *within* a slice safe; a second component thinner
than the scan spacing across the slices, away from the seed, could be missed by the 3-D spans.

Entry point: :func:`exact_set`; :func:`exact_set_for_surrogates` adapts
:class:`demid.surrogate.Surrogate` objects.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property
from itertools import product
from math import comb
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

if TYPE_CHECKING:
    from .domain import Domain

#: Highest number of factors handled exactly (more factors need quasi-Monte Carlo).
MAX_EXACT_DIM = 3

_QUADRATURE_RTOL = 1e-7  # per plane (QUADPACK estimates are conservative: true errors ~1e-11)
_OUTER_RTOL = 1e-6
_MAX_ROUNDS = 40
_BISECTION_STEPS = 60
_SCAN_POINTS = 65        # slices scanned before the zoom refinement (3 factors)
_ROOT_IMAG_TOL = 1e-6    # accepted imaginary part of a breakpoint (extra breakpoints are harmless)


# =========================================================================== polynomials
@dataclass(frozen=True, eq=False)
class Polynomial:
    """``sum_m coefficients[m] * prod_i z_i ** exponents[m, i]`` in model coordinates.

    ``exponents`` is an integer matrix (terms x factors), the same exponent tuples as
    :data:`demid.design.Term`; ``coefficients`` are in model units (what
    ``Surrogate.coefficients`` holds).
    """

    exponents: np.ndarray
    coefficients: np.ndarray

    def __post_init__(self):
        exps = np.asarray(self.exponents, dtype=int)
        coef = np.asarray(self.coefficients, dtype=float).ravel()
        if exps.ndim != 2 or exps.shape[0] != coef.shape[0] or (exps < 0).any():
            raise ValueError("a Polynomial needs a (terms x factors) matrix of non-negative exponents "
                             "and one coefficient per term")
        object.__setattr__(self, "exponents", exps)
        object.__setattr__(self, "coefficients", coef)

    @property
    def dim(self) -> int:
        return self.exponents.shape[1]

    @property
    def degree(self) -> int:
        return int(self.exponents.sum(axis=1).max()) if len(self.coefficients) else 0

    def __call__(self, z) -> np.ndarray:
        z = np.atleast_2d(np.asarray(z, dtype=float))
        return np.prod(z[:, None, :] ** self.exponents[None, :, :], axis=2) @ self.coefficients

    def unit_tensor(self, lower, upper, degree: int | None = None) -> np.ndarray:
        """Dense coefficients ``c[e_1, ..., e_d]`` in unit coordinates ``z = lower + (upper - lower) u``."""
        lower = np.asarray(lower, dtype=float)
        scale = np.asarray(upper, dtype=float) - lower
        size = (degree if degree is not None else self.degree) + 1
        out = np.zeros((size,) * self.dim)
        for exps, coef in zip(self.exponents, self.coefficients):
            # prod_i (lower_i + scale_i u_i)^e_i, expanded binomially per factor
            block = np.array(coef)
            for e, lo, h in zip(exps, lower, scale):
                block = np.multiply.outer(block, [comb(e, j) * lo ** (e - j) * h ** j for j in range(e + 1)])
            out[tuple(slice(0, e + 1) for e in exps)] += block
        return out


def polynomial_from_surrogate(surrogate) -> Polynomial:
    """The polynomial of a :class:`demid.surrogate.Surrogate` (model units, log10 for log factors)."""
    terms = np.array(surrogate.terms, dtype=int).reshape(len(surrogate.terms), len(surrogate.factors))
    return Polynomial(terms, np.asarray(surrogate.coefficients, dtype=float))


# =========================================================================== one dimension
def _real_roots_unit(coef: np.ndarray) -> np.ndarray:
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
            value = _horner(scaled[rows, :deg + 1][:, None, :], real)[:, 0, :]
            slope = _horner((scaled[rows, 1:deg + 1] * np.arange(1, deg + 1))[:, None, :], real)[:, 0, :]
            with np.errstate(divide="ignore", invalid="ignore"):
                step = np.where(slope != 0, value / slope, 0.0)
            real = real - np.where(np.abs(step) < 1e-6, step, 0.0)
        out[rows, :deg] = real
    return out.reshape(shape + (degree,))


def _horner(coef: np.ndarray, t: np.ndarray) -> np.ndarray:
    """Values (N, K, R) of K polynomials per line (coef (N, K, D+1)) at R points per line (t (N, R))."""
    out = np.broadcast_to(coef[:, :, -1:], coef.shape[:2] + (t.shape[1],)).copy()
    for e in range(coef.shape[2] - 2, -1, -1):
        out *= t[:, None, :]
        out += coef[:, :, e:e + 1]
    return out


@dataclass(frozen=True)
class _Lines:
    """Lines cut into pieces at the roots of every ``g_k -+ eps``: ``edges`` (N, R+2), ``admissible`` (N, R+1)."""

    edges: np.ndarray
    admissible: np.ndarray

    @classmethod
    def cut(cls, coef: np.ndarray, eps: float) -> "_Lines":
        n, k = coef.shape[:2]
        shifted = np.concatenate([coef, coef], axis=1)
        shifted[:, :k, 0] -= eps
        shifted[:, k:, 0] += eps
        roots = _real_roots_unit(shifted).reshape(n, -1)
        edges = np.concatenate([np.zeros((n, 1)), np.where(np.isnan(roots), 1.0, roots), np.ones((n, 1))], axis=1)
        edges.sort(axis=1)
        mids = 0.5 * (edges[:, 1:] + edges[:, :-1])
        worst = np.max(np.abs(_horner(coef, mids)), axis=1)
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


def _line_coefficients(tensor: np.ndarray, axis: int, points: np.ndarray) -> np.ndarray:
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


# =========================================================================== quadrature
# Gauss-Kronrod 7-15 (QUADPACK qk15): Kronrod abscissae in (0, 1] of [-1, 1] and weights; the
# 7-point Gauss rule uses every second abscissa.
_XGK = np.array([0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                 0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                 0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                 0.207784955007898467600689403773245, 0.0])
_WGK = np.array([0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                 0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                 0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                 0.204432940075298892414161999234649, 0.209482141084727828012999174891714])
_WG = np.array([0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                0.381830050505118944950369775488975, 0.417959183673469387755102040816327])
_KRONROD_NODES = np.concatenate([-_XGK[:-1], _XGK[::-1]]) / 2 + 0.5   # on [0, 1], ascending
_KRONROD_WEIGHTS = np.concatenate([_WGK[:-1], _WGK[::-1]]) / 2
_GAUSS_WEIGHTS = np.zeros(15)
_GAUSS_WEIGHTS[[1, 3, 5, 7, 9, 11, 13]] = np.concatenate([_WG[:-1], _WG[::-1]]) / 2
_MAX_PIECES = 20_000


def _integrate(func, owners, lower, upper, n_owners: int, rtol: float, columns: int = 1,
               atol: float = 1e-15) -> tuple[np.ndarray, np.ndarray]:
    """Adaptive integrals of a vectorised ``func(owner, s) -> (M, columns)`` over pieces of owners.

    Piece m covers [lower[m], upper[m]] of owner ``owners[m]``.  Each piece is mapped by
    ``s = s0 + h (1 - cos(pi v)) / 2``, which turns square-root ends (a line grazing a curve)
    into smooth ones, and integrated by Gauss-Kronrod 7-15 in ``v``; pieces are bisected until
    the QUADPACK error estimate meets ``rtol`` of the owner's integral.  Returns integrals
    (n_owners, columns) and the summed error estimates of the first column (n_owners,).
    """
    owners = np.asarray(owners, dtype=int)
    lower, upper = np.asarray(lower, dtype=float), np.asarray(upper, dtype=float)
    keep = upper - lower > 1e-15
    owners, lower, upper = owners[keep], lower[keep], upper[keep]
    length = np.bincount(owners, weights=upper - lower, minlength=n_owners)
    length[length == 0] = 1.0
    total, error, target = np.zeros((n_owners, columns)), np.zeros(n_owners), None
    for rnd in range(_MAX_ROUNDS):
        if not len(lower):
            break
        h = upper - lower
        nodes = lower[:, None] + h[:, None] * (1 - np.cos(np.pi * _KRONROD_NODES)) / 2
        jac = h[:, None] * np.pi / 2 * np.sin(np.pi * _KRONROD_NODES)
        values = np.asarray(func(np.repeat(owners, 15), nodes.ravel()), dtype=float).reshape(len(h), 15, columns)
        kronrod = np.einsum("pn,pnc->pc", jac * _KRONROD_WEIGHTS, values)
        gauss = np.einsum("pn,pn->p", jac * _GAUSS_WEIGHTS, values[:, :, 0])
        # QUADPACK's estimate: |K - G| scaled by the integrand's variation on the piece
        mean = kronrod[:, 0] / h
        variation = np.einsum("pn,pn->p", jac * _KRONROD_WEIGHTS, np.abs(values[:, :, 0] - mean[:, None]))
        diff = np.abs(kronrod[:, 0] - gauss)
        with np.errstate(divide="ignore", invalid="ignore"):
            scaled = np.where(variation > 0, variation * np.minimum(1.0, (200 * diff / variation) ** 1.5), diff)
        estimate = np.maximum(scaled, 50 * np.finfo(float).eps * np.abs(kronrod[:, 0]))
        if target is None:
            target = np.maximum(rtol * np.abs(np.bincount(owners, weights=kronrod[:, 0], minlength=n_owners)), atol)
        last = rnd == _MAX_ROUNDS - 1 or 2 * len(h) > _MAX_PIECES
        done = (estimate <= target[owners] * h / length[owners]) | (h < 1e-13) | last
        np.add.at(total, owners[done], kronrod[done])
        np.add.at(error, owners[done], estimate[done])
        owners, lower, upper = owners[~done], lower[~done], upper[~done]
        mid = 0.5 * (lower + upper)
        owners = np.concatenate([owners, owners])
        lower, upper = np.concatenate([lower, mid]), np.concatenate([mid, upper])
    return total, error


def _argmin_by_owner(owners: np.ndarray, values: np.ndarray, n_owners: int) -> np.ndarray:
    """Index of the smallest value of each owner (-1 for owners without entries)."""
    order = np.lexsort((values, owners))
    first = np.ones(len(order), dtype=bool)
    first[1:] = owners[order][1:] != owners[order][:-1]
    out = np.full(n_owners, -1)
    out[owners[order][first]] = order[first]
    return out


def _zoom_min(func, owners, lower, upper, best_x, best_value, rounds: int = 11, points: int = 17):
    """Refine per-owner minima of ``func(owner, x)`` by repeatedly sampling the bracket around the best point."""
    best_x, best_value = np.array(best_x, dtype=float), np.array(best_value, dtype=float)
    lower, upper = np.array(lower, dtype=float), np.array(upper, dtype=float)
    rows = np.arange(len(owners))
    grid = np.linspace(0.0, 1.0, points)
    for _ in range(rounds):
        x = lower[:, None] + (upper - lower)[:, None] * grid
        values = np.asarray(func(np.repeat(owners, points), x.ravel())).reshape(len(owners), points)
        i = np.argmin(values, axis=1)
        better = values[rows, i] < best_value
        best_x = np.where(better, x[rows, i], best_x)
        best_value = np.where(better, values[rows, i], best_value)
        lower, upper = x[rows, np.maximum(i - 1, 0)], x[rows, np.minimum(i + 1, points - 1)]
        if np.max(upper - lower) < 1e-13:
            break
    return best_x, best_value


# =========================================================================== planes
def _sylvester_det(f: np.ndarray, g: np.ndarray) -> np.ndarray:
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


def _chebyshev_roots(coef: np.ndarray) -> np.ndarray:
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


def _ragged(owners: np.ndarray, values: np.ndarray, n_owners: int) -> np.ndarray:
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


@dataclass(frozen=True)
class _Pieces:
    """Breakpoint pieces of lines along one axis, for all planes: owner, [lower, upper], feasible."""

    owner: np.ndarray
    lower: np.ndarray
    upper: np.ndarray
    feasible: np.ndarray

    @property
    def mid(self) -> np.ndarray:
        return 0.5 * (self.lower + self.upper)


class _Planes:
    """Admissible sets of a batch of planes, residual tensors (P, K, D+1, D+1) on the unit square.

    Pieces of lines along ``axis`` are delimited by breakpoints of the other coordinate; each
    piece is feasible (its lines hold admissible intervals) or not, throughout.
    """

    def __init__(self, tensors: np.ndarray, eps: float):
        self.tensors = tensors
        self.eps = eps
        self.count = tensors.shape[0]
        self._pieces: dict[int, _Pieces] = {}

    def lines(self, axis: int, owners, s) -> _Lines:
        """Lines parallel to ``axis`` in planes ``owners`` at other coordinate ``s``."""
        s = np.atleast_1d(np.asarray(s, dtype=float))
        powers = s[:, None] ** np.arange(self.tensors.shape[2])
        spec = "ns,nkts->nkt" if axis == 0 else "ns,nkst->nkt"
        return _Lines.cut(np.einsum(spec, powers, self.tensors[np.asarray(owners)]), self.eps)

    def pieces(self, axis: int) -> _Pieces:
        if axis not in self._pieces:
            points = self._breakpoints(axis)
            points = np.where(np.isnan(points), 1.0, points)
            lower, upper = points[:, :-1], points[:, 1:]
            valid = upper - lower > 1e-14
            owner = np.nonzero(valid)[0]
            lower, upper = lower[valid], upper[valid]
            feasible = self.lines(axis, owner, 0.5 * (lower + upper)).feasible
            self._pieces[axis] = _Pieces(owner, lower, upper, feasible)
        return self._pieces[axis]

    def _breakpoints(self, axis: int) -> np.ndarray:
        """Per plane, the sorted values of the other coordinate where lines along ``axis`` change structure."""
        tens = self.tensors if axis == 0 else self.tensors.transpose(0, 1, 3, 2)  # [p, k, e_t, e_s]
        n_planes, n_obs, size = tens.shape[:3]
        levels = np.array([self.eps, -self.eps])
        owners = [np.arange(n_planes), np.arange(n_planes)]
        values = [np.zeros(n_planes), np.ones(n_planes)]
        # roots entering or leaving through the edges t = 0 and t = 1
        for t in (0.0, 1.0):
            edge = np.einsum("t,pkts->pks", t ** np.arange(size), tens)
            shifted = np.repeat(edge[:, :, None, :], 2, axis=2)
            shifted[..., 0] -= levels
            roots = _real_roots_unit(shifted).reshape(n_planes, -1)
            owners.append(np.repeat(np.arange(n_planes), roots.shape[1]))
            values.append(roots.ravel())
        scale = np.max(np.abs(tens), axis=(2, 3), keepdims=True)
        significant = np.abs(tens) > 1e-14 * scale
        e_t, e_s = np.meshgrid(np.arange(size), np.arange(size), indexing="ij")
        t_degree = np.max(np.where(significant, e_t, 0), axis=(2, 3))  # formal degree per plane and observable
        top = int(np.max(np.where(significant, e_t + e_s, 0)))
        if t_degree.max() > 0:
            rows, dets = self._resultants(tens, t_degree, top)
            if len(rows):
                n_nodes = dets.shape[1]
                nodes = np.cos(np.pi * (np.arange(n_nodes) + 0.5) / n_nodes)
                from numpy.polynomial import chebyshev as cheb

                peak = np.max(np.abs(dets), axis=1, keepdims=True)
                keep = peak[:, 0] > 0
                coef = (dets[keep] / peak[keep]) @ np.linalg.inv(cheb.chebvander(nodes, n_nodes - 1)).T
                roots = (_chebyshev_roots(coef) + 1) / 2
                owners.append(np.repeat(rows[keep], roots.shape[1]))
                values.append(roots.ravel())
        return _ragged(np.concatenate(owners), np.clip(np.concatenate(values), 0.0, 1.0), n_planes)

    def _resultants(self, tens, t_degree, top):
        """Resultants in t of every curve with its t-derivative and with every curve of another observable,
        sampled at Chebyshev nodes of s (enough nodes to interpolate them exactly)."""
        n_nodes = 2 * top * top + 1
        s = (np.cos(np.pi * (np.arange(n_nodes) + 0.5) / n_nodes) + 1) / 2
        coef_t = np.einsum("ns,pkts->pknt", s[:, None] ** np.arange(tens.shape[2]), tens)  # (P, K, n, D+1)
        levels = (self.eps, -self.eps)
        rows, dets = [], []

        def curve(planes, k, level, degree):
            f = coef_t[planes, k, :, :degree + 1].copy()
            f[..., 0] -= level
            return f

        n_obs = tens.shape[1]
        for k in range(n_obs):
            for degree in np.unique(t_degree[:, k]):
                if degree == 0:
                    continue  # curves s = const: their positions are edge roots already
                planes = np.flatnonzero(t_degree[:, k] == degree)
                for level in levels:
                    f = curve(planes, k, level, degree)
                    rows.append(planes)
                    dets.append(_sylvester_det(f, f[..., 1:] * np.arange(1, degree + 1)))
        for k1 in range(n_obs):
            for k2 in range(k1 + 1, n_obs):
                pairs = t_degree[:, [k1, k2]]
                for d1, d2 in np.unique(pairs, axis=0):
                    if d1 == 0 or d2 == 0:
                        continue
                    planes = np.flatnonzero((pairs[:, 0] == d1) & (pairs[:, 1] == d2))
                    for l1, l2 in product(levels, levels):
                        rows.append(planes)
                        dets.append(_sylvester_det(curve(planes, k1, l1, d1), curve(planes, k2, l2, d2)))
        if not rows:
            return np.empty(0, dtype=int), np.empty((0, n_nodes))
        return np.concatenate(rows), np.concatenate(dets)

    def integral(self, axis: int, rtol: float | None = None) -> tuple[np.ndarray, np.ndarray]:
        """Areas (P,) from exact line lengths, and their quadrature error estimates (P,)."""
        pieces = self.pieces(axis)
        f = pieces.feasible
        total, error = _integrate(lambda o, s: self.lines(axis, o, s).length[:, None], pieces.owner[f],
                                  pieces.lower[f], pieces.upper[f], self.count, rtol or _QUADRATURE_RTOL)
        return total[:, 0], error

    def spans(self, coord: int, polish: bool = True) -> np.ndarray:
        """(P, 2) exact min and max of coordinate ``coord`` per plane (NaN when empty)."""
        axis = 1 - coord  # lines across the coordinate
        pieces = self.pieces(axis)
        out = np.full((self.count, 2), np.nan)
        idx = np.flatnonzero(pieces.feasible)
        if not len(idx):
            return out
        first = np.full(self.count, -1)
        last = np.full(self.count, -1)
        first[pieces.owner[idx[::-1]]] = idx[::-1]
        last[pieces.owner[idx]] = idx
        has = np.flatnonzero(first >= 0)
        lo_piece, hi_piece = first[has], last[has]
        out[has, 0] = pieces.lower[lo_piece]
        out[has, 1] = pieces.upper[hi_piece]
        if polish:
            # bisection between the feasible piece's midpoint and the infeasible neighbour's
            inner = np.concatenate([lo_piece, hi_piece])
            outer = np.concatenate([lo_piece - 1, hi_piece + 1])
            interior = np.concatenate([pieces.lower[lo_piece] > 0, pieces.upper[hi_piece] < 1])
            owners = pieces.owner[inner]
            inside = pieces.mid[inner]
            outside = np.where(interior, pieces.mid[np.clip(outer, 0, len(pieces.mid) - 1)], inside)
            ends = self._bisect(axis, owners, inside, outside)
            out[has, 0] = np.where(interior[:len(has)], ends[:len(has)], 0.0)
            out[has, 1] = np.where(interior[len(has):], ends[len(has):], 1.0)
        return out

    def _bisect(self, axis: int, owners, inside: np.ndarray, outside: np.ndarray) -> np.ndarray:
        """Transitions between feasible lines at ``inside`` and infeasible lines at ``outside``."""
        inside, outside = inside.copy(), outside.copy()
        for _ in range(_BISECTION_STEPS):
            if np.max(np.abs(inside - outside)) < 1e-15:
                break
            mid = 0.5 * (inside + outside)
            ok = self.lines(axis, owners, mid).feasible
            inside = np.where(ok, mid, inside)
            outside = np.where(ok, outside, mid)
        return inside

    def distance(self, ref: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Per plane: Euclidean distance from ``ref`` (2,) to the set and the nearest point (inf, NaN when empty)."""
        pieces = self.pieces(0)
        f = np.flatnonzero(pieces.feasible)
        dist, point = np.full(self.count, np.inf), np.full((self.count, 2), np.nan)
        if not len(f):
            return dist, point

        def squared(owners, s):
            gap, _ = self.lines(0, owners, s).nearest(ref[0])
            return gap ** 2 + (s - ref[1]) ** 2

        grid = (1 - np.cos(np.pi * np.linspace(0, 1, 17))) / 2
        lo, hi = pieces.lower[f], pieces.upper[f]
        pad = 1e-12 * (hi - lo)
        samples = (lo + pad)[:, None] + (hi - lo - 2 * pad)[:, None] * grid
        owners = np.repeat(pieces.owner[f], 17)
        values = squared(owners, samples.ravel())
        best = _argmin_by_owner(owners, values, self.count)
        has = np.flatnonzero(best >= 0)
        piece, i = np.divmod(best[has], 17)
        s_best, v_best = _zoom_min(squared, has, samples[piece, np.maximum(i - 1, 0)],
                                   samples[piece, np.minimum(i + 1, 16)], samples[piece, i], values[best[has]])
        _, t_best = self.lines(0, has, s_best).nearest(ref[0])
        dist[has] = np.sqrt(v_best)
        point[has] = np.column_stack([t_best, s_best])
        return dist, point


# =========================================================================== three factors
class _Solid:
    """The admissible set of residual tensors (K, D+1, D+1, D+1) in the unit cube, slice by slice."""

    def __init__(self, tensor: np.ndarray, eps: float):
        self.tensor = tensor
        self.eps = eps

    def planes(self, axis: int, s) -> _Planes:
        """The slices ``u_axis = s``; their coordinates are the other two axes in order."""
        s = np.atleast_1d(np.asarray(s, dtype=float))
        moved = np.moveaxis(self.tensor, axis + 1, -1)
        return _Planes(np.einsum("pe,kabe->pkab", s[:, None] ** np.arange(self.tensor.shape[1]), moved), self.eps)

    @cached_property
    def seed(self) -> np.ndarray | None:
        """An admissible point (unit coordinates), or None: best node of a 41^3 grid, else a local search."""
        from scipy import optimize

        nodes = np.linspace(0.0, 1.0, 41)
        powers = nodes[:, None] ** np.arange(self.tensor.shape[1])
        worst = np.max(np.abs(np.einsum("ia,jb,kc,qabc->qijk", powers, powers, powers, self.tensor)), axis=0)
        order = np.argsort(worst, axis=None)[:4]
        starts = np.column_stack(np.unravel_index(order, worst.shape)) / 40.0
        if worst.flat[order[0]] <= self.eps:
            return starts[0]

        def excess(u):
            inside = np.clip(u, 0.0, 1.0)
            coef = _line_coefficients(self.tensor, 0, inside[None, :])
            return float(np.max(np.abs(_horner(coef, inside[None, :1])))) + float(np.sum(np.abs(u - inside)))

        for start in starts:
            res = optimize.minimize(excess, start, method="Nelder-Mead",
                                    options={"xatol": 1e-12, "fatol": 1e-14, "maxfev": 4000})
            if res.fun <= self.eps:
                return np.clip(res.x, 0.0, 1.0)
        return None

    def span(self, coord: int) -> tuple[float, float]:
        """Min and max of ``coord``: exact slice spans, minimised over slices of another coordinate."""
        seed = self.seed
        if seed is None:
            return np.nan, np.nan
        for axis in (a for a in range(3) if a != coord):
            c = coord - (coord > axis)
            # the slice through the seed holds the set however thin it is across the slices
            scan = np.unique(np.append(np.linspace(0.0, 1.0, _SCAN_POINTS), seed[axis]))
            ends = self.planes(axis, scan).spans(c, polish=False)
            if np.isnan(ends[:, 0]).all():
                continue  # the seed lies on a measure-zero part: slice another way

            def objective(owners, s):
                e = self.planes(axis, s).spans(c, polish=False)
                return np.nan_to_num(np.where(owners == 0, e[:, 0], -e[:, 1]), nan=np.inf)

            values = np.nan_to_num(np.column_stack([ends[:, 0], -ends[:, 1]]), nan=np.inf)
            i = np.argmin(values, axis=0)
            last = len(scan) - 1
            s_best, _ = _zoom_min(objective, np.array([0, 1]), scan[np.maximum(i - 1, 0)],
                                  scan[np.minimum(i + 1, last)], scan[i], values[i, [0, 1]])
            final = self.planes(axis, s_best).spans(c)
            return float(final[0, 0]), float(final[1, 1])
        return np.nan, np.nan

    def integral(self, axis: int, lower: float, upper: float) -> tuple[float, float]:
        """Volume by adaptive integration over slices ``u_axis = s`` of exact slice areas."""

        def areas(owners, s):
            area, error = self.planes(axis, s).integral(0)
            return np.column_stack([area, error])

        edges = np.linspace(lower, upper, 9)
        total, error = _integrate(areas, np.zeros(8, dtype=int), edges[:-1], edges[1:], 1, _OUTER_RTOL, columns=2)
        return float(total[0, 0]), float(error[0] + total[0, 1])

    def distance(self, ref: np.ndarray, axis: int, lower: float, upper: float) -> tuple[float, np.ndarray]:
        """Distance from ``ref`` (3,) to the set, minimising over slices ``u_axis = s`` in [lower, upper]."""
        rest = np.delete(ref, axis)

        def squared(owners, s):
            d, _ = self.planes(axis, s).distance(rest)
            return d * d + (s - ref[axis]) ** 2

        pad = 1e-12 * (upper - lower)
        scan = np.linspace(lower + pad, upper - pad, 33)
        values = squared(None, scan)
        i = int(np.argmin(values))
        s_best, best = _zoom_min(squared, np.array([0]), [scan[max(i - 1, 0)]], [scan[min(i + 1, 32)]],
                                 [scan[i]], [values[i]])
        _, point = self.planes(axis, s_best).distance(rest)
        return float(np.sqrt(best[0])), np.insert(point[0], axis, s_best[0])


# =========================================================================== result
@dataclass(frozen=True, eq=False)
class ExactSet:
    """The admissible set of polynomial surrogates, computed on first access of each property.

    Coordinates: ``lower``/``upper``/``reference`` and :attr:`model_spans` are in model units
    (log10 for log-scale factors); :attr:`spans` reports actual units (``10 **`` for the
    factors flagged in ``log``).  ``reference_distance`` is in fractions of the search range
    (Euclidean in model units divided by the range of each factor).
    """

    residuals: np.ndarray = field(repr=False)  # (K, D+1, ..., D+1) residual tensors in unit coordinates
    tolerance: float
    lower: np.ndarray
    upper: np.ndarray
    factors: tuple[str, ...]
    log: tuple[bool, ...]
    reference: np.ndarray | None = None

    @property
    def dim(self) -> int:
        return len(self.factors)

    def to_model(self, u) -> np.ndarray:
        return self.lower + (self.upper - self.lower) * np.asarray(u, dtype=float)

    def to_actual(self, z) -> np.ndarray:
        z = np.array(z, dtype=float)
        return np.where(np.array(self.log), 10.0 ** z, z)

    @cached_property
    def _shape(self):
        if self.dim == 1:
            return _Lines.cut(self.residuals[None], self.tolerance)
        if self.dim == 2:
            return _Planes(self.residuals[None], self.tolerance)
        return _Solid(self.residuals, self.tolerance)

    @cached_property
    def _unit_spans(self) -> np.ndarray:
        shape = self._shape
        if self.dim == 1:
            return np.array([[shape.first[0], shape.last[0]]]) if shape.feasible[0] else np.full((1, 2), np.nan)
        if self.dim == 2:
            return np.array([shape.spans(j)[0] for j in range(2)])
        return np.array([shape.span(j) for j in range(3)])

    @cached_property
    def _outer_axis(self) -> int:
        """Slicing axis of a solid: the widest span (a set thin in one coordinate is never sliced across it)."""
        widths = np.nan_to_num(self._unit_spans[:, 1] - self._unit_spans[:, 0], nan=-1.0)
        return int(np.argmax(widths))

    @cached_property
    def _fraction(self) -> tuple[float, float]:
        shape = self._shape
        if self.dim == 1:
            return float(shape.length[0]), 0.0
        if self.dim == 2:
            # two independent integrations, along each axis; their difference joins the error
            (along0,), (err0,) = shape.integral(0)
            (along1,), (err1,) = shape.integral(1)
            return float(along0), float(err0 + err1 + abs(along0 - along1))
        lo, hi = self._unit_spans[self._outer_axis]
        if np.isnan(lo) or hi <= lo:
            return 0.0, 0.0
        return shape.integral(self._outer_axis, lo, hi)

    @property
    def fraction(self) -> float:
        """Feasible fraction of the box (volume in model coordinates)."""
        return self._fraction[0]

    @property
    def fraction_error(self) -> float:
        """Estimated absolute error of :attr:`fraction`: the quadrature estimates, and in 2-D the
        difference between the integrations along the two axes."""
        return self._fraction[1]

    @cached_property
    def model_spans(self) -> np.ndarray:
        """(d, 2) array: min and max of each factor over the set, model units (NaN when empty)."""
        return self.lower[:, None] + (self.upper - self.lower)[:, None] * self._unit_spans

    @cached_property
    def spans(self) -> pd.DataFrame:
        lower, upper = self.to_actual(self.model_spans[:, 0]), self.to_actual(self.model_spans[:, 1])
        return pd.DataFrame({"factor": list(self.factors), "lower": lower, "upper": upper, "width": upper - lower})

    @cached_property
    def _nearest(self) -> tuple[float, np.ndarray]:
        if self.reference is None:
            return np.nan, np.full(self.dim, np.nan)
        ref = (np.asarray(self.reference, dtype=float) - self.lower) / (self.upper - self.lower)
        worst = self._worst_residual(ref)
        if worst <= self.tolerance:
            return 0.0, ref
        shape = self._shape
        if self.dim == 1:
            gap, point = shape.nearest(ref[0])
            return float(gap[0]), np.array([point[0]])
        if self.dim == 2:
            dist, point = shape.distance(ref)
            return float(dist[0]), point[0]
        lo, hi = self._unit_spans[self._outer_axis]
        if np.isnan(lo):
            return np.inf, np.full(3, np.nan)
        return shape.distance(ref, self._outer_axis, lo, hi)

    def _worst_residual(self, u: np.ndarray) -> float:
        axis = 0
        coef = _line_coefficients(self.residuals, axis, u[None, :])
        return float(np.max(np.abs(_horner(coef, u[None, axis:axis + 1]))))

    @property
    def reference_distance(self) -> float:
        """Distance from the reference point to the set, as a fraction of the search range (0 inside, inf if empty)."""
        return self._nearest[0]

    @property
    def nearest_point(self) -> np.ndarray:
        """The admissible point nearest the reference point, in actual units."""
        return self.to_actual(self.to_model(self._nearest[1]))

    def to_frame(self) -> pd.DataFrame:
        """One row per factor: span, feasible fraction with error, reference distance and nearest point."""
        frame = self.spans.copy()
        frame.insert(0, "tolerance", self.tolerance)
        frame["feasible_fraction"] = self.fraction
        frame["fraction_error"] = self.fraction_error
        frame["reference_distance"] = self.reference_distance
        frame["nearest_point"] = self.nearest_point
        return frame


def exact_set(polys, targets, tolerance: float, lower, upper, *, reference=None, factors=None,
              log=None) -> ExactSet:
    """The admissible set ``max_k |p_k(z) - targets_k| / |targets_k| <= tolerance`` over the box [lower, upper].

    ``polys`` are :class:`Polynomial` objects in model coordinates; ``lower``, ``upper`` and
    ``reference`` are in model coordinates too.  ``factors`` names the coordinates (default
    ``x0, x1, ...``); ``log`` flags factors whose model coordinate is log10 of the actual value,
    used only to report spans and the nearest point in actual units.
    """
    polys = list(polys)
    targets = np.asarray(targets, dtype=float).ravel()
    lower = np.asarray(lower, dtype=float).ravel()
    upper = np.asarray(upper, dtype=float).ravel()
    dim = len(lower)
    if not polys or len(polys) != len(targets):
        raise ValueError("exact_set needs one target per polynomial")
    if not 1 <= dim <= MAX_EXACT_DIM or upper.shape != lower.shape or not np.all(upper > lower):
        raise ValueError(f"exact_set needs 1 to {MAX_EXACT_DIM} factors with lower < upper")
    if any(p.dim != dim for p in polys) or np.any(targets == 0) or not np.isfinite(targets).all():
        raise ValueError("every polynomial must have one exponent per factor and every target must be finite, non-zero")
    if not tolerance > 0:
        raise ValueError("tolerance must be positive")
    degree = max(max(p.degree for p in polys), 1)
    residuals = np.stack([p.unit_tensor(lower, upper, degree) for p in polys])
    residuals[(slice(None),) + (0,) * dim] -= targets
    residuals /= np.abs(targets).reshape((-1,) + (1,) * dim)
    names = tuple(factors) if factors is not None else tuple(f"x{i}" for i in range(dim))
    flags = tuple(bool(x) for x in log) if log is not None else (False,) * dim
    ref = None if reference is None else np.asarray(reference, dtype=float).ravel()
    if ref is not None and (ref.shape != lower.shape or not np.isfinite(ref).all()):
        raise ValueError("the reference point needs one finite value per factor")
    return ExactSet(residuals, float(tolerance), lower, upper, names, flags, ref)


def exact_set_for_surrogates(surrogates: dict, observables, targets: dict, tolerance: float,
                             domain: Domain, *, reference: dict | None = None) -> ExactSet:
    """:func:`exact_set` for :class:`demid.surrogate.Surrogate` objects over a material's search domain
    (:attr:`demid.spec.MaterialSpec.domain`).

    Bounds and the reference point are given in actual units (as in the config); log-scale
    factors are converted to their model coordinate (log10) here.
    """
    names = list(domain.factors)
    log = list(domain.log)

    def model(values):
        values = np.array(values, dtype=float)
        values[log] = np.log10(values[log])
        return values

    for o in observables:
        if list(surrogates[o].factors) != names:
            raise ValueError(f"surrogate '{o}' has factors {surrogates[o].factors}, expected {names}")
    lower = model(domain.lower)
    upper = model(domain.upper)
    ref = None if reference is None else model([reference[f] for f in names])
    return exact_set([polynomial_from_surrogate(surrogates[o]) for o in observables],
                     [targets[o] for o in observables], tolerance, lower, upper, reference=ref,
                     factors=names, log=log)

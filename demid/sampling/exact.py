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
embedded Clenshaw-Curtis rules then converge geometrically and their difference is the error
estimate.  A span end is the first breakpoint bounding a feasible piece, polished by
bisection on "the line at x_j = t holds an admissible interval".  The fraction is computed
along both axes; the two results are independent and their difference enters the error.

*Three factors* are handled by slices: each slice is an exact plane; spans and the reference
distance minimise exact slice quantities over the slicing coordinate (scan, then golden
section), and the fraction integrates exact slice areas adaptively.

Entry point: :func:`exact_set`; :func:`exact_set_for_surrogates` adapts
:class:`demid.surrogate.Surrogate` objects.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property
from itertools import product
from math import comb

import numpy as np
import pandas as pd

#: Highest number of factors handled exactly (more factors need quasi-Monte Carlo).
MAX_EXACT_DIM = 3

_QUADRATURE_RTOL = 1e-9  # per plane; the 3-D outer integral uses _OUTER_RTOL
_OUTER_RTOL = 1e-7
_MAX_ROUNDS = 40
_BISECTION_STEPS = 60
_SCAN_POINTS = 65        # slices scanned before golden-section refinement (3 factors)
_GOLDEN_TOL = 1e-11      # in unit coordinates
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
    c2 = coef[..., 2] if coef.shape[-1] > 2 else np.zeros_like(c0)
    with np.errstate(divide="ignore", invalid="ignore"):
        disc = c1 * c1 - 4.0 * c2 * c0
        q = -0.5 * (c1 + np.copysign(np.sqrt(disc), c1))
        roots = np.stack([q / c2, c0 / q], axis=-1)
    roots[disc < 0] = np.nan
    roots[~np.isfinite(roots)] = np.nan
    return roots[..., : coef.shape[-1] - 1]


def _companion_roots(coef: np.ndarray) -> np.ndarray:
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
        real = np.where(np.abs(eig.imag) <= 1e-7 * np.maximum(1.0, np.abs(eig.real)), eig.real, np.nan)
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


def _integrate(func, pieces: np.ndarray, rtol: float, atol: float = 1e-15) -> tuple[np.ndarray, float]:
    """Adaptive integral of a vectorised ``func`` (M,) -> (M, c) over the union of ``pieces`` (P, 2).

    Each piece is mapped by ``s = s0 + h (1 - cos(pi v)) / 2``, which turns square-root ends
    (a line that grazes a curve) into smooth ones, and integrated by Gauss-Kronrod 7-15 in
    ``v``; pieces are bisected until the QUADPACK error estimate meets the tolerance.
    Returns the integrals of the c columns and the summed error estimate of the first column.
    """
    pending = np.asarray(pieces, dtype=float).reshape(-1, 2)
    pending = pending[pending[:, 1] - pending[:, 0] > 1e-15]
    total_length = float(np.sum(pending[:, 1] - pending[:, 0])) or 1.0
    total, error, target = None, 0.0, None
    for rnd in range(_MAX_ROUNDS):
        if not len(pending):
            break
        h = pending[:, 1] - pending[:, 0]
        nodes = pending[:, :1] + h[:, None] * (1 - np.cos(np.pi * _KRONROD_NODES)) / 2
        jac = h[:, None] * np.pi / 2 * np.sin(np.pi * _KRONROD_NODES)
        values = np.asarray(func(nodes.ravel()), dtype=float).reshape(len(pending), 15, -1)
        kronrod = np.einsum("pn,pnc->pc", jac * _KRONROD_WEIGHTS, values)
        gauss = np.einsum("pn,pn->p", jac * _GAUSS_WEIGHTS, values[:, :, 0])
        # QUADPACK's estimate: |K - G| scaled by the integrand's variation on the piece
        mean = kronrod[:, 0] / h
        variation = np.einsum("pn,pn->p", jac * _KRONROD_WEIGHTS, np.abs(values[:, :, 0] - mean[:, None]))
        diff = np.abs(kronrod[:, 0] - gauss)
        with np.errstate(divide="ignore", invalid="ignore"):
            scaled = np.where(variation > 0, variation * np.minimum(1.0, (200 * diff / variation) ** 1.5), diff)
        estimate = np.maximum(scaled, 50 * np.finfo(float).eps * np.abs(kronrod[:, 0]))
        if total is None:
            total = np.zeros(values.shape[2])
            target = max(rtol * abs(float(kronrod[:, 0].sum())), atol)
        last = rnd == _MAX_ROUNDS - 1 or 2 * len(pending) > _MAX_PIECES
        done = (estimate <= target * h / total_length) | (h < 1e-13) | last
        total += kronrod[done].sum(axis=0)
        error += float(estimate[done].sum())
        rest = pending[~done]
        mid = rest.mean(axis=1)
        pending = np.concatenate([np.column_stack([rest[:, 0], mid]), np.column_stack([mid, rest[:, 1]])])
    return (total if total is not None else np.zeros(1)), error


def _golden_min(func, a: float, b: float, anchor: float) -> tuple[float, float]:
    """Minimum of a scalar ``func`` on [a, b] by golden section.

    ``func`` may return inf (an empty slice); when both probes are inf the search moves
    towards ``anchor``, a point known to be feasible.
    """
    ratio = (np.sqrt(5.0) - 1) / 2
    c, d = b - ratio * (b - a), a + ratio * (b - a)
    fc, fd = func(c), func(d)
    while b - a > _GOLDEN_TOL:
        left = fc < fd if (np.isfinite(fc) or np.isfinite(fd)) else anchor < (c + d) / 2
        if left:
            b, d, fd = d, c, fc
            c = b - ratio * (b - a)
            fc = func(c)
        else:
            a, c, fc = c, d, fd
            d = a + ratio * (b - a)
            fd = func(d)
    return (c, fc) if fc <= fd else (d, fd)


# =========================================================================== planes
def _sylvester_det(f: np.ndarray, g: np.ndarray) -> np.ndarray:
    """Resultants (batched over rows) of polynomials with ascending coefficients f (n, p+1), g (n, q+1)."""
    p, q = f.shape[1] - 1, g.shape[1] - 1
    size = p + q
    if size == 0:
        return np.ones(len(f))
    mat = np.zeros((len(f), size, size))
    for i in range(q):
        mat[:, i, i:i + p + 1] = f[:, ::-1]
    for i in range(p):
        mat[:, q + i, i:i + q + 1] = g[:, ::-1]
    return np.linalg.det(mat)


def _unit_roots_of_values(values: np.ndarray, nodes: np.ndarray) -> list[float]:
    """Roots in [0, 1] of the polynomials interpolating ``values`` (n, S) at Chebyshev ``nodes`` (in [-1, 1])."""
    from numpy.polynomial import chebyshev as cheb

    scale = np.max(np.abs(values), axis=0)
    keep = scale > 0
    coef = np.linalg.solve(cheb.chebvander(nodes, len(nodes) - 1), values[:, keep] / scale[keep])
    found = []
    for column in coef.T:
        column = cheb.chebtrim(column, 1e-11 * np.max(np.abs(column)))
        if len(column) < 2:
            continue
        roots = cheb.chebroots(column)
        roots = roots.real[np.abs(roots.imag) <= _ROOT_IMAG_TOL]
        found.extend(((roots[(roots >= -1) & (roots <= 1)] + 1) / 2).tolist())
    return found


class _Plane:
    """The admissible set of residual tensors ``tensor`` (K, D+1, D+1) in the unit square."""

    def __init__(self, tensor: np.ndarray, eps: float):
        self.tensor = tensor
        self.eps = eps
        self._breakpoints: dict[int, np.ndarray] = {}

    def lines(self, axis: int, s) -> _Lines:
        """Lines parallel to ``axis`` at other coordinate(s) ``s``."""
        s = np.atleast_1d(np.asarray(s, dtype=float))
        points = np.zeros((len(s), 2))
        points[:, 1 - axis] = s
        return _Lines.cut(_line_coefficients(self.tensor, axis, points), self.eps)

    def breakpoints(self, axis: int) -> np.ndarray:
        """Sorted values of the other coordinate where the pieces of lines along ``axis`` change."""
        if axis not in self._breakpoints:
            self._breakpoints[axis] = self._find_breakpoints(axis)
        return self._breakpoints[axis]

    def _find_breakpoints(self, axis: int) -> np.ndarray:
        tens = self.tensor if axis == 0 else self.tensor.transpose(0, 2, 1)  # [k, e_t, e_s]
        n_obs, size = tens.shape[:2]
        eps = self.eps
        found = [0.0, 1.0]
        levels = np.array([eps, -eps])
        # roots entering or leaving through the edges t = 0 and t = 1
        for t in (0.0, 1.0):
            edge = np.einsum("t,kts->ks", t ** np.arange(size), tens)
            shifted = np.repeat(edge[:, None, :], 2, axis=1)
            shifted[:, :, 0] -= levels
            roots = _real_roots_unit(shifted)
            found.extend(roots[np.isfinite(roots)].tolist())
        nonzero = tens != 0
        e_t, e_s = np.meshgrid(np.arange(size), np.arange(size), indexing="ij")
        t_degree = [int(e_t[nz].max()) if nz.any() else 0 for nz in nonzero]
        total_degree = [int((e_t + e_s)[nz].max()) if nz.any() else 0 for nz in nonzero]
        top = max(total_degree)
        if max(t_degree) > 0:
            n_nodes = 2 * top * top + 1
            nodes = np.cos(np.pi * (np.arange(n_nodes) + 0.5) / n_nodes)
            s = (nodes + 1) / 2
            coef_t = np.einsum("ns,kts->nkt", s[:, None] ** np.arange(size), tens)
            curves = []
            for k in range(n_obs):
                if t_degree[k] == 0:
                    continue  # curves s = const: their positions are edge roots already
                for level in levels:
                    f = coef_t[:, k, :t_degree[k] + 1].copy()
                    f[:, 0] -= level
                    curves.append((k, f))
            values = []
            for k, f in curves:
                # two roots of one curve merge where the resultant with its t-derivative vanishes
                values.append(_sylvester_det(f, f[:, 1:] * np.arange(1, f.shape[1])))
            for (k1, f1), (k2, f2) in product(curves, curves):
                if k1 < k2:
                    values.append(_sylvester_det(f1, f2))
            if values:
                found.extend(_unit_roots_of_values(np.column_stack(values), nodes))
        points = np.unique(np.clip(found, 0.0, 1.0))
        return points[np.concatenate([[True], np.diff(points) > 1e-14])]

    def piece_feasibility(self, axis: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Breakpoints, piece midpoints and whether the line at each midpoint holds an admissible interval."""
        points = self.breakpoints(axis)
        mids = 0.5 * (points[1:] + points[:-1])
        return points, mids, self.lines(axis, mids).feasible

    def integral(self, axis: int, rtol: float = _QUADRATURE_RTOL) -> tuple[float, float]:
        """Area of the admissible set from exact line lengths, and the quadrature error estimate."""
        points, _, feasible = self.piece_feasibility(axis)
        pieces = np.column_stack([points[:-1], points[1:]])[feasible]
        value, error = _integrate(lambda s: self.lines(axis, s).length[:, None], pieces, rtol)
        return float(value[0]), error

    def span(self, coord: int, polish: bool = True) -> tuple[float, float]:
        """Exact [min, max] of coordinate ``coord`` over the set (NaN when empty)."""
        axis = 1 - coord  # lines across the coordinate
        points, mids, feasible = self.piece_feasibility(axis)
        if not feasible.any():
            return np.nan, np.nan
        first, last = np.flatnonzero(feasible)[[0, -1]]
        lower, upper = points[first], points[last + 1]
        if polish:
            inside = np.array([mids[first], mids[last]])
            outside = np.array([mids[first - 1] if first > 0 else np.nan,
                                mids[last + 1] if last + 1 < len(mids) else np.nan])
            ends = self._bisect(axis, inside, outside)
            lower = ends[0] if first > 0 else 0.0
            upper = ends[1] if last + 1 < len(mids) else 1.0
        return float(lower), float(upper)

    def _bisect(self, axis: int, inside: np.ndarray, outside: np.ndarray) -> np.ndarray:
        """Transitions between feasible lines at ``inside`` and infeasible lines at ``outside`` (NaN: skip)."""
        inside, outside = inside.copy(), np.where(np.isnan(outside), inside, outside)
        for _ in range(_BISECTION_STEPS):
            mid = 0.5 * (inside + outside)
            ok = self.lines(axis, mid).feasible
            inside = np.where(ok, mid, inside)
            outside = np.where(ok, outside, mid)
            if np.max(np.abs(inside - outside)) < 1e-15:
                break
        return inside

    def distance(self, ref: np.ndarray) -> tuple[float, np.ndarray]:
        """Euclidean distance from ``ref`` (2,) to the set and the nearest point (inf, NaN when empty)."""
        points, _, feasible = self.piece_feasibility(0)
        if not feasible.any():
            return np.inf, np.full(2, np.nan)

        def squared(s):
            gap, _ = self.lines(0, s).nearest(ref[0])
            return gap ** 2 + (np.asarray(s) - ref[1]) ** 2

        grid = (1 - np.cos(np.pi * np.linspace(0, 1, 17))) / 2
        best_value, s_best = np.inf, np.nan
        for lo, hi in np.column_stack([points[:-1], points[1:]])[feasible]:
            pad = 1e-12 * (hi - lo)
            s = lo + pad + (hi - lo - 2 * pad) * grid
            vals = squared(s)
            i = int(np.argmin(vals))
            if vals[i] < best_value:
                best_value, s_best = vals[i], s[i]
                x, value = _golden_min(lambda x: float(squared(x)[0]), s[max(i - 1, 0)], s[min(i + 1, 16)], s[i])
                if value < best_value:
                    best_value, s_best = value, x
        _, t_best = self.lines(0, s_best).nearest(ref[0])
        return float(np.sqrt(best_value)), np.array([t_best[0], s_best])


# =========================================================================== three factors
class _Solid:
    """The admissible set of residual tensors (K, D+1, D+1, D+1) in the unit cube, slice by slice."""

    def __init__(self, tensor: np.ndarray, eps: float):
        self.tensor = tensor
        self.eps = eps
        self._planes: dict[tuple[int, float], _Plane] = {}

    def plane(self, axis: int, s: float) -> _Plane:
        """The slice ``u_axis = s``; its coordinates are the other two axes in order."""
        key = (axis, float(s))
        if key not in self._planes:
            powers = float(s) ** np.arange(self.tensor.shape[1])
            self._planes[key] = _Plane(np.tensordot(self.tensor, powers, axes=([axis + 1], [0])), self.eps)
        return self._planes[key]

    @staticmethod
    def _in_plane(axis: int, coord: int) -> int:
        return coord - (coord > axis)

    def span(self, coord: int) -> tuple[float, float]:
        """Minimum and maximum of ``coord`` over slices of another coordinate: scan, then golden section."""
        for axis in (a for a in range(3) if a != coord):
            c = self._in_plane(axis, coord)
            scan = np.linspace(0.0, 1.0, _SCAN_POINTS)
            ends = np.array([self.plane(axis, s).span(c, polish=False) for s in scan])
            if np.isnan(ends[:, 0]).all():
                continue
            result = []
            for sign, column in ((1.0, 0), (-1.0, 1)):
                values = np.where(np.isnan(ends[:, column]), np.inf, sign * ends[:, column])
                i = int(np.argmin(values))

                def end(s, sign=sign, column=column):
                    value = self.plane(axis, s).span(c, polish=False)[column]
                    return np.inf if np.isnan(value) else sign * value

                s_best, _ = _golden_min(end, scan[max(i - 1, 0)], scan[min(i + 1, len(scan) - 1)], scan[i])
                candidates = [(values[i], scan[i]), (end(s_best), s_best)]
                s_best = min(candidates)[1]
                result.append(self.plane(axis, s_best).span(c)[column])
            return result[0], result[1]
        return np.nan, np.nan

    def integral(self, axis: int, lower: float, upper: float) -> tuple[float, float]:
        """Volume by adaptive integration over slices ``u_axis = s`` of exact slice areas."""

        def areas(s):
            out = np.empty((len(s), 2))
            for i, value in enumerate(s):
                out[i] = self.plane(axis, value).integral(0)
            return out

        edges = np.linspace(lower, upper, 9)
        value, error = _integrate(areas, np.column_stack([edges[:-1], edges[1:]]), _OUTER_RTOL)
        return float(value[0]), error + float(value[1])

    def distance(self, ref: np.ndarray, axis: int, lower: float, upper: float) -> tuple[float, np.ndarray]:
        """Distance from ``ref`` (3,) to the set, minimising over slices ``u_axis = s`` in [lower, upper]."""
        rest = np.delete(ref, axis)

        def squared(s):
            d, _ = self.plane(axis, s).distance(rest)
            return d * d + (s - ref[axis]) ** 2

        pad = 1e-12 * (upper - lower)
        scan = np.linspace(lower + pad, upper - pad, 33)
        values = np.array([squared(s) for s in scan])
        i = int(np.argmin(values))
        s_best, best = _golden_min(squared, scan[max(i - 1, 0)], scan[min(i + 1, len(scan) - 1)], scan[i])
        if values[i] < best:
            s_best, best = scan[i], values[i]
        _, point = self.plane(axis, s_best).distance(rest)
        return float(np.sqrt(best)), np.insert(point, axis, s_best)


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
            return _Plane(self.residuals, self.tolerance)
        return _Solid(self.residuals, self.tolerance)

    @cached_property
    def _unit_spans(self) -> np.ndarray:
        shape = self._shape
        if self.dim == 1:
            return np.array([[shape.first[0], shape.last[0]]]) if shape.feasible[0] else np.full((1, 2), np.nan)
        return np.array([shape.span(j) for j in range(self.dim)])

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
            along0, err0 = shape.integral(0)
            along1, err1 = shape.integral(1)
            return along0, err0 + err1 + abs(along0 - along1)
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
        """Estimated absolute error of :attr:`fraction` (quadrature; in 2-D plus the difference of the two line directions)."""
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
            return shape.distance(ref)
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
    return ExactSet(residuals, float(tolerance), lower, upper, names, flags, ref)


def exact_set_for_surrogates(surrogates: dict, observables, targets: dict, tolerance: float,
                             factors_cfg: dict, *, reference: dict | None = None) -> ExactSet:
    """:func:`exact_set` for :class:`demid.surrogate.Surrogate` objects and a material's ``factors`` config.

    Bounds and the reference point are given in actual units (as in the config); log-scale
    factors are converted to their model coordinate (log10) here.
    """
    names = list(factors_cfg)
    log = [factors_cfg[f].get("scale", "linear") == "log" for f in names]

    def model(values):
        values = np.asarray(values, dtype=float)
        return np.where(log, np.log10(values), values)

    for o in observables:
        if list(surrogates[o].factors) != names:
            raise ValueError(f"surrogate '{o}' has factors {surrogates[o].factors}, expected {names}")
    lower = model([factors_cfg[f]["lower"] for f in names])
    upper = model([factors_cfg[f]["upper"] for f in names])
    ref = None if reference is None else model([reference[f] for f in names])
    return exact_set([polynomial_from_surrogate(surrogates[o]) for o in observables],
                     [targets[o] for o in observables], tolerance, lower, upper, reference=ref,
                     factors=names, log=log)

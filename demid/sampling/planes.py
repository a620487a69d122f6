"""The exact admissible sets behind :mod:`demid.sampling.exact`: :class:`Planes`, a batch of planes on the
unit square (lines cut at roots, breakpoints from resultants, adaptive quadrature between them, span ends by
bisection), and :class:`Solid`, three factors as slices that are exact planes.  The method is described in
:mod:`demid.sampling.exact`.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property
from itertools import product

import numpy as np

from .quadrature import argmin_by_owner, integrate, zoom_min
from .roots import Lines, chebyshev_roots, horner, line_coefficients, ragged, real_roots_unit, sylvester_det

QUADRATURE_RTOL = 1e-7  # per plane (QUADPACK estimates are conservative: true errors ~1e-11)
OUTER_RTOL = 1e-6
_BISECTION_STEPS = 60
_SCAN_POINTS = 65        # slices scanned before the zoom refinement (3 factors)


# =========================================================================== planes
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


class Planes:
    """Admissible sets of a batch of planes, residual tensors (P, K, D+1, D+1) on the unit square.

    Pieces of lines along ``axis`` are delimited by breakpoints of the other coordinate; each
    piece is feasible (its lines hold admissible intervals) or not, throughout.
    """

    def __init__(self, tensors: np.ndarray, eps: float):
        self.tensors = tensors
        self.eps = eps
        self.count = tensors.shape[0]
        self._pieces: dict[int, _Pieces] = {}

    def lines(self, axis: int, owners, s) -> Lines:
        """Lines parallel to ``axis`` in planes ``owners`` at other coordinate ``s``."""
        s = np.atleast_1d(np.asarray(s, dtype=float))
        powers = s[:, None] ** np.arange(self.tensors.shape[2])
        spec = "ns,nkts->nkt" if axis == 0 else "ns,nkst->nkt"
        return Lines.cut(np.einsum(spec, powers, self.tensors[np.asarray(owners)]), self.eps)

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
            roots = real_roots_unit(shifted).reshape(n_planes, -1)
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
                roots = (chebyshev_roots(coef) + 1) / 2
                owners.append(np.repeat(rows[keep], roots.shape[1]))
                values.append(roots.ravel())
        return ragged(np.concatenate(owners), np.clip(np.concatenate(values), 0.0, 1.0), n_planes)

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
                    dets.append(sylvester_det(f, f[..., 1:] * np.arange(1, degree + 1)))
        for k1 in range(n_obs):
            for k2 in range(k1 + 1, n_obs):
                pairs = t_degree[:, [k1, k2]]
                for d1, d2 in np.unique(pairs, axis=0):
                    if d1 == 0 or d2 == 0:
                        continue
                    planes = np.flatnonzero((pairs[:, 0] == d1) & (pairs[:, 1] == d2))
                    for l1, l2 in product(levels, levels):
                        rows.append(planes)
                        dets.append(sylvester_det(curve(planes, k1, l1, d1), curve(planes, k2, l2, d2)))
        if not rows:
            return np.empty(0, dtype=int), np.empty((0, n_nodes))
        return np.concatenate(rows), np.concatenate(dets)

    def integral(self, axis: int, rtol: float | None = None) -> tuple[np.ndarray, np.ndarray]:
        """Areas (P,) from exact line lengths, and their quadrature error estimates (P,)."""
        pieces = self.pieces(axis)
        f = pieces.feasible
        total, error = integrate(lambda o, s: self.lines(axis, o, s).length[:, None], pieces.owner[f],
                                 pieces.lower[f], pieces.upper[f], self.count, rtol or QUADRATURE_RTOL)
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
        best = argmin_by_owner(owners, values, self.count)
        has = np.flatnonzero(best >= 0)
        piece, i = np.divmod(best[has], 17)
        s_best, v_best = zoom_min(squared, has, samples[piece, np.maximum(i - 1, 0)],
                                  samples[piece, np.minimum(i + 1, 16)], samples[piece, i], values[best[has]])
        _, t_best = self.lines(0, has, s_best).nearest(ref[0])
        dist[has] = np.sqrt(v_best)
        point[has] = np.column_stack([t_best, s_best])
        return dist, point


# =========================================================================== three factors
class Solid:
    """The admissible set of residual tensors (K, D+1, D+1, D+1) in the unit cube, slice by slice."""

    def __init__(self, tensor: np.ndarray, eps: float):
        self.tensor = tensor
        self.eps = eps

    def planes(self, axis: int, s) -> Planes:
        """The slices ``u_axis = s``; their coordinates are the other two axes in order."""
        s = np.atleast_1d(np.asarray(s, dtype=float))
        moved = np.moveaxis(self.tensor, axis + 1, -1)
        return Planes(np.einsum("pe,kabe->pkab", s[:, None] ** np.arange(self.tensor.shape[1]), moved), self.eps)

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
            coef = line_coefficients(self.tensor, 0, inside[None, :])
            return float(np.max(np.abs(horner(coef, inside[None, :1])))) + float(np.sum(np.abs(u - inside)))

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
            s_best, _ = zoom_min(objective, np.array([0, 1]), scan[np.maximum(i - 1, 0)],
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
        total, error = integrate(areas, np.zeros(8, dtype=int), edges[:-1], edges[1:], 1, OUTER_RTOL, columns=2)
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
        s_best, best = zoom_min(squared, np.array([0]), [scan[max(i - 1, 0)]], [scan[min(i + 1, 32)]],
                                 [scan[i]], [values[i]])
        _, point = self.planes(axis, s_best).distance(rest)
        return float(np.sqrt(best[0])), np.insert(point[0], axis, s_best[0])

"""Adaptive Gauss-Kronrod (7-15) quadrature of many integrals at once, each over its owner's pieces, with
QUADPACK's error estimate; and the minimum of a function per owner by repeated zooming (used by
:mod:`demid.sampling.exact`).
"""

from __future__ import annotations

import numpy as np

_MAX_ROUNDS = 40


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


def integrate(func, owners, lower, upper, n_owners: int, rtol: float, columns: int = 1,
              atol: float = 1e-15) -> tuple[np.ndarray, np.ndarray]:
    """Adaptive integrals of a vectorised ``func(owner, s) -> (M, columns)`` over pieces of owners.

    Piece m covers [lower[m], upper[m]] of owner ``owners[m]``.  Each piece is mapped by
    ``s = s0 + h (1 - cos(pi v)) / 2``, which turns square-root ends (a line grazing a curve)
    into smooth ones, and integrated by Gauss-Kronrod 7-15 in ``v``; pieces are bisected until
    the QUADPACK error estimate meets ``rtol`` of the owner's integral (or ``atol``), for at most
    :data:`_MAX_ROUNDS` rounds; a round whose bisection would leave more than :data:`_MAX_PIECES` pieces
    is the last (exactly :data:`_MAX_PIECES` are still made).  Pieces no longer than 1e-15 are left out.
    Returns integrals (n_owners, columns) and the summed error estimates of the first column (n_owners,).
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


def argmin_by_owner(owners: np.ndarray, values: np.ndarray, n_owners: int) -> np.ndarray:
    """Index of the smallest value of each owner (-1 for owners without entries)."""
    order = np.lexsort((values, owners))
    first = np.ones(len(order), dtype=bool)
    first[1:] = owners[order][1:] != owners[order][:-1]
    out = np.full(n_owners, -1)
    out[owners[order][first]] = order[first]
    return out


def zoom_min(func, owners, lower, upper, best_x, best_value, rounds: int = 11, points: int = 17):
    """Refine per-owner minima of ``func(owner, x)`` by repeatedly sampling the bracket around the best point.

    Each round samples ``points`` points of the bracket and keeps the two steps around the best, so the 11
    rounds of 17 points place the minimiser of a function unimodal in the first bracket to a few 1e-11 of it
    (where the function's values resolve it); a point replaces the best only when its value is strictly smaller.
    """
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

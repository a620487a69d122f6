"""The search domain Omega: a box in search units (actual, or log10 for log-scale factors),
and the one decision between a full grid and scrambled Sobol points (:func:`uses_grid`)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..design import model_units


#: Up to this many factors Omega is evaluated on a full grid; beyond it on scrambled Sobol points.
MAX_GRID_DIM = 3

#: Distance to a search bound, as a fraction of the search range, within which a set or point *touches* it.
BOUND_TOUCH = 0.005
#: Width, as a fraction of the search range, up to which a factor (or a direction of a set) is *identified*;
#: the per-factor verdicts (:mod:`demid.story.verdicts`) and the combinations (:mod:`demid.combinations.axes`)
#: both judge by it, so "identified" and "identified in combination" mean the same width.
IDENTIFIED_MAX_WIDTH = 0.10
#: Width from which a factor is *unresolved* (a direction *free*): the data leave (almost) the whole range open.
UNRESOLVED_MIN_WIDTH = 0.90

#: Values of the ``at_bound`` column: which ends of the search range a set reaches, per factor.
AT_BOUND = ("none", "lower", "upper", "both")

#: The ends each ``at_bound`` value names, lower first.
SIDES_OF = {"none": (), "lower": ("lower",), "upper": ("upper",), "both": ("lower", "upper")}


def uses_grid(dim: int) -> bool:
    """True when a ``dim``-factor domain is evaluated on a full grid, False for Sobol points.

    The only test of :data:`MAX_GRID_DIM`: every grid-or-Sobol branch asks this function.
    """
    return dim <= MAX_GRID_DIM


#: A bound this share of its range inside a physical limit is at it: a bound written rounded (a next wave's box,
#: 6-10 digits) is still at the limit, and no violation of it.
LIMIT_SLACK = 1e-6


def sides_at_limit(bounds: tuple, limits: tuple) -> list[str]:
    """The ends of a factor's search range (lower, upper) that are its physical limits (lower, upper; None:
    none): no value lies beyond them, so a set reaching them is not cut there."""
    slack = LIMIT_SLACK * abs(bounds[1] - bounds[0])
    return [side for side, bound, limit, beyond in zip(("lower", "upper"), bounds, limits, (1.0, -1.0))
            if limit is not None and beyond * (limit - bound) >= -slack]


def search_to_actual(z, log) -> np.ndarray:
    """Search units (log10 for a log-scale factor) to actual units, a copy; ``log`` flags the factors (the last
    axis).  Only the log factors are raised: 10 ** z of a linear factor above about 308 would overflow."""
    z = np.array(z, dtype=float)
    flags = np.broadcast_to(np.array(log, dtype=bool), z.shape)
    z[flags] = 10.0 ** z[flags]
    return z


@dataclass(frozen=True)
class Domain:
    """The search domain Omega: a box in search units (actual, or log10 for log factors)."""

    factors: tuple[str, ...]
    lower: tuple[float, ...]
    upper: tuple[float, ...]
    log: tuple[bool, ...] = ()
    # per factor, its physical limits (lower, upper) in actual units, None where it has none
    limits: tuple[tuple[float | None, float | None], ...] = ()

    def __post_init__(self):
        if not self.log:
            object.__setattr__(self, "log", tuple(False for _ in self.factors))
        if not self.limits:
            object.__setattr__(self, "limits", tuple((None, None) for _ in self.factors))

    def room_beyond(self, factor: str, side: str) -> float:
        """How far the search range of ``factor`` could be widened on ``side`` before its physical limit, as a
        fraction of the range in search units (inf: no limit on that side; a log factor's limit 0 is none)."""
        i = self.factors.index(factor)
        limit = self.limits[i][0 if side == "lower" else 1]
        if limit is None or (self.log[i] and limit <= 0):
            return float("inf")
        lo, hi = self.search_bounds()
        at = float(self.to_search(np.array([[limit if j == i else self.lower[j]
                                              for j in range(self.dim)]], dtype=float))[0, i])
        room = (lo[i] - at) if side == "lower" else (at - hi[i])
        return max(float(room / (hi[i] - lo[i])), 0.0)

    @property
    def dim(self) -> int:
        return len(self.factors)

    def search_bounds(self) -> tuple[np.ndarray, np.ndarray]:
        lo, hi = self.to_search(np.array([self.lower, self.upper]))
        return lo, hi

    def at_bound(self, lower, upper) -> tuple[str, ...]:
        """Per factor, which ends of the search range the span [lower, upper] (actual units) reaches:
        ``none``, ``lower``, ``upper`` or ``both`` (within :data:`BOUND_TOUCH` of the range, in search
        units); ``none`` for an empty span (NaN).  A point is the span [point, point]."""
        lo, hi = self.search_bounds()
        with np.errstate(invalid="ignore", divide="ignore"):
            ends = self.to_search(np.array([lower, upper], dtype=float))
        tol = BOUND_TOUCH * (hi - lo)
        low = ends[0] <= lo + tol
        high = ends[1] >= hi - tol
        return tuple(AT_BOUND[int(a) + 2 * int(b)] for a, b in zip(low, high))

    def to_actual(self, u: np.ndarray) -> np.ndarray:
        return search_to_actual(np.atleast_2d(np.asarray(u, dtype=float)), self.log)

    def to_search(self, x: np.ndarray) -> np.ndarray:
        return model_units(x, self.factors, [f for f, lg in zip(self.factors, self.log) if lg])

    def from_unit(self, u: np.ndarray) -> np.ndarray:
        """Points of the unit cube over the search box (clipped to it), in actual units."""
        lo, hi = self.search_bounds()
        return self.to_actual(lo + np.clip(np.atleast_2d(u), 0.0, 1.0) * (hi - lo))

    def to_unit(self, x: np.ndarray) -> np.ndarray:
        """Points in actual units as coordinates of the unit cube over the search box."""
        lo, hi = self.search_bounds()
        return (self.to_search(np.atleast_2d(x)) - lo) / (hi - lo)

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
        return self.grid(n) if uses_grid(self.dim) else self.sobol(n)

    def grid(self, n: int) -> np.ndarray:
        """All grid nodes in actual units, shape (n**d, d), 'ij' (C) order."""
        out = np.empty((n,) * self.dim + (self.dim,))
        for i, ax in enumerate(self.axes(n)):  # broadcast along the other axes: no tiled copies
            out[..., i] = ax.reshape([n if j == i else 1 for j in range(self.dim)])
        return out.reshape(n ** self.dim, self.dim)

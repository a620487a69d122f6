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
from math import comb
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from .domain import search_to_actual
from .planes import Planes, Solid
from .roots import Lines, horner, line_coefficients

if TYPE_CHECKING:
    from .domain import Domain

#: Highest number of factors handled exactly (more factors need quasi-Monte Carlo).
MAX_EXACT_DIM = 3


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
        return search_to_actual(z, self.log)

    @cached_property
    def _shape(self):
        if self.dim == 1:
            return Lines.cut(self.residuals[None], self.tolerance)
        if self.dim == 2:
            return Planes(self.residuals[None], self.tolerance)
        return Solid(self.residuals, self.tolerance)

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
        # a reference meeting the targets outside the search box is not in the set: its distance is to the box's part
        if self._worst_residual(ref) <= self.tolerance and np.all((ref >= 0.0) & (ref <= 1.0)):
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
        coef = line_coefficients(self.residuals, axis, u[None, :])
        return float(np.max(np.abs(horner(coef, u[None, axis:axis + 1]))))

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

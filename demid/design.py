"""Designed experiments: factor coding, polynomial terms and design-structure checks.

A *term* is a tuple of non-negative integer exponents, one per factor in CSV
column order.  Its name follows the factor column names: ``Intercept``, ``a``,
``a:b``, ``a^2``, ``a^2:b``, ``a:b:c``.
"""

from __future__ import annotations

from dataclasses import dataclass
from itertools import combinations, combinations_with_replacement

import numpy as np

Term = tuple[int, ...]

INTERCEPT = "Intercept"

#: A run whose leverage reaches this (1 to round-off) is fitted exactly whatever its value: its
#: leave-one-out residual, studentised residual and Cook's distance are round-off over round-off.
LEVERAGE_ONE = 1 - 1e-10

#: A run at or above this leverage is one the other runs all but fail to determine the model at: a lone
#: centre run of a rotatable CCD has leverage 1, and 1 - 1e-4 once its printed levels are rounded.
#: Its leave-one-out error, residual / (1 - h), is then over ten residual standard deviations of noise
#: driven by the last printed digit of the levels, so it says nothing about the fit (Q² of -1e5 seen).
LEVERAGE_UNPREDICTABLE = 0.99


def term_name(term: Term, factors: list[str]) -> str:
    parts = []
    for name, power in zip(factors, term):
        if power == 1:
            parts.append(name)
        elif power > 1:
            parts.append(f"{name}^{power}")
    return ":".join(parts) if parts else INTERCEPT


def parse_term(name: str, factors: list[str]) -> Term:
    """Inverse of :func:`term_name`; raises ``ValueError`` for unknown factors."""
    powers = [0] * len(factors)
    if name == INTERCEPT:
        return tuple(powers)
    for part in name.split(":"):
        base, _, power = part.partition("^")
        if base not in factors:
            raise ValueError(f"unknown factor '{base}' in term '{name}'")
        powers[factors.index(base)] += int(power) if power else 1
    return tuple(powers)


def quadratic_terms(n_factors: int) -> list[Term]:
    """Eq. (1): intercept, linear, two-factor interactions, pure quadratics."""
    eye = np.eye(n_factors, dtype=int)
    terms: list[Term] = [tuple([0] * n_factors)]
    terms += [tuple(row) for row in eye]
    terms += [tuple(eye[i] + eye[j]) for i, j in combinations(range(n_factors), 2)]
    terms += [tuple(2 * row) for row in eye]
    return terms


def cubic_terms(n_factors: int) -> list[Term]:
    """All third-order monomials, in a stable order (pure cubes first)."""
    cubes = [tuple(3 * row) for row in np.eye(n_factors, dtype=int)]
    mixed = []
    for combo in combinations_with_replacement(range(n_factors), 3):
        powers = [0] * n_factors
        for i in combo:
            powers[i] += 1
        if max(powers) < 3:
            mixed.append(tuple(powers))
    return cubes + mixed


def model_units(x, factors, log_factors=()) -> np.ndarray:
    """A copy of points ``x`` (n, k) in model units: log10 for the factors in ``log_factors``."""
    z = np.array(x, dtype=float, copy=True, ndmin=2)
    for i, name in enumerate(factors):
        if name in log_factors:
            z[:, i] = np.log10(z[:, i])
    return z


def model_matrix(x: np.ndarray, terms: list[Term]) -> np.ndarray:
    """Columns ``prod_i x_i**term_i`` for points ``x`` of shape (n, k)."""
    cols = np.ascontiguousarray(np.asarray(x, dtype=float).T)  # one contiguous row per factor
    out = np.empty((len(terms), cols.shape[1]))
    for j, term in enumerate(terms):
        row = out[j]
        row.fill(1.0)
        for i, power in enumerate(term):
            if power == 1:
                row *= cols[i]
            elif power > 1:
                row *= cols[i] ** power
    return out.T


@dataclass(frozen=True)
class Coding:
    """Affine map between actual factor units and design (coded) units.

    ``coded = (actual - center) / unit``.  For a CCD with axial distance alpha,
    the factorial points sit at +-1 and the axial points at +-alpha.
    """

    factors: tuple[str, ...]
    center: tuple[float, ...]
    unit: tuple[float, ...]

    @classmethod
    def from_levels(cls, factors, actual: np.ndarray, alpha: float = 1.0) -> "Coding":
        """Centre = mid-range of the table, unit = half-range / alpha."""
        actual = np.asarray(actual, dtype=float)
        lo, hi = actual.min(axis=0), actual.max(axis=0)
        unit = (hi - lo) / (2.0 * alpha)
        unit = np.where(unit > 0, unit, 1.0)
        return cls(tuple(factors), tuple(float(v) for v in (lo + hi) / 2), tuple(float(v) for v in unit))

    def to_coded(self, actual) -> np.ndarray:
        return (np.asarray(actual, dtype=float) - np.array(self.center)) / np.array(self.unit)

    def to_actual(self, coded) -> np.ndarray:
        return np.asarray(coded, dtype=float) * np.array(self.unit) + np.array(self.center)


@dataclass(frozen=True)
class DesignStructure:
    """Counts of point types found in a coded design."""

    n_runs: int
    n_factorial: int
    n_axial: int
    n_center: int
    n_other: int
    alpha: float | None

    def describe(self) -> str:
        return (f"{self.n_runs} runs: {self.n_factorial} factorial, {self.n_axial} axial, "
                f"{self.n_center} centre" + (f", {self.n_other} other" if self.n_other else ""))


def classify_points(coded: np.ndarray, alpha, atol: float = 1e-3) -> np.ndarray:
    """Label each coded point 'center', 'factorial', 'axial', 'edge' (Box-Behnken) or 'other'.

    ``alpha`` is one axial distance or one per factor (a CCD whose levels were rounded to practical values)."""
    coded = np.asarray(coded, dtype=float)
    alpha = np.asarray(alpha, dtype=float)
    labels = []
    for row in coded:
        mag = np.abs(row)
        zero = mag < atol
        one = np.abs(mag - 1) < atol
        ax = np.abs(mag - alpha) < atol * np.maximum(alpha, 1)
        if zero.all():
            labels.append("center")
        elif one.all():
            labels.append("factorial")
        elif zero.sum() == len(row) - 1 and ax.sum() == 1:
            labels.append("axial")
        elif (zero | one).all() and one.sum() == 2:
            labels.append("edge")
        else:
            labels.append("other")
    return np.array(labels)


#: Coded distance within which a table's value is read as a level of its design.
LEVEL_TOLERANCE = 0.02


def unreadable_alpha(alpha: float) -> str | None:
    """Why the levels of a CCD with this axial distance cannot be told apart in its table, or None.

    Closer than twice the level tolerance, axial and factorial levels read as one; beyond its inverse, the
    factorial levels sit within the tolerance of the centre once the axial ones are taken as +-1.
    """
    low, high = 1 + 2 * LEVEL_TOLERANCE, 1 / LEVEL_TOLERANCE
    if 1 < alpha < low:
        return (f"puts the axial levels {alpha - 1:.3g} coded units beyond the factorial ones, too close to tell "
                f"apart; use 1 (face-centred) or at least {low:g}")
    if alpha > high:
        return (f"puts the factorial levels within 1/{alpha:g} of the axial half-range from the centre, too close "
                f"to tell apart; use at most {high:g}")
    return None


def nominal_levels(design_type: str, alpha: float) -> np.ndarray:
    """The coded levels a factor may take in the declared design."""
    if design_type == "ccd":
        return np.array([-alpha, -1.0, 0.0, 1.0, alpha]) if abs(alpha - 1) > 1e-9 else np.array([-1.0, 0.0, 1.0])
    if design_type in ("box_behnken", "factorial"):
        return np.array([-1.0, 0.0, 1.0])
    return np.array([])


def snap_to_levels(coded: np.ndarray, levels: np.ndarray) -> np.ndarray:
    """Each coded value replaced by the nearest of the design's ``levels``."""
    coded = np.asarray(coded, dtype=float)
    return levels[np.argmin(np.abs(coded[..., None] - levels), axis=-1)]


def axial_distances(alpha, n_factors: int) -> np.ndarray:
    """One axial distance per factor from one for all (a declared design) or one per factor (a CCD whose
    levels were rounded to practical values: 1.404 for one factor, 1.429 for another)."""
    return np.broadcast_to(np.asarray(alpha, dtype=float), (n_factors,)).copy()


def factor_levels(design_type: str, alpha, n_factors: int) -> list[np.ndarray]:
    """The coded levels each factor may take in the design (per-factor axial distances allowed)."""
    return [nominal_levels(design_type, float(a)) for a in axial_distances(alpha, n_factors)]


def snap_to_factor_levels(coded: np.ndarray, levels: list[np.ndarray]) -> np.ndarray:
    """Each coded value replaced by the nearest level of its own factor (columns of ``coded``)."""
    coded = np.array(coded, dtype=float, ndmin=2)
    return np.column_stack([snap_to_levels(coded[:, j], lv) for j, lv in enumerate(levels)])


def rotatable_alpha(n_factors: int) -> float:
    return float((2 ** n_factors) ** 0.25)


def ccd_points(n_factors: int, alpha: float | None = None, center_runs: int = 5) -> np.ndarray:
    """Coded CCD points in standard order: factorial, axial, centre."""
    alpha = axial_distances(rotatable_alpha(n_factors) if alpha is None else alpha, n_factors)
    fact = np.array(np.meshgrid(*[[-1.0, 1.0]] * n_factors, indexing="ij")).reshape(n_factors, -1).T
    fact = fact[:, ::-1]  # first factor varies fastest (Yates order)
    axial = np.zeros((2 * n_factors, n_factors))
    for i in range(n_factors):
        axial[2 * i, i] = -alpha[i]
        axial[2 * i + 1, i] = alpha[i]
    return np.vstack([fact, axial, np.zeros((center_runs, n_factors))])


def box_behnken_points(n_factors: int, center_runs: int) -> np.ndarray:
    """Coded Box-Behnken points: a 2^2 factorial on every pair of factors (others at 0), then centres."""
    rows = []
    for i, j in combinations(range(n_factors), 2):
        for a, b in ((-1.0, -1.0), (-1.0, 1.0), (1.0, -1.0), (1.0, 1.0)):
            row = np.zeros(n_factors)
            row[i], row[j] = a, b
            rows.append(row)
    return np.vstack([np.array(rows), np.zeros((center_runs, n_factors))])


#: Coded points equal to this many decimals are one design point: their runs are replicates.  The one rule
#: of the ANOVA's pure error, the criticism's lack of fit and the transcription check's refits.
REPLICATE_DECIMALS = 6


def replicate_keys(coded: np.ndarray) -> np.ndarray:
    """The coded points as the replicate rule compares them (rounded to :data:`REPLICATE_DECIMALS`)."""
    return np.round(np.asarray(coded, dtype=float), REPLICATE_DECIMALS)


def replicate_groups(coded: np.ndarray) -> np.ndarray:
    """Integer group id per run; runs at the same design point (:func:`replicate_keys`) share an id."""
    _, inverse = np.unique(replicate_keys(coded), axis=0, return_inverse=True)
    return inverse.ravel()

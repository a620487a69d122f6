"""Relative residuals (y - y*) / |y*| and their plausibility widening.

A plausibility field is the surrogate's predicted mean with a band of ``z`` standard
deviations (the fitted mean's standard error and the measurement sigma) around it;
with ``z = 0`` it is the plain surrogate.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from ..formulas import relative_error

if TYPE_CHECKING:
    from ..surrogate import Surrogate


def relative_residuals(predictions: dict[str, np.ndarray], targets: dict[str, float],
                       observables) -> np.ndarray:
    """Array (k, n) of (y_k - y_k*) / |y_k*|."""
    return np.stack([relative_error(np.asarray(predictions[o], dtype=float), targets[o]) for o in observables])


# =========================================================================== plausible admissibility
#: The plausible set in words, for the report and the tables' notes (one definition, used for every verdict).
PLAUSIBLE_DEFINITION = (
    "x is plausible when, for every observable k, |ŷₖ(x) − yₖ*| ≤ z·√(seₖ(x)² + σₖ² + δₖ²) "
    "(history matching: se = the surrogate's standard error of its mean prediction, σ = the measurement "
    "standard deviation, δ = an optional model-discrepancy standard deviation). Where a response declares "
    "no σ, its tolerance band is taken as the measurement band: σₖ = εₖ·|yₖ*|/z, so that without surrogate "
    "error the plausible band is the tolerance itself and the strict set lies inside the plausible set. The "
    "tolerance and an assumed σ are never added together.")


@dataclass(frozen=True)
class PlausibilityField:
    """A surrogate-like field whose *strict* admissibility equals plausible admissibility.

    Plausible: ``|yhat(x) - y*| <= H(x) = z sqrt(se(x)^2 + sigma^2 + delta^2)`` with ``se`` the
    standard error of the fitted mean (``se_prediction`` when ``predictive``), ``sigma`` the
    measurement sd (``None``: the tolerance band read as the measurement band, ``sigma = eps |y*| / z``)
    and ``delta`` the model-discrepancy sd (:data:`PLAUSIBLE_DEFINITION`).
    ``predict(x) = y* + (yhat(x) - y*) * b / H(x)`` with ``b = eps |y*|``: ``|predict - y*| <= b``
    iff ``|yhat - y*| <= H``, and the field is smooth, so
    :func:`~demid.sampling.grid.admissible_set` (cell classification, curvature margins, boundary
    refinement) applies unchanged.
    """

    surrogate: Surrogate
    target: float
    tolerance: float
    z: float
    sigma: float | None = None
    predictive: bool = False
    discrepancy: float = 0.0

    @property
    def measurement_sd(self) -> float:
        """The configured sigma, or the tolerance band read as a z-sigma measurement band."""
        if self.sigma is not None:
            return float(self.sigma)
        return self.tolerance * abs(self.target) / self.z if self.z > 0 else 0.0

    def uncertainty(self, points, se=None) -> np.ndarray:
        """sqrt(se^2 + sigma^2 + delta^2); ``se`` replaces the surrogate's own standard error when given."""
        if se is None:
            se = self.surrogate.se_prediction(points) if self.predictive else self.surrogate.se_mean(points)
        return np.sqrt(np.asarray(se, dtype=float) ** 2 + self.measurement_sd ** 2 + self.discrepancy ** 2)

    def half_width(self, points, se=None) -> np.ndarray:
        """H(x): the largest |yhat - y*| that is still plausible."""
        return self.z * self.uncertainty(points, se)

    def predict(self, points) -> np.ndarray:
        yhat = self.surrogate.predict(points)
        if self.z == 0:
            return yhat
        band = self.tolerance * abs(self.target)
        return self.target + (yhat - self.target) * band / np.maximum(self.half_width(points), 1e-300)


@dataclass(frozen=True)
class MeasurementBand:
    """A target's configured measurement sd (``None``: the tolerance is the band) and discrepancy sd."""

    sigma: float | None = None
    discrepancy: float = 0.0


def plausibility_fields(surrogates: dict[str, Surrogate], observables, targets: dict[str, float],
                        tolerance: float, z: float, sigma: dict | None = None,
                        predictive: bool = False) -> dict[str, PlausibilityField]:
    """One :class:`PlausibilityField` per observable.  ``sigma``: per observable its configured
    measurement sd (a number) or a :class:`MeasurementBand` (sd and discrepancy sd); an observable
    missing from it takes its tolerance as the measurement band."""
    fields = {}
    for o in observables:
        band = (sigma or {}).get(o)
        if not isinstance(band, MeasurementBand):
            band = MeasurementBand(None if band is None else float(band))
        fields[o] = PlausibilityField(surrogates[o], float(targets[o]), float(tolerance), float(z), band.sigma,
                                      predictive, float(band.discrepancy))
    return fields


def _fields(surrogates, observables, targets, tolerance, z, sigma) -> dict:
    """The surrogates themselves (strict sets) or their plausibility fields (z > 0)."""
    if z > 0:
        return plausibility_fields(surrogates, observables, targets, tolerance, z, sigma)
    return {o: surrogates[o] for o in observables}


def residual_evaluator(fields, observables, targets):
    """The relative residuals (K, N) of the observables at N points: the one evaluator the estimators share."""
    def evaluate(x):
        return np.stack([relative_error(fields[o].predict(x), targets[o]) for o in observables])
    return evaluate

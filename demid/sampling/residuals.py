"""Relative residuals (y - y*) / |y*| and their robust (plausibility) widening.

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


# =========================================================================== robust admissibility
@dataclass(frozen=True)
class PlausibilityField:
    """A surrogate-like field whose *strict* admissibility equals plausible admissibility.

    ``predict(x) = y* + (yhat(x) - y*) * b / (b + z s(x))`` with ``b = eps |y*|`` and
    ``s = sqrt(se_mean^2 + sigma^2)`` (``se_prediction`` instead of ``se_mean`` when
    ``predictive``).  ``|predict - y*| <= b`` iff ``|yhat - y*| <= b + z s``, and the
    field is smooth, so :func:`~demid.sampling.grid.admissible_set` (cell classification,
    curvature margins, boundary refinement) applies unchanged.
    """

    surrogate: Surrogate
    target: float
    tolerance: float
    z: float
    sigma: float = 0.0
    predictive: bool = False

    def uncertainty(self, points) -> np.ndarray:
        se = self.surrogate.se_prediction(points) if self.predictive else self.surrogate.se_mean(points)
        return np.sqrt(se ** 2 + self.sigma ** 2)

    def predict(self, points) -> np.ndarray:
        yhat = self.surrogate.predict(points)
        band = self.tolerance * abs(self.target)
        if self.z == 0:
            return yhat
        return self.target + (yhat - self.target) * band / (band + self.z * self.uncertainty(points))


def plausibility_fields(surrogates: dict[str, Surrogate], observables, targets: dict[str, float],
                        tolerance: float, z: float, sigma: dict[str, float] | None = None,
                        predictive: bool = False) -> dict[str, PlausibilityField]:
    sigma = sigma or {}
    return {o: PlausibilityField(surrogates[o], float(targets[o]), float(tolerance), float(z),
                                 float(sigma.get(o, 0.0)), predictive) for o in observables}


def _fields(surrogates, observables, targets, tolerance, z, sigma) -> dict:
    """The surrogates themselves (strict sets) or their plausibility fields (z > 0)."""
    if z > 0:
        return plausibility_fields(surrogates, observables, targets, tolerance, z, sigma)
    return {o: surrogates[o] for o in observables}


def _residual_evaluator(fields, observables, targets):
    def evaluate(x):
        return np.stack([relative_error(fields[o].predict(x), targets[o]) for o in observables])
    return evaluate

"""Evaluating admissible sets over the search domain Omega.

``domain`` (the box, its grids and Sobol points), ``residuals`` (the one relative-residual
evaluator), ``grid`` and ``sobol`` (the two estimators), ``polish`` (span ends on the exact
boundary) and ``choice`` (:func:`evaluate_set`, the only place that picks grid or Sobol).
"""

from .choice import MAX_GRID_DIM, evaluate_set, uses_grid
from .domain import Domain
from .grid import AdmissibleSet, CellCount, FractionEstimate, admissible_set, cell_count, fraction_with_error, \
    plane_band_fraction, predict_grid
from .polish import polish_spans
from .residuals import PlausibilityField, plausibility_fields, relative_residuals
from .sobol import SobolFraction, sobol_admissible_set, sobol_fraction

__all__ = ["MAX_GRID_DIM", "AdmissibleSet", "CellCount", "Domain", "FractionEstimate", "PlausibilityField",
           "SobolFraction", "admissible_set", "cell_count", "evaluate_set", "fraction_with_error",
           "plane_band_fraction", "plausibility_fields", "polish_spans", "predict_grid", "relative_residuals",
           "sobol_admissible_set", "sobol_fraction", "uses_grid"]

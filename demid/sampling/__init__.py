"""Evaluating admissible sets over the search domain Omega.

``domain`` (the box, its grids and Sobol points, and :func:`uses_grid`, the one grid-or-Sobol
decision), ``residuals`` (the one relative-residual evaluator and plausibility fields), ``grid``
and ``sobol`` (the two estimators), ``polish`` (span ends on the exact boundary) and ``evaluate``
(:func:`evaluate_set`: the one strict-set evaluator -- exact for polynomial surrogates in up to
3 factors via ``exact``, with its ``planes``, polynomial ``roots`` and adaptive ``quadrature``, else
the estimator :func:`uses_grid` picks).

The estimators (scipy) load on first use (PEP 562), so the workflow's parse step and the
spec import only the domain.
"""

from ..lazy import lazy_exports
from .domain import MAX_GRID_DIM, Domain, uses_grid

_WHERE = {
    "AdmissibleSet": ".grid", "CellCount": ".grid", "FractionEstimate": ".grid", "admissible_set": ".grid",
    "cell_count": ".grid", "fraction_with_error": ".grid", "plane_band_fraction": ".grid", "predict_grid": ".grid",
    "PlausibilityField": ".residuals", "plausibility_fields": ".residuals", "relative_residuals": ".residuals",
    "SobolFraction": ".sobol", "sobol_admissible_set": ".sobol", "sobol_fraction": ".sobol",
    "polish_spans": ".polish", "evaluate_set": ".evaluate", "uses_exact": ".evaluate",
    "ExactSet": ".exact", "exact_set": ".exact",
}

__getattr__, _lazy_names = lazy_exports(__name__, _WHERE)
__all__ = ["MAX_GRID_DIM", "Domain", "uses_grid", *_lazy_names]

"""evaluate_set: one admissible set, on the grid or on Sobol points as :func:`uses_grid` decides."""

from __future__ import annotations

from typing import TYPE_CHECKING

from .domain import uses_grid
from .grid import admissible_set
from .sobol import sobol_admissible_set

if TYPE_CHECKING:
    import pandas as pd

    from ..surrogate import Surrogate
    from .domain import Domain
    from .grid import AdmissibleSet

def evaluate_set(surrogates: dict[str, Surrogate], domain: Domain, observables, targets: dict[str, float],
                 tolerance: float, n: int, predictions: pd.DataFrame | None = None) -> AdmissibleSet:
    """The admissible set of ``observables`` at ``tolerance``: on the n-per-axis grid up to
    :data:`MAX_GRID_DIM` factors, on n scrambled Sobol points beyond.  ``predictions`` are the
    surrogates' values at those evaluation points when the caller already has them."""
    if uses_grid(domain.dim):
        return admissible_set(surrogates, domain, observables, targets, tolerance, n, grid_predictions=predictions)
    return sobol_admissible_set(surrogates, domain, observables, targets, tolerance, n, predictions)

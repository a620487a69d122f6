"""The one decision between a full grid and scrambled Sobol points."""

from __future__ import annotations

from typing import TYPE_CHECKING

from .grid import admissible_set
from .sobol import sobol_admissible_set

if TYPE_CHECKING:
    import pandas as pd

    from ..surrogate import Surrogate
    from .domain import Domain
    from .grid import AdmissibleSet

#: Up to this many factors Omega is evaluated on a full grid; beyond it on scrambled Sobol points.
MAX_GRID_DIM = 3


def uses_grid(dim: int) -> bool:
    """True when a ``dim``-factor domain is evaluated on a full grid, False for Sobol points."""
    return dim <= MAX_GRID_DIM


def evaluate_set(surrogates: dict[str, Surrogate], domain: Domain, observables, targets: dict[str, float],
                 tolerance: float, n: int, predictions: pd.DataFrame | None = None) -> AdmissibleSet:
    """The admissible set of ``observables`` at ``tolerance``: on the n-per-axis grid up to
    :data:`MAX_GRID_DIM` factors, on n scrambled Sobol points beyond.  ``predictions`` are the
    surrogates' values at those evaluation points when the caller already has them."""
    if uses_grid(domain.dim):
        return admissible_set(surrogates, domain, observables, targets, tolerance, n, grid_predictions=predictions)
    return sobol_admissible_set(surrogates, domain, observables, targets, tolerance, n, predictions)

"""Evaluating admissible sets over the search domain: the domain, the relative residuals,
grid and Sobol estimators, span polishing, and the one grid-or-Sobol decision."""

from .choice import MAX_GRID_DIM, uses_grid
from .domain import Domain

__all__ = ["MAX_GRID_DIM", "Domain", "uses_grid"]

"""The one decision between a full grid and scrambled Sobol points."""

#: Up to this many factors Omega is evaluated on a full grid; beyond it on scrambled Sobol points.
MAX_GRID_DIM = 3


def uses_grid(dim: int) -> bool:
    """True when a ``dim``-factor domain is evaluated on a full grid, False for Sobol points."""
    return dim <= MAX_GRID_DIM

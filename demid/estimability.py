"""Whether the full quadratic can be estimated, with residual degrees of freedom, from a table's usable runs,
and, when not, which terms the runs cannot tell apart and what design change would separate them: one
``InputError`` line naming the file and the column."""

from __future__ import annotations

import numpy as np

from .design import model_matrix, quadratic_terms, replicate_keys, term_name
from .errors import InputError


def require_estimable(coded: np.ndarray, usable: np.ndarray, point_types: np.ndarray | None, src: str,
                      column: str, factors: list[str] | None = None) -> None:
    """The full quadratic must be estimable, with residual degrees of freedom, from the usable runs.

    Runs that all lie on one sphere about the design centre (a spherical CCD whose centre runs
    failed or were never made) cannot tell the intercept from the squared terms; a fit would
    return arbitrary coefficients without complaint.  The rank counts the model matrix's singular values
    above 1e-8 of the largest.
    """
    k = coded.shape[1]
    terms = quadratic_terms(k)
    x = coded[usable]
    n, p = len(x), len(terms)
    if n <= p:
        raise InputError(f"only {n} usable runs for a quadratic model with {p} coefficients; at least {p + 1} "
                         f"are needed (with {p} the fit is saturated and says nothing about its error)",
                         source=src, column=column)
    radius = np.sum(x ** 2, axis=1)
    # Printed (rounded) levels put a spherical design only *nearly* on its sphere: test the geometry,
    # not the numerical rank, or the fit returns arbitrary coefficients from the rounding noise.
    if np.ptp(radius) <= 0.01 * max(radius.max(), 1e-300):
        why = ("every usable run lies at the same distance from the design centre, so the intercept and the "
               "squared terms cannot be told apart")
        n_centre = int(np.sum(point_types == "center")) if point_types is not None else 0
        why += (f" (all {n_centre} centre run(s) failed); at least one centre run is needed" if n_centre
                else "; the design needs at least one centre run")
        raise InputError(f"the quadratic model cannot be estimated: {why}", source=src, column=column)
    if point_types is not None and np.any(point_types == "axial"):
        centre = point_types == "center"
        if centre.any() and not np.any(centre & usable):
            # Off the sphere the fit still runs, but its centre is extrapolated from runs at radius >= 1.
            raise InputError(f"the quadratic model cannot be trusted: all {int(centre.sum())} centre run(s) failed, "
                             "so its value at the design centre would be extrapolated from the factorial and axial "
                             "runs; at least one centre run is needed", source=src, column=column)
    matrix = model_matrix(x, terms)
    _, singular, vt = np.linalg.svd(matrix, full_matrices=False)  # n x n left vectors: 800 MB at 10,000 runs
    rank = int(np.sum(singular > 1e-8 * singular[0]))
    if rank < p:
        raise InputError(f"the quadratic model cannot be estimated (rank {rank} of {p} terms): "
                         f"{_confounded_terms(vt[rank:], terms, x, factors)}", source=src, column=column)


def _confounded_terms(null_space: np.ndarray, terms, coded: np.ndarray, factors: list[str] | None) -> str:
    """Which terms the runs cannot tell apart, and what design change would separate them."""
    factors = factors or [f"x{i + 1}" for i in range(coded.shape[1])]
    names = ["intercept" if sum(t) == 0 else term_name(t, factors) for t in terms]
    involved = [n for n, w in zip(names, np.abs(null_space).max(axis=0)) if w > 1e-6]
    # levels told apart as the replicate rule tells design points apart
    few = [f for i, f in enumerate(factors) if len(np.unique(replicate_keys(coded[:, i]))) < 3]
    listed = ", ".join(involved[:-1]) + f" and {involved[-1]}" if len(involved) > 1 else involved[0]
    text = f"the usable runs cannot tell {listed} apart"
    if few:
        return text + f" ({', '.join(few)} at fewer than three levels: a squared term needs three)"
    squares = [n for n in involved if n.endswith("^2")]
    if len(squares) > 1:
        return text + (" (every run away from the centre has its squared terms equal, as in a two-level factorial "
                       "with centre runs); axial runs (a CCD) or a three-level factorial separate them")
    return text

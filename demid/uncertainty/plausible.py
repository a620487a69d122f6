"""Plausible admissibility, history-matching style.

x is plausibly admissible when, for every observable k,
``|yhat_k(x) - y_k*| <= z sqrt(se_mean_k(x)^2 + sigma_k^2 + delta_k^2)``, with ``se_mean`` the
OLS standard error of the fitted mean (statsmodels' ``mean_se``), ``sigma_k`` the measurement
standard deviation of the target (none configured: ``eps |y_k*| / z``, the tolerance as the
measurement band) and ``delta_k`` an optional discrepancy sd
(:data:`~demid.sampling.residuals.PLAUSIBLE_DEFINITION`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from ..sampling import uses_grid
from ..sampling.evaluate import evaluate_set, uses_exact
from ..sampling.grid import admissible_set, fraction_with_error
from ..sampling.polish import polish_spans
from ..sampling.residuals import plausibility_fields
from ..sampling.sobol import sobol_fraction
from ..spec import join_observables

if TYPE_CHECKING:
    from ..sampling import Domain
    from ..sampling.grid import AdmissibleSet
    from ..surrogate import Surrogate


#: Column contracts of the tables this module feeds (the pipeline prepends ``material``).
PLAUSIBLE_COLUMNS = ["scenario", "observables", "tolerance", "z", "factor", "strict_fraction_pct",
                  "robust_fraction_pct", "strict_lower", "strict_upper", "strict_width",
                  "robust_lower", "robust_upper", "robust_width"]


def plausible_admissible_set(surrogates: dict[str, Surrogate], domain: Domain, observables,
                          targets: dict[str, float], tolerance: float, n: int, *, z: float = 2.0,
                          sigma: dict[str, float] | None = None, predictive: bool = False,
                          subdivisions: int | None = None) -> AdmissibleSet:
    """Plausibly admissible set: ``|yhat - y*| <= z sqrt(se_mean^2 + sigma^2 + delta^2)``.

    Same grid, boundary refinement and spans as the strict set; without a configured sigma the
    plausible set contains the strict one point by point (tested).  ``sigma``: per observable its
    configured sd or a :class:`~demid.sampling.residuals.MeasurementBand` (missing: the tolerance
    is the band).  ``best_error`` of the result is ``eps * min_x max_k |yhat - y*| / H``, i.e. the
    smallest implausibility expressed in tolerance units.
    """
    observables = tuple(observables)
    fields = plausibility_fields(surrogates, observables, targets, tolerance, z, sigma, predictive)
    return admissible_set(fields, domain, observables, targets, tolerance, n, subdivisions=subdivisions)


# =========================================================================== tables
@dataclass(frozen=True)
class SetSummary:
    """Fraction (of Omega), its numerical error and the spans of one admissible set."""

    fraction: float
    error: float
    lower: np.ndarray
    upper: np.ndarray
    method: str

    @property
    def width(self) -> np.ndarray:
        return self.upper - self.lower


def summarise_set(surrogates: dict[str, Surrogate], domain: Domain, observables, targets: dict[str, float],
                  tolerance: float, n: int, *, z: float = 0.0, sigma: dict[str, float] | None = None,
                  polish: bool = True, with_error: bool = True, sobol_points: int = 2 ** 16, seed: int = 0,
                  grid_predictions: pd.DataFrame | None = None, grid_set: AdmissibleSet | None = None) -> SetSummary:
    """One strict (z = 0) or plausible set by the method that suits the dimension.

    Strict sets of polynomial surrogates in up to 3 factors: the exact set of
    :func:`~demid.sampling.evaluate.evaluate_set` (``grid_set`` if already computed).
    Otherwise up to 3 factors: :func:`admissible_set` on the n-grid (``grid_set`` if already
    computed), spans polished, error from :func:`fraction_with_error` (``grid_error``).
    More factors: :func:`sobol_fraction` with ``sobol_points`` points; the error is the
    half-width of its 95 % confidence interval.
    """
    observables = tuple(observables)
    if z == 0 and uses_exact(surrogates, observables, domain):
        # the strict set of polynomial surrogates: the one exact evaluator (or the set already computed)
        aset = grid_set if grid_set is not None and grid_set.exact is not None else evaluate_set(
            surrogates, domain, observables, targets, tolerance, n)
        return SetSummary(aset.fraction, aset.fraction_error, aset.lower, aset.upper, aset.method)
    if not uses_grid(domain.dim):
        res = sobol_fraction(surrogates, domain, observables, targets, tolerance, sobol_points, seed,
                             z=z, sigma=sigma, polish=polish)
        return SetSummary(res.fraction, (res.ci_upper - res.ci_lower) / 2, res.lower, res.upper,
                          f"scrambled Sobol, {res.replicates} x {res.points_per_replicate} points")
    aset = grid_set
    if aset is None:
        aset = (admissible_set(surrogates, domain, observables, targets, tolerance, n,
                               grid_predictions=grid_predictions) if z == 0 else
                plausible_admissible_set(surrogates, domain, observables, targets, tolerance, n, z=z, sigma=sigma))
    lower, upper = aset.lower, aset.upper
    if polish:
        lower, upper = polish_spans(surrogates, domain, observables, targets, tolerance, aset, z=z, sigma=sigma)
    error = np.nan
    if with_error:
        preds = grid_predictions if (z == 0 and n % 2 == 1) else None
        error = fraction_with_error(surrogates, domain, observables, targets, tolerance, n, z=z, sigma=sigma,
                                    grid_predictions=preds, reference=aset).grid_error
    return SetSummary(aset.fraction, error, lower, upper, f"grid {n}^{domain.dim} with boundary refinement")


def plausible_identifiability_frame(surrogates: dict[str, Surrogate], domain: Domain, scenarios: dict,
                                 targets: dict[str, float], n: int, *, z: float = 2.0,
                                 sigma: dict[str, float] | None = None, polish: bool = True,
                                 strict_sets: dict[str, AdmissibleSet] | None = None,
                                 sobol_points: int = 2 ** 16, seed: int = 0) -> pd.DataFrame:
    """``robust_identifiability.csv``: strict and plausible sets side by side per scenario and factor.

    ``scenarios``: name -> (observables, tolerance).  ``strict_sets`` (name -> the
    pipeline's strict :class:`AdmissibleSet`) are reused when they were computed on the
    same n-grid.
    ``observables`` may be any iterable of names, read once.  More than 3 factors: ``sobol_points`` scrambled
    Sobol points (2^16 unless given, scramble ``seed`` 0).
    Spans are polished to the exact boundary unless ``polish`` is False.  Trailing
    columns give the numerical error of both fractions (percentage points).
    """
    frames = []
    for name, (observables, tolerance) in scenarios.items():
        observables = tuple(observables)
        common = dict(polish=polish, sobol_points=sobol_points, seed=seed)
        given = (strict_sets or {}).get(name)
        if given is not None and given.exact is None and given.n_nodes != n ** domain.dim:
            given = None  # a grid set on another grid: recompute so that both sets share one grid
        strict = summarise_set(surrogates, domain, observables, targets, tolerance, n, grid_set=given, **common)
        plausible = summarise_set(surrogates, domain, observables, targets, tolerance, n, z=z, sigma=sigma, **common)
        frames.append(pd.DataFrame({
            "scenario": name, "observables": join_observables(observables), "tolerance": float(tolerance),
            "z": float(z), "factor": list(domain.factors),
            "strict_fraction_pct": 100.0 * strict.fraction, "robust_fraction_pct": 100.0 * plausible.fraction,
            "strict_lower": strict.lower, "strict_upper": strict.upper, "strict_width": strict.width,
            "robust_lower": plausible.lower, "robust_upper": plausible.upper, "robust_width": plausible.width,
            "strict_fraction_error_pct": 100.0 * strict.error, "robust_fraction_error_pct": 100.0 * plausible.error,
            "method": strict.method,
        }))
    return pd.concat(frames, ignore_index=True)

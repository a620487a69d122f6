"""Scrambled-Sobol estimator of an admissible set (more than 3 factors).

Randomised QMC fractions with a confidence interval from independent scramblings;
spans from the extreme admissible points, polished to the set boundary.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from .grid import AdmissibleSet, predict_grid
from .polish import _polish
from .residuals import _fields, residual_evaluator, relative_residuals

if TYPE_CHECKING:
    from .domain import Domain
    from ..surrogate import Surrogate
    import pandas as pd


def sobol_admissible_set(surrogates: dict[str, Surrogate], domain: Domain, observables, targets: dict[str, float],
                         tolerance: float, n: int, sample: pd.DataFrame | None = None) -> AdmissibleSet:
    """Eq. (2)-(4) for more than 3 factors: randomised-QMC fraction with a confidence interval
    (:func:`sobol_fraction`), spans polished to the boundary, and the admissible
    points of the evaluation sample for figures."""
    observables = tuple(observables)
    if sample is None:
        sample = predict_grid({o: surrogates[o] for o in observables}, domain, n)
    points = sample[list(domain.factors)].to_numpy()
    resid = relative_residuals({o: sample[o].to_numpy() for o in observables}, targets, observables)
    worst = np.max(np.abs(resid), axis=0)
    mask = worst <= tolerance
    est = sobol_fraction(surrogates, domain, observables, targets, tolerance, n, seed=0)
    best = int(np.argmin(worst))
    return AdmissibleSet(
        observables=observables, tolerance=float(tolerance), factors=tuple(domain.factors), fraction=est.fraction,
        node_fraction=float(mask.mean()), n_nodes=int(mask.size), n_admissible_nodes=int(mask.sum()),
        n_refined_cells=0, lower=np.asarray(est.lower), upper=np.asarray(est.upper), mask=mask,
        best_error=float(worst[best]), best_point=points[best], evaluations=int(est.evaluations + resid.size),
        points=points, fraction_ci=(est.ci_lower, est.ci_upper), fraction_error=(est.ci_upper - est.ci_lower) / 2,
        method="scrambled Sobol")


# =========================================================================== Sobol fraction
@dataclass(frozen=True)
class SobolFraction:
    """Randomised-QMC feasible fraction: mean over independent scrambles with a t interval.

    ``lower``/``upper`` are the spans: the extreme admissible sample points, polished to
    the exact boundary unless ``polish=False``.
    """

    fraction: float
    std_error: float
    ci_lower: float
    ci_upper: float
    confidence: float
    replicates: int
    points_per_replicate: int
    evaluations: int
    lower: np.ndarray
    upper: np.ndarray


def _extreme_points(points: np.ndarray, per_side: int = 3) -> np.ndarray:
    """The ``per_side`` points with the smallest and the largest value of each coordinate."""
    keep = set()
    for i in range(points.shape[1]):
        order = np.argsort(points[:, i])
        keep.update(order[:per_side].tolist())
        keep.update(order[-per_side:].tolist())
    return points[sorted(keep)]


def sobol_fraction(surrogates: dict[str, Surrogate], domain: Domain, observables, targets: dict[str, float],
                   tolerance: float, n_points: int, seed: int, *, replicates: int = 16,
                   confidence: float = 0.95, z: float = 0.0, sigma: dict[str, float] | None = None,
                   polish: bool = True) -> SobolFraction:
    """Feasible fraction from ``replicates`` independently scrambled Sobol sequences.

    Each replicate holds ``2**m`` points with ``2**m * replicates`` as close to
    ``n_points`` as possible; the replicate means are i.i.d. and unbiased, so a Student-t
    interval on them is a valid confidence interval (checked for coverage on a 4-ball).
    Points are uniform in search units.  With ``polish`` the spans are extended to the
    exact boundary from the extreme admissible points as in :func:`polish_spans`.
    """
    # scipy.stats on first use: importing the sampling package (every set job) stays light
    from scipy import stats
    from scipy.stats import qmc

    observables = tuple(observables)
    eps = float(tolerance)
    fields = _fields(surrogates, observables, targets, eps, z, sigma)
    evaluate = residual_evaluator(fields, observables, targets)
    m = max(1, int(round(np.log2(max(n_points / replicates, 2)))))
    rng = np.random.default_rng(seed)
    lo_u, hi_u = domain.search_bounds()
    d = domain.dim
    means = np.empty(replicates)
    extremes = []
    for rep in range(replicates):
        u = lo_u + qmc.Sobol(d, scramble=True, rng=rng).random_base2(m) * (hi_u - lo_u)
        ok = np.all(np.abs(evaluate(domain.to_actual(u))) <= eps, axis=0)
        means[rep] = ok.mean()
        if ok.any():
            extremes.append(_extreme_points(u[ok]))
    fraction = float(means.mean())
    se = float(means.std(ddof=1) / np.sqrt(replicates))
    half = float(stats.t.ppf(0.5 + confidence / 2, replicates - 1)) * se
    if extremes:
        points = domain.to_actual(np.vstack(extremes))
        lower, upper = points.min(axis=0), points.max(axis=0)
        if polish:
            lower, upper = _polish(evaluate, domain, eps, lower, upper, points, starts=3)
    else:
        lower = upper = np.full(d, np.nan)
    return SobolFraction(fraction, se, max(0.0, fraction - half), min(1.0, fraction + half), confidence,
                         replicates, 2 ** m, replicates * 2 ** m * len(observables), lower, upper)

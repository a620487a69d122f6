"""What a next wave of simulations can still buy: the expected contraction of the plausible set.

New runs at points F add F'F / s² to the information of the surrogate's coefficients (s² its residual
variance), so the standard error of the fitted mean becomes ``se_new(x)² = f(x)' (C⁻¹ + F'F / s²)⁻¹ f(x)``
(C the coefficients' covariance).  The predictions themselves are taken as they are (their change is not
known before the runs are made), so the plausible set with ``se_new`` in place of ``se`` is what the wave is
expected to leave: ``contraction = 1 - Φ_new / Φ_now``.  Where the plausible band is set by the measurement
(σ, or the tolerance read as the measurement band) rather than by the surrogate, no run narrows it, and a
contraction below :data:`STOP_CONTRACTION` says: stop simulating this kind of run.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from .design import model_matrix
from .sampling import uses_grid

if TYPE_CHECKING:
    from .scenario import JudgedScenario

#: Expected contraction of the plausible volume below which more runs of this kind are not worth simulating.
STOP_CONTRACTION = 0.10


def _updated_se(surrogate, points: np.ndarray, new_runs: np.ndarray) -> np.ndarray:
    """se of the fitted mean at ``points`` once ``new_runs`` (actual units) are added to the fit."""
    if hasattr(surrogate, "se_mean_after"):  # not a polynomial (demid.kriging): its own update
        return surrogate.se_mean_after(points, new_runs)
    f_new = model_matrix(surrogate.model_units(new_runs), surrogate.terms)
    scale = float(surrogate.resid_var)
    cov = np.asarray(surrogate.covariance, dtype=float)
    if scale <= 0 or not np.any(cov):
        return surrogate.se_mean(points)
    info = np.linalg.pinv(cov) + f_new.T @ f_new / scale
    updated = np.linalg.pinv(info)
    f = model_matrix(surrogate.model_units(points), surrogate.terms)
    return np.sqrt(np.maximum(np.einsum("ij,jk,ik->i", f, updated, f), 0.0))


def _evaluation_points(domain, seed: int = 0) -> np.ndarray:
    lo, hi = domain.search_bounds()
    if uses_grid(domain.dim):
        n = 201 if domain.dim <= 2 else 41
        axes = [np.linspace(a, b, n) for a, b in zip(lo, hi)]
        unit = np.column_stack([g.ravel() for g in np.meshgrid(*axes, indexing="ij")])
    else:
        from scipy.stats import qmc

        unit = lo + qmc.Sobol(domain.dim, scramble=True, seed=seed).random(2 ** 14) * (hi - lo)
    return domain.to_actual(unit)


def expected_contraction(judged: JudgedScenario, new_runs: np.ndarray) -> dict:
    """``{"scenario", "count", "plausible_fraction_pct", "expected_fraction_pct", "expected_contraction",
    "stop"}`` for the wave ``new_runs`` (actual units) and the judged scenario's plausible set."""
    points = _evaluation_points(judged.spec.domain)
    now = judged.contains(points)
    after = judged.contains(points, se={o: _updated_se(field.surrogate, points, new_runs)
                                        for o, field in judged.fields.items()})
    phi_now, phi_after = float(now.mean()), float(after.mean())
    contraction = 1.0 - phi_after / phi_now if phi_now > 0 else float("nan")
    return {"scenario": judged.name, "count": int(len(new_runs)), "plausible_fraction_pct": 100 * phi_now,
            "expected_fraction_pct": 100 * phi_after, "expected_contraction": contraction,
            "stop": bool(np.isfinite(contraction) and contraction < STOP_CONTRACTION)}

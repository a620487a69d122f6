"""Beyond deterministic admissibility: uncertainty, tolerance sweeps, information gain, accuracy.

The admissible set of eq. (2) treats the surrogate as exact and the targets as
known.  This module adds what a calibration decision needs on top of it:

* **Plausible admissibility**, history-matching style: x is plausible when, for every
  observable k, ``|yhat_k(x) - y_k*| <= z sqrt(se_mean_k(x)^2 + sigma_k^2 + delta_k^2)``, with
  ``se_mean`` the OLS standard error of the fitted mean (statsmodels' ``mean_se``), ``sigma_k`` the
  measurement standard deviation of the target (where none is configured, the tolerance band is the
  measurement band: ``sigma_k = eps_k |y_k*| / z``) and ``delta_k`` an optional discrepancy
  (:data:`demid.sampling.residuals.PLAUSIBLE_DEFINITION`, the one definition).
* **Tolerance sweeps** Phi(eps) and spans as functions of eps.
* **Grid posteriors**: a uniform prior on Omega (in search units: log10 for
  log-scale factors) and independent Gaussian likelihoods with variance
  ``sigma_k^2 + se_mean_k(x)^2``; marginal densities, equal-tailed credible
  intervals, posterior means and the information gain KL(posterior || prior)
  in bits, all by trapezoidal quadrature on the grid.
* **Which experiment next**: every non-empty subset of the observables ranked
  by information gain and feasible-fraction contraction (in words: :mod:`demid.story.measurements`).
* **Numerical accuracy**: fractions with an error estimate, spans polished to
  the exact set boundary by SLSQP, and randomised-QMC (scrambled Sobol)
  fractions with a confidence interval for materials with more than 3 factors.

:func:`analyse_material` runs all of it for one configured material with the
grid sizes of :func:`recommended_sizes`.

Modules: ``plausible``, ``sweep``, ``posterior``,
``ranking`` and ``material`` (the per-material step);
figures in :mod:`demid.plots.uncertainty`, estimators in :mod:`demid.sampling`, each scenario judged
(its rescaled surrogates, bands and measurement sigma) in :mod:`demid.scenario`.

Measurement sigma: ``sigma`` (absolute) or ``sigma_rel`` (times |y*|) from the
response's config.  Plausible sets take the tolerance as the measurement band
when neither is configured.  Posteriors need a likelihood width; when neither is
configured the default is ``sigma_rel = tolerance / 2``, i.e. the scenario
tolerance is read as a two-sigma (about 95 %) band; outputs say which basis
was used (``sigma_basis``).
"""

from ..plots.uncertainty import posterior_figure, tolerance_sweep_figure
from ..sampling import (AdmissibleSet, Domain, FractionEstimate, PlausibilityField, SobolFraction, admissible_set,
                        cell_count, fraction_with_error, plane_band_fraction, plausibility_fields, polish_spans,
                        predict_grid, sobol_fraction)
from ..scenario import measurement_sigma, measurement_sigmas, sigma_basis
from ..spec import FALLBACK_TOLERANCE
from .material import MaterialUncertainty, analyse_material, recommended_sizes
from .posterior import (INFORMATION_GAIN_COLUMNS, NO_OBSERVABLE, Posterior, gaussian_loglik, grid_posterior,
                        information_gain_frame, posterior_from_loglik, subset_posteriors)
from .ranking import RANKING_COLUMNS, rank_observable_sets
from .plausible import PLAUSIBLE_COLUMNS, SetSummary, plausible_admissible_set, plausible_identifiability_frame, summarise_set
from .sweep import DEFAULT_SWEEP_TOLERANCES, SWEEP_COLUMNS, tolerance_sweep

__all__ = ["DEFAULT_SWEEP_TOLERANCES", "FALLBACK_TOLERANCE", "INFORMATION_GAIN_COLUMNS", "NO_OBSERVABLE",
           "RANKING_COLUMNS", "PLAUSIBLE_COLUMNS", "SWEEP_COLUMNS", "AdmissibleSet", "Domain", "FractionEstimate",
           "MaterialUncertainty", "PlausibilityField", "Posterior", "SetSummary", "SobolFraction",
           "admissible_set", "analyse_material", "cell_count", "fraction_with_error", "gaussian_loglik",
           "grid_posterior", "information_gain_frame", "measurement_sigma", "measurement_sigmas",
           "plane_band_fraction", "plausibility_fields", "polish_spans",
           "posterior_figure", "posterior_from_loglik", "predict_grid", "rank_observable_sets",
           "recommended_sizes", "plausible_admissible_set", "plausible_identifiability_frame", "sigma_basis",
           "sobol_fraction", "subset_posteriors", "summarise_set", "tolerance_sweep", "tolerance_sweep_figure"]

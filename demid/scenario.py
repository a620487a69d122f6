"""One judged scenario: the surrogates it judges, each observable's band, its strict and plausible sets and
the one test of whether a point is plausible.

A scenario of a material (its observables and tolerance ε) is judged by the fitted surrogates *rescaled* for
each observable's own tolerance (:mod:`demid.tolerance`), and its plausible set widens each observable's
band by the surrogate's standard error, the measurement σ and the discrepancy δ
(:data:`~demid.sampling.residuals.PLAUSIBLE_DEFINITION`).  :class:`JudgedScenario` holds all of it, built
once per scenario as ``JudgedScenario(spec, scenario, surrogates, z)`` and asked many times: the next wave,
the recommended point, the combinations, the wave value, the posteriors, the ranking and the plausible
table all take it instead of re-deriving the rescaled surrogates or the fields.

The measurement σ of a target is here too (:func:`measurement_sigma`): the configured ``sigma`` or
``sigma_rel``, or, where neither is configured, the observable's own tolerance band read as a z-sigma
measurement band -- the same width the plausible set uses, so the posteriors and the ranking judge an
observable with ``tolerance`` or ``tolerance_abs`` by that band, as the sets do.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property
from typing import TYPE_CHECKING

import numpy as np

from .sampling.evaluate import evaluate_set
from .sampling.residuals import MeasurementBand, plausibility_fields
from .spec import Scenario
from .tolerance import has_own_band, observable_band, scenario_grid, scenario_scales, scenario_surrogates

if TYPE_CHECKING:
    from .sampling.grid import AdmissibleSet
    from .spec import MaterialSpec

#: The one membership test's round-off slack: a point is plausible when its implausibility is at most
#: ``1 + MEMBERSHIP_SLACK`` (a point on the band's edge stays in the set whatever the last bit says).
MEMBERSHIP_SLACK = 1e-12


# =========================================================================== measurement sigma
def measurement_sigma(response_cfg: dict | None, target: float, default_rel: float | None = None) -> float:
    """Absolute measurement standard deviation of one target.

    ``sigma`` wins over ``sigma_rel`` (times |target|); without either,
    ``default_rel * |target|`` when a default is given, else 0.
    """
    cfg = response_cfg or {}
    if cfg.get("sigma") is not None:
        return float(cfg["sigma"])
    if cfg.get("sigma_rel") is not None:
        return float(cfg["sigma_rel"]) * abs(float(target))
    if default_rel is not None:
        return float(default_rel) * abs(float(target))
    return 0.0


def sigma_basis(response_cfg: dict | None, default_rel: float | None = None, z: float = 2.0) -> str:
    """Where :func:`measurement_sigma` took its value from, in words for tables."""
    cfg = response_cfg or {}
    if cfg.get("sigma") is not None:
        return f"config sigma = {float(cfg['sigma']):g}"
    if cfg.get("sigma_rel") is not None:
        return f"config sigma_rel = {float(cfg['sigma_rel']):g}"
    if default_rel is not None:
        return f"default sigma_rel = {float(default_rel):g} (tolerance/{z:g})"
    return "none (surrogate uncertainty only)"


def measurement_sigmas(responses_cfg: dict, observables, targets: dict[str, float],
                       tolerance: float | None = None, z: float = 2.0) -> tuple[dict[str, float], dict[str, str]]:
    """Sigma and its basis for each observable; ``tolerance`` enables the default sigma_rel = tolerance / z
    (the tolerance read as a z-sigma measurement band, as in the plausible set)."""
    default_rel = None if tolerance is None else float(tolerance) / float(z)
    sigma = {o: measurement_sigma(responses_cfg.get(o), targets[o], default_rel) for o in observables}
    basis = {o: sigma_basis(responses_cfg.get(o), default_rel, z) for o in observables}
    return sigma, basis


def own_band_basis(response, target: float, tolerance: float, z: float) -> str:
    """The basis of the default σ of an observable with no configured σ: its band (its own tolerance, or
    the scenario's) read as a z-sigma measurement band, in words."""
    if getattr(response, "tolerance_abs", None) is not None:
        sigma = observable_band(response, target, tolerance) / float(z)
        return f"default sigma = {sigma:g} (own tolerance ±{float(response.tolerance_abs):g}/{z:g})"
    if getattr(response, "tolerance", None) is not None:
        return f"default sigma_rel = {float(response.tolerance) / float(z):g} (own tolerance/{z:g})"
    return sigma_basis(None, float(tolerance) / float(z), z)


# =========================================================================== bands and their words
def scenario_bands(spec, observables, tolerance: float) -> dict:
    """Per observable with a configured sigma (or discrepancy), its :class:`MeasurementBand` in the units
    of :func:`~demid.tolerance.scenario_surrogates`; the others take the tolerance as their band."""
    scales = scenario_scales(spec, tolerance)
    out = {}
    for o in observables:
        response = spec.response(o)
        configured = response.sigma is not None or response.sigma_rel is not None
        delta = float(response.discrepancy or 0.0)
        if not configured and delta == 0.0:
            continue
        c = scales.get(o, 1.0)
        sigma = measurement_sigma(response.sigma_config, spec.targets[o]) if configured else None
        out[o] = MeasurementBand(None if sigma is None else c * sigma, c * delta)
    return out


def plausible_basis(spec, observable: str) -> str:
    """Where the plausible band of one observable comes from, in words for the notes."""
    response = spec.response(observable)
    if response.sigma is not None or response.sigma_rel is not None:
        text = sigma_basis(response.sigma_config)
    else:
        text = "no sigma configured: the tolerance band is the measurement band (σ = ε·|y*|/z)"
    if response.tolerance_abs is not None:
        text += f"; own tolerance ±{response.tolerance_abs:g} {response.unit if response.unit != '-' else ''}".rstrip()
    elif response.tolerance is not None:
        text += f"; own tolerance {response.tolerance:g}"
    if response.discrepancy:
        text += f"; discrepancy δ = {response.discrepancy:g}"
    return text


# =========================================================================== the judged scenario
def reference_scenario(spec: MaterialSpec, observables) -> Scenario:
    """The scenario the posteriors and the ranking judge: ``observables`` at the spec's reference tolerance."""
    observables = tuple(observables)
    return Scenario("reference", observables, float(spec.reference_tolerance), "reference")


@dataclass(frozen=True, eq=False)
class JudgedScenario:
    """One scenario of a material, judged: built once, asked many times.

    ``fitted``: the surrogates as fitted (response -> surrogate); ``z``: the plausible set's number of
    standard deviations (``robust_z``).  Every derived quantity is computed on first use and kept.
    """

    spec: MaterialSpec
    scenario: Scenario
    fitted: dict
    z: float

    @property
    def name(self) -> str:
        return self.scenario.name

    @property
    def observables(self) -> tuple[str, ...]:
        return tuple(self.scenario.observables)

    @property
    def tolerance(self) -> float:
        return float(self.scenario.tolerance)

    @property
    def targets(self) -> dict[str, float]:
        return self.spec.targets

    @cached_property
    def surrogates(self) -> dict:
        """The surrogates this scenario judges: rescaled where a response has its own tolerance, so that
        ``|ŷ - y*| <= ε |y*|`` on them is ``|ŷ - y*| <= a_k`` in the response's units."""
        return scenario_surrogates(self.fitted, self.spec, self.tolerance)

    @cached_property
    def bands(self) -> dict:
        """Per observable with a configured σ or δ, its :class:`MeasurementBand` in the units of
        :attr:`surrogates`."""
        return scenario_bands(self.spec, self.observables, self.tolerance)

    @cached_property
    def fields(self) -> dict:
        """One :class:`~demid.sampling.residuals.PlausibilityField` per observable."""
        return plausibility_fields(self.surrogates, self.observables, self.targets, self.tolerance, self.z,
                                   self.bands)

    @cached_property
    def likelihood_sd(self) -> dict[str, float]:
        """Per observable, the measurement σ in the units of :attr:`surrogates`, the posteriors' likelihood
        width: the configured σ, or the observable's band (its own tolerance, else the scenario's) read as a
        z-sigma measurement band -- the plausible set's σ, so that an own tolerance moves the posteriors,
        the information gain and the ranking as it moves the sets."""
        scales = scenario_scales(self.spec, self.tolerance)
        out = {}
        for o in self.observables:
            response, target = self.spec.response(o), self.targets[o]
            own_rel = (observable_band(response, target, self.tolerance) / abs(float(target))
                       if has_own_band(response) and target else self.tolerance)
            out[o] = measurement_sigma(response.sigma_config, target, own_rel / self.z) * scales.get(o, 1.0)
        return out

    @cached_property
    def sigma_basis(self) -> dict[str, str]:
        """Per observable, where :attr:`likelihood_sd` comes from, in words."""
        out = {}
        for o in self.observables:
            response = self.spec.response(o)
            configured = response.sigma_config
            out[o] = (sigma_basis(configured) if configured else
                      own_band_basis(response, self.targets[o], self.tolerance, self.z))
        return out

    def strict_set(self, n: int, predictions=None, **options) -> AdmissibleSet:
        """The strict set: |ŷ - y*| within each observable's band, by
        :func:`~demid.sampling.evaluate.evaluate_set` (``predictions``: the fitted surrogates' values at the
        evaluation points when the caller has them, rescaled here as :attr:`surrogates` are; ``options``:
        ``grid``, ``reference``)."""
        return evaluate_set(self.surrogates, self.spec.domain, self.observables, self.targets, self.tolerance, n,
                            scenario_grid(predictions, self.spec, self.tolerance), **options)

    def plausible_set(self, n: int, **options) -> AdmissibleSet:
        """The plausible set, by the same evaluator on the plausibility fields."""
        return evaluate_set(self.fields, self.spec.domain, self.observables, self.targets, self.tolerance, n,
                            **options)

    def implausibility(self, points, se: dict | None = None, plausible: bool = True) -> np.ndarray:
        """I(x) = max_k |ŷ_k(x) - y_k*| / H_k(x) at ``points`` (actual units), H the plausible half-width
        (``plausible``, z > 0) or the band a_k itself (the strict set).  ``se``: per observable a standard
        error of the mean that replaces the surrogate's own (a planned wave's)."""
        points = np.asarray(points, dtype=float)
        out = np.zeros(len(points))
        for o, field in self.fields.items():
            target = self.targets[o]
            if plausible and self.z > 0:
                half = field.half_width(points, None if se is None else se.get(o))
            else:
                half = self.tolerance * abs(target)
            miss = np.abs(self.surrogates[o].predict(points) - target)
            out = np.maximum(out, miss / np.maximum(half, 1e-300))
        return out

    def contains(self, points, plausible: bool = True, se: dict | None = None) -> np.ndarray:
        """The one membership test: which ``points`` (actual units) lie in the plausible set (``plausible``)
        or in the strict set."""
        return self.implausibility(points, se, plausible) <= 1.0 + MEMBERSHIP_SLACK


def judged_scenarios(spec: MaterialSpec, surrogates: dict, z: float) -> dict[str, JudgedScenario]:
    """Every configured scenario of ``spec``, judged (name -> :class:`JudgedScenario`)."""
    return {sc.name: JudgedScenario(spec, sc, surrogates, z) for sc in spec.scenarios}

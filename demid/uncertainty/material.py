"""Beyond deterministic admissibility, for one configured material.

:func:`analyse_material` runs plausible sets, the tolerance sweep, posteriors and the
observable ranking with the grid sizes of :func:`recommended_sizes`.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import pandas as pd

from ..plots.labels import axis_label, tex_label
from ..plots.uncertainty import posterior_figure, tolerance_sweep_figure
from ..sampling import uses_grid
from ..sampling.evaluate import uses_exact
from ..spec import FALLBACK_TOLERANCE
from .posterior import INFORMATION_GAIN_COLUMNS, information_gain_frame, subset_posteriors
from .ranking import RANKING_COLUMNS, rank_observable_sets
from ..sampling.residuals import PLAUSIBLE_DEFINITION
from .recommended import recommended_point, uninformative_observables
from .plausible import PLAUSIBLE_COLUMNS, plausible_identifiability_frame
from ..scenario import JudgedScenario, judged_scenarios, plausible_basis, reference_scenario
from ..tolerance import has_own_tolerance
from .sweep import DEFAULT_SWEEP_TOLERANCES, SWEEP_COLUMNS, tolerance_sweep

if TYPE_CHECKING:
    from ..sampling.grid import AdmissibleSet
    from ..spec import MaterialSpec
    from ..surrogate import Surrogate


def recommended_sizes(dim: int) -> dict[str, int]:
    """Grid points per axis (Sobol points / histogram bins above 3 factors) per analysis.

    Chosen on demo-like materials so that fractions agree with a 1001-point (2 factors)
    or 201-point (3 factors) grid to < 0.1 % relative, spans are exact after polishing,
    and information gains agree with a 5x finer grid to < 0.01 bit, while the three
    demo materials take a few seconds together.
    """
    if dim <= 2:
        return {"plausible": 401, "sweep": 201, "posterior": 401}
    if uses_grid(dim):
        return {"plausible": 61, "sweep": 41, "posterior": 61}
    return {"plausible": 2 ** 16, "sweep": 2 ** 14, "posterior": 51, "posterior_points": 2 ** 16}


@dataclass
class MaterialUncertainty:
    """Everything :func:`analyse_material` computes for one material."""

    plausible: pd.DataFrame
    sweep: pd.DataFrame
    information_gain: pd.DataFrame
    ranking: pd.DataFrame
    posteriors: dict
    notes: list[str]
    factor_labels: dict[str, str] = field(default_factory=dict)
    scenario_labels: dict[str, str] = field(default_factory=dict)
    unreachable: tuple[str, ...] = ()  # observable sets (d5+d10) with a target out of reach
    observable_labels: dict[str, str] = field(default_factory=dict)  # mathtext, for the legends
    recommended: dict | None = None  # the most robust point of the widest scenario's plausible set
    uninformative: dict[str, str] = field(default_factory=dict)  # observable -> why it says nothing

    @property
    def summary(self) -> dict:
        """``uncertainty/{material}.json``: the notes on sizes and sigmas, the plausible-set definition, the
        recommended point and the uninformative observables (the ranking in words is advice:
        :mod:`demid.story.measurements`)."""
        return {"notes": self.notes, "plausible_definition": PLAUSIBLE_DEFINITION,
                "recommended": self.recommended, "uninformative": dict(self.uninformative)}

    def sweep_figure(self, title: str):
        return tolerance_sweep_figure(self.sweep, title, factor_labels=self.factor_labels,
                                      scenario_labels=self.scenario_labels)

    def posterior_figure(self, title: str):
        return posterior_figure(self.posteriors, title, factor_labels=self.factor_labels,
                                unreachable=self.unreachable, observable_labels=self.observable_labels)


def analyse_material(surrogates: dict[str, Surrogate], spec: MaterialSpec, *, z: float = 2.0,
                     tolerances=DEFAULT_SWEEP_TOLERANCES, sizes: dict[str, int] | None = None,
                     strict_sets: dict[str, AdmissibleSet] | None = None, seed: int = 0,
                     judged: dict[str, JudgedScenario] | None = None) -> MaterialUncertainty:
    """Plausible sets, tolerance sweep, posteriors and the observable ranking for one configured material.

    ``spec`` is the material's :class:`~demid.spec.MaterialSpec` (factors, responses with ``target`` and
    optional ``sigma``/``sigma_rel``, scenarios).  Plausible sets use the
    configured measurement sigma or, when absent, the tolerance band read as a z-sigma measurement band;
    posteriors and the ranking use the same σ at the reference tolerance (the tolerance of the scenario
    with the most observables), an observable's own ``tolerance``/``tolerance_abs`` included
    (:attr:`~demid.scenario.JudgedScenario.likelihood_sd`).  ``notes`` states the
    grid sizes and sigma bases used, for the report.  ``judged``: the scenarios already judged at ``z``
    (:func:`~demid.scenario.judged_scenarios`).
    """
    domain = spec.domain
    targets = {r: t for r, t in spec.targets.items() if r in surrogates}
    sizes = {**recommended_sizes(domain.dim), **(sizes or {})}
    tolerance = spec.reference_tolerance
    observables = list(targets)
    # each scenario judged once (its own-tolerance surrogates, bands, sets); the posteriors and the ranking
    # judge every observable at the reference tolerance, their likelihood width the plausible set's σ
    judged = judged_scenarios(spec, surrogates, z) if judged is None else judged
    reference = JudgedScenario(spec, reference_scenario(spec, observables), surrogates, z)
    at_reference, post_sigma, post_basis = reference.surrogates, reference.likelihood_sd, reference.sigma_basis
    factor_labels = {f.name: axis_label(f) for f in spec.factors}  # mathtext with unit, for the figures

    if strict_sets is None:
        # each scenario's strict set, evaluated once and shared by plausible table, sweep and ranking
        strict_sets = {sc.name: judged[sc.name].strict_set(sizes["plausible"])
                       for sc in spec.scenarios if uses_exact(surrogates, sc.observables, domain)}
    by_observables = {frozenset(sc.observables): strict_sets[sc.name] for sc in spec.scenarios
                      if sc.tolerance == tolerance and sc.name in strict_sets}
    plausible, sweep = _plausible_tables(spec, judged, targets, sizes, z, tolerances, strict_sets, seed)
    points = sizes.get("posterior_points", 2 ** 16)
    posteriors = subset_posteriors(at_reference, domain, observables, targets, post_sigma, sizes["posterior"],
                                   sigma_basis=post_basis, sobol_points=points, seed=seed) if observables else {}
    ranking = (rank_observable_sets(at_reference, domain, observables, targets, post_sigma, tolerance,
                                    sizes["posterior"], posteriors=posteriors, sobol_points=points,
                                    strict_sets=by_observables)
               if observables else pd.DataFrame(columns=RANKING_COLUMNS))
    unreachable = (tuple(ranking.loc[~ranking["targets_reachable"].astype(bool), "observables"])
                   if "targets_reachable" in ranking.columns else ())
    information_gain = (information_gain_frame(posteriors) if posteriors else
                        pd.DataFrame(columns=INFORMATION_GAIN_COLUMNS))
    # one number: a set with a target out of reach has no information gain, in every table
    information_gain.loc[information_gain["observables"].isin(unreachable),
                         ["information_gain_bits", "information_gain_error_bits"]] = float("nan")
    widest = max(spec.scenarios, key=lambda sc: len(sc.observables)) if spec.scenarios else None
    recommended = (recommended_point(judged[widest.name], n=sizes["plausible"])
                   if widest is not None and all(o in surrogates for o in widest.observables) else None)
    uninformative = uninformative_observables(ranking)
    notes = _notes(spec, reference, sizes, strict_sets, unreachable, uninformative)
    return MaterialUncertainty(
        recommended=recommended, uninformative=uninformative, plausible=plausible, sweep=sweep,
        information_gain=information_gain,
        ranking=ranking,
        posteriors=posteriors, notes=notes, factor_labels=factor_labels, unreachable=unreachable,
        scenario_labels={sc.name: sc.label for sc in spec.scenarios if sc.label != sc.name},
        observable_labels={r.name: tex_label(r.label) for r in spec.responses})


def _plausible_tables(spec: MaterialSpec, judged: dict, targets: dict, sizes: dict, z: float, tolerances,
                      strict_sets: dict, seed: int) -> tuple[pd.DataFrame, pd.DataFrame]:
    """The plausible-identifiability table and the tolerance sweep of every judged scenario (empty tables
    without scenarios)."""
    if not spec.scenarios:
        return pd.DataFrame(columns=PLAUSIBLE_COLUMNS), pd.DataFrame(columns=SWEEP_COLUMNS)
    domain = spec.domain
    scenarios = {sc.name: (sc.observables, sc.tolerance) for sc in spec.scenarios}
    plausible = pd.concat([plausible_identifiability_frame(
        judged[sc.name].surrogates, domain, {sc.name: scenarios[sc.name]}, targets,
        sizes["plausible"], z=z, sigma=judged[sc.name].bands, strict_sets=strict_sets,
        sobol_points=sizes["plausible"], seed=seed) for sc in spec.scenarios], ignore_index=True)
    # one sweep for all scenarios, unless an own tolerance makes each scenario's surrogates its own
    groups = ([spec.scenarios] if not has_own_tolerance(spec) else [(sc,) for sc in spec.scenarios])
    sweep = pd.concat([tolerance_sweep(judged[group[0].name].surrogates, domain,
                                       {sc.name: scenarios[sc.name] for sc in group}, targets, tolerances,
                                       sizes["sweep"], sobol_points=sizes["sweep"], seed=seed,
                                       strict_sets=strict_sets) for group in groups], ignore_index=True)
    return plausible, sweep


def _notes(spec: MaterialSpec, reference: JudgedScenario, sizes: dict, strict_sets: dict, unreachable: tuple,
           uninformative: dict) -> list[str]:
    """The grid sizes and σ bases the analysis used, and what it left out, in words for the report."""
    observables, dim, points = reference.observables, spec.domain.dim, sizes.get("posterior_points", 2 ** 16)
    grid_word = "grid points per axis" if uses_grid(dim) else "scrambled Sobol points"
    notes = [
        f"Plausible sets: z = {reference.z:g}; " + "; ".join(f"{o}: {plausible_basis(spec, o)}" for o in observables)
        + ".",
        f"Posteriors and ranking at tolerance {reference.tolerance:g}: "
        + "; ".join(f"{o}: {reference.sigma_basis[o]}" for o in observables) + ".",
        f"Plausible sets on {sizes['plausible']} {grid_word}, sweeps on {sizes['sweep']}, "
        + (f"posteriors on {points} scrambled Sobol points ({sizes['posterior']} histogram bins)."
           if not uses_grid(dim) else f"posteriors on {sizes['posterior']} grid points per axis."),
    ]
    if strict_sets and all(a.exact is not None for a in strict_sets.values()):
        notes.append("Strict sets (identifiability table, the strict columns, the sweep and the ranking): "
                     "exact for the fitted polynomials (roots along lines, span ends by bisection), one evaluation per scenario "
                     "and tolerance.")
    if unreachable:
        notes.append("Sets with targets out of reach (" + ", ".join(unreachable) + "): no point of the search range "
                     "meets their targets within the tolerance (one alone, or all together), so their posterior "
                     "measures the misfit (a discrepancy between simulation and experiment), not information; no "
                     "information gain is given and they rank last.")
    if not spec.scenarios:
        notes.append(f"No scenarios configured: ranking and default sigma use tolerance {FALLBACK_TOLERANCE:g}.")
    if uninformative:
        notes.append("Uninformative observables: " + "; ".join(f"{o}: {why}" for o, why in uninformative.items())
                     + ".")
    return notes

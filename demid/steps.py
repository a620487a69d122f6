"""The per-material step of the workflow and the parts it chains.

:func:`material_step` takes a :class:`~demid.spec.MaterialSpec` and the material's table and
returns one :class:`MaterialAnalysis` whose parts are named after the rule's outputs, so
``scripts/analyse_material.py`` is read -> step -> write.  It chains validation, the fit
(:func:`demid.surrogate.fit_frames`), the scenario sets, the Pareto front, the uncertainty
analysis (:func:`demid.uncertainty.analyse_material`) and the criticism
(:func:`demid.criticism.criticize_material`) in one process: each part is less work than a
Python start-up with the scientific stack.  Every intermediate a later part uses goes through
a parquet round trip first (:func:`demid.io.as_stored`), so it sees exactly the stored file.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

import pandas as pd

if TYPE_CHECKING:
    import numpy as np

    from .design import Coding
    from .spec import MaterialSpec


@dataclass(frozen=True)
class Output:
    """One output of a material's job: its path under the results folder (``{material}``: the material's
    name), and where a figure goes in Snakemake's report (its category and caption file under
    ``workflow/report/``).  ``directory``: a folder of files (the criticism's per-response JSON)."""

    path: str
    category: str | None = None
    caption: str | None = None
    directory: bool = False


#: Every output of a material's job (rules ``analyse_material`` and ``analyse_wave``), by the name both the
#: rule's ``output`` and :class:`MaterialAnalysis` use: the one place these names are written
#: (``workflow/rules/common.smk`` builds the rule's outputs from it).  Each figure is also written as SVG
#: beside its PNG (:func:`output_table`).
MATERIAL_OUTPUTS = {
    "table": Output("validated/{material}.parquet"),
    "validation_summary": Output("validated/{material}.json"),
    "transcription": Output("validated/{material}_transcription.parquet"),
    "fits": Output("fits/{material}.parquet"),
    "statistics": Output("fits/{material}_statistics.parquet"),
    "anova": Output("fits/{material}_anova.parquet"),
    "diagnostics": Output("fits/{material}_diagnostics.parquet"),
    "scenarios": Output("scenarios/{material}.parquet"),
    "sets_figure": Output("figures/sets_{material}.png", "Admissible sets", "sets.rst"),
    "surface_figure": Output("figures/surface_{material}.png", "Response surfaces", "surface.rst"),
    "plausible": Output("uncertainty/{material}_robust.parquet"),
    "sweep": Output("uncertainty/{material}_sweep.parquet"),
    "information_gain": Output("uncertainty/{material}_information_gain.parquet"),
    "ranking": Output("uncertainty/{material}_ranking.parquet"),
    "uncertainty_summary": Output("uncertainty/{material}.json"),
    "sweep_figure": Output("figures/sweep_{material}.png", "Uncertainty", "sweep.rst"),
    "posterior_figure": Output("figures/posterior_{material}.png", "Uncertainty", "posterior.rst"),
    "criticism": Output("criticism/{material}", directory=True),
    "findings": Output("criticism/{material}_findings.parquet"),
    "calibration": Output("criticism/{material}_calibration.parquet"),
    "criticism_summary": Output("criticism/{material}.json"),
    "residuals_figure": Output("figures/residuals_{material}.png", "Model criticism", "residuals.rst"),
    "combinations": Output("combinations/{material}.parquet"),
    "combinations_summary": Output("combinations/{material}.json"),
    "fit_summary": Output("fits/{material}.json"),
    "combinations_figure": Output("figures/combinations_{material}.png", "Identified combinations",
                                  "combinations.rst"),
}

#: The outputs a material that declares ``pareto:`` adds: its front's table and figure.
PARETO_OUTPUTS = {
    "pareto": Output("tables/pareto_{material}.csv"),
    "pareto_figure": Output("figures/pareto_{material}.png", "Pareto trade-off", "pareto.rst"),
}


def output_table(pareto: bool = False) -> dict[str, Output]:
    """A material job's outputs by name (with ``pareto`` the front's too), each figure's SVG beside its PNG
    as ``<name without _figure>_svg`` (:func:`demid.io.save_figures` writes both)."""
    out = {**MATERIAL_OUTPUTS, **(PARETO_OUTPUTS if pareto else {})}
    svgs = {name.removesuffix("_figure") + "_svg": Output(entry.path.removesuffix(".png") + ".svg")
            for name, entry in out.items() if name.endswith("_figure")}
    return {**out, **svgs}


@dataclass
class ValidatedMaterial:
    """The validation part of a material's job: the checked table, the transcription check, the summary JSON
    and the design coding."""

    table: pd.DataFrame
    transcription: pd.DataFrame
    summary: dict
    warnings: list[str]
    coding: Coding  # the design coding validation inferred; the fit and criticism reuse it


def validate_step(spec: MaterialSpec, data: str | Path, *, typo_stop: bool = True) -> ValidatedMaterial:
    """Validate one transcribed table, check it against the published statistics and flag likely
    typos (flags confirmed under ``confirmed_values`` are kept, marked confirmed).  The table's one full
    validation, and the labels' mathtext: the workflow's start-up checks only that the table can be read
    and has its columns.  With
    ``typo_stop`` (a hand-typed table, not a simulated wave) a likely slip stops with InputError."""
    from .config import check_labels
    from .data import read_printed, validate_material
    from .transcription import check_material, likely_typos, refuse_likely_typos, transcription_frame

    check_labels(spec.label_entries())
    validated = validate_material(spec)
    printed = read_printed(data, validated.table)
    if typo_stop:
        refuse_likely_typos(validated, spec, printed)
    checks = check_material(validated, spec, printed)
    typos = likely_typos(validated, spec, printed)
    for flag in typos:
        if (int(flag["run"]), flag["column"]) in spec.confirmed_values:
            flag["confirmed"] = True
            flag["message"] += " (confirmed correct under confirmed_values)"
    summary = validated.summary(spec.name)
    summary["warnings"] += [flag["message"] for flag in typos]
    summary["likely_typos"] = typos
    summary["transcription"] = {r.response: r.to_json() for r in checks}
    return ValidatedMaterial(validated.to_frame(), transcription_frame(checks), summary,
                             list(validated.warnings) + [flag["message"] for flag in typos], validated.coding)


@dataclass
class MaterialSets:
    """Outputs of ``admissibility``: the scenarios table (Table 3 columns, diagnostics and each
    exact set's stored state) and the two figures."""

    scenarios: pd.DataFrame
    figure: object
    surface: object
    pareto: MaterialPareto | None = None
    sets: dict | None = None  # the strict sets with their node masks (the combinations read them)


def admissibility_step(surrogates: dict, spec: MaterialSpec, table: pd.DataFrame,
                       judged: dict | None = None) -> MaterialSets:
    """Every scenario's strict set on the evaluation grid, its overlay figure and the response surfaces
    (and, for a material that declares ``pareto``, its front from the same grid predictions).
    ``judged``: the scenarios judged once (:func:`~demid.scenario.judged_scenarios`)."""
    from .admissibility import evaluate_scenarios, predict_grid
    from .plots import sets_figure, surface_figure_from_surrogates
    from .sampling.stored import set_state_frame
    from .scenario import judged_scenarios

    judged = judged_scenarios(spec, surrogates, 0.0) if judged is None else judged  # strict sets: z unused

    n = spec.grid_points
    used = {o for scen in spec.scenarios for o in scen.observables}
    if spec.pareto:
        used |= {spec.pareto.error_of, spec.pareto.minimise}
    # the responses in the order of the surrogates, whichever subset is predicted: one column each
    grid = predict_grid({r: s for r, s in surrogates.items() if r in used}, spec.domain, n)
    frame, sets = evaluate_scenarios(surrogates, spec, n, grid, judged)
    pareto = pareto_step(surrogates, spec, grid) if spec.pareto else None
    del grid  # the figures need only the node masks; free the dense predictions first
    frame.insert(0, "material", spec.name)
    frame = pd.concat([frame, set_state_frame(sets)], axis=1)
    figure = sets_figure(spec, sets, n, judged)
    return MaterialSets(frame, figure, surface_figure_from_surrogates(surrogates, spec, table), pareto, sets)


@dataclass
class MaterialPareto:
    """Outputs of ``extract_pareto``: the front with its interval rows, and the figure."""

    table: pd.DataFrame
    figure: object


def pareto_step(surrogates: dict, spec: MaterialSpec, grid: pd.DataFrame | None = None) -> MaterialPareto:
    """Non-dominated grid points (error of one observable vs a second objective) and their figure;
    ``grid`` holds the surrogates' predictions on the evaluation grid when already computed."""
    from .admissibility import predict_grid
    from .pareto import front_intervals, pareto_analysis, polish_front
    from .plots import pareto_figure
    from .sampling import uses_grid

    par = spec.pareto
    if grid is None:
        grid = predict_grid(surrogates, spec.domain, spec.grid_points)
    result = pareto_analysis(grid, spec.factor_names, par.error_of, spec.targets[par.error_of], par.minimise,
                             par.max_error)
    if not uses_grid(spec.dim):  # Sobol points leave a sparse front: refine it
        result.front = polish_front(surrogates, spec.domain, spec.factor_names, par.error_of,
                                    spec.targets[par.error_of], par.minimise, par.max_error, result.front)
        result.intervals = front_intervals(result.front, spec.factor_names, par.max_error)
    return MaterialPareto(result.to_frame(), pareto_figure(grid, result.front, spec))


@dataclass
class MaterialCombinationsStep:
    """Outputs of the combinations part: the table, its JSON (statements, curves, advice), the fit
    JSON (canonical analysis per response) and the figure."""

    table: pd.DataFrame
    summary: dict
    fit_summary: dict
    figure: object


def combinations_step(surrogates: dict, spec: MaterialSpec, coding: Coding, fitted: list, strict_sets: dict, *,
                      z: float, ranking: pd.DataFrame | None = None,
                      judged: dict | None = None) -> MaterialCombinationsStep:
    """Every scenario's identified combinations (strict set: the admissibility step's node masks;
    plausible set: the plausible set on the plausible table's grid) and the canonical analysis of every fit.
    ``judged``: the scenarios judged once at ``z`` (:func:`~demid.scenario.judged_scenarios`)."""
    from .canonical import fit_canonical
    from .combinations import material_combinations, plausible_sets
    from .plots import combinations_figure
    from .uncertainty import recommended_sizes

    plausible = plausible_sets(surrogates, spec, z=z, n=recommended_sizes(spec.dim)["plausible"], judged=judged)
    result = material_combinations(surrogates, spec, coding, strict_sets, plausible, ranking)
    fit_summary = {fit.response: {"canonical": fit_canonical(fit).to_json()} for fit in fitted}
    return MaterialCombinationsStep(result.to_frame(), result.to_json(), fit_summary,
                                    combinations_figure(result, spec.label))


@dataclass
class MaterialAnalysis:
    """Outputs of ``analyse_material``, keyed by the rule's output names: tables written as parquet
    (``parquet``) or CSV (``csv``), JSON documents, figures (PNG with an SVG next to it), and the
    criticism's per-response JSON files (``responses``, written into the ``criticism`` folder)."""

    parquet: dict[str, pd.DataFrame]
    csv: dict[str, pd.DataFrame]
    json: dict[str, dict]
    figures: dict[str, object]
    responses: dict[str, dict]
    warnings: list[str]

    def names(self) -> set[str]:
        """The output names this result fills: those of :func:`output_table` but the SVGs, which are
        written beside their PNGs."""
        return {*self.parquet, *self.csv, *self.json, *self.figures, "criticism"}


def _next_box_points(spec: MaterialSpec, plausible: pd.DataFrame) -> np.ndarray | None:
    """Where the criticism chooses the runs it proposes when a next wave will make them: the next box's grid
    (a next wave made by hand keeps only runs inside the box; a simulated one places its design there); None
    without ``next_runs``."""
    if spec.next_runs is None:
        return None
    from .next_wave import box_points, planned_box

    lo, hi, _ = planned_box(spec, plausible)
    return box_points(spec.domain, lo, hi)


def material_step(spec: MaterialSpec, data: str | Path, *, z: float, tolerances,
                  typo_stop: bool = True) -> MaterialAnalysis:
    """One material from its transcribed table to every per-material output: validation and the
    transcription check, the fit, the scenario sets (and Pareto front), uncertainty and criticism."""
    from .criticism import criticize_material
    from .io import as_stored
    from .sampling.stored import stored_strict_sets
    from .scenario import judged_scenarios
    from .surrogate import fit_frames, fit_material, surrogates_from_frame
    from .uncertainty import analyse_material

    validated = validate_step(spec, data, typo_stop=typo_stop)
    table = as_stored(validated.table)
    fitted = fit_material(table, spec, coding=validated.coding)
    fits = fit_frames(fitted)
    surrogates = surrogates_from_frame(as_stored(fits["fits"]), spec.factor_names)
    judged = judged_scenarios(spec, surrogates, z)  # each scenario judged once, asked by every step below
    sets = admissibility_step(surrogates, spec, table, judged)
    scenarios = as_stored(sets.scenarios)
    uncertainty = analyse_material(surrogates, spec, z=z, tolerances=tolerances, judged=judged,
                                   strict_sets=stored_strict_sets(scenarios, judged))
    criticism = criticize_material(table, surrogates, spec, coding=validated.coding,
                                   fits={fit.response: fit for fit in fitted},
                                   strict_sets=stored_strict_sets(scenarios, judged, reference=True),
                                   run_candidates=_next_box_points(spec, uncertainty.plausible),
                                   simulated=not typo_stop)  # a simulated wave: demid made every run itself
    combos = combinations_step(surrogates, spec, validated.coding, fitted, sets.sets or {}, z=z,
                               ranking=uncertainty.ranking, judged=judged)
    figures = {"sets_figure": sets.figure, "surface_figure": sets.surface,
               "combinations_figure": combos.figure,
               "sweep_figure": uncertainty.sweep_figure(spec.label),
               "posterior_figure": uncertainty.posterior_figure(spec.label),
               "residuals_figure": criticism.figure}
    csv = {}
    if sets.pareto is not None:
        figures["pareto_figure"] = sets.pareto.figure
        csv["pareto"] = sets.pareto.table
    parquet = {"table": validated.table, "transcription": validated.transcription, **fits,
               "scenarios": sets.scenarios, "plausible": uncertainty.plausible, "sweep": uncertainty.sweep,
               "information_gain": uncertainty.information_gain, "ranking": uncertainty.ranking,
               "findings": criticism.findings, "calibration": criticism.calibration,
               "combinations": combos.table}
    json = {"validation_summary": validated.summary, "uncertainty_summary": uncertainty.summary,
            "criticism_summary": criticism.summary, "combinations_summary": combos.summary,
            "fit_summary": combos.fit_summary}
    return MaterialAnalysis(parquet, csv, json, figures, criticism.response_json, validated.warnings)


def write_material_analysis(result: MaterialAnalysis, out) -> None:
    """Write a material's outputs to the paths ``out`` names (a Snakemake rule's ``output``, by name)."""
    from .io import save_figures, write_csv, write_json, write_parquet

    def tables():
        for name, frame in result.parquet.items():
            write_parquet(frame, getattr(out, name))
        for name, frame in result.csv.items():
            write_csv(frame, getattr(out, name))
        for name, document in result.json.items():
            write_json(document, getattr(out, name))
        Path(out.criticism).mkdir(parents=True, exist_ok=True)
        for response, document in result.responses.items():
            write_json(document, Path(out.criticism) / f"{response}.json")

    save_figures({getattr(out, name): figure for name, figure in result.figures.items()}, also=tables)

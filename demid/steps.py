"""The per-material steps of the workflow that have no result object of their own elsewhere.

Each step takes a :class:`~demid.spec.MaterialSpec` and what its rule reads, and returns one
result whose fields are named after the rule's outputs, so every ``scripts/*.py`` is read ->
step -> write.  (The fit, uncertainty and criticism steps return theirs from
:func:`demid.surrogate.fit_frames`, :func:`demid.uncertainty.analyse_material` and
:func:`demid.criticism.criticize_material`.)
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

import pandas as pd

if TYPE_CHECKING:
    from .spec import MaterialSpec


@dataclass
class ValidatedMaterial:
    """The validation half of ``validate_and_fit``: the checked table, the transcription check, the summary JSON."""

    table: pd.DataFrame
    transcription: pd.DataFrame
    summary: dict
    warnings: list[str]


def validate_step(spec: MaterialSpec, data: str | Path) -> ValidatedMaterial:
    """Validate one transcribed table, check it against the published statistics and flag likely
    typos (flags confirmed under ``confirmed_values`` are kept, marked confirmed)."""
    from .data import read_printed, validate_material
    from .transcription import check_material, likely_typos, transcription_frame

    validated = validate_material(spec.name, spec.material_config())
    printed = read_printed(data, validated.table)
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
                             list(validated.warnings) + [flag["message"] for flag in typos])


@dataclass
class MaterialSets:
    """Outputs of ``admissibility``: the scenarios table (Table 3 columns, diagnostics and each
    exact set's stored state) and the two figures."""

    scenarios: pd.DataFrame
    figure: object
    surface: object


def admissibility_step(surrogates: dict, spec: MaterialSpec, table: pd.DataFrame) -> MaterialSets:
    """Every scenario's strict set on the evaluation grid, its overlay figure and the response surfaces."""
    from .admissibility import evaluate_scenarios, predict_grid
    from .plots import sets_figure, surface_figure_from_surrogates
    from .sampling.stored import set_state_frame

    n = spec.grid_points
    observed = {o for scen in spec.scenarios for o in scen.observables}  # (not, e.g., a Pareto objective)
    grid = predict_grid({r: s for r, s in surrogates.items() if r in observed}, spec.domain, n)
    frame, sets = evaluate_scenarios(surrogates, spec, n, grid)
    del grid  # the figures need only the node masks; free the dense predictions first
    frame.insert(0, "material", spec.name)
    frame = pd.concat([frame, set_state_frame(sets)], axis=1)
    figure = sets_figure(spec, sets, n, surrogates)
    del sets
    return MaterialSets(frame, figure, surface_figure_from_surrogates(surrogates, spec, table))


@dataclass
class MaterialPareto:
    """Outputs of ``extract_pareto``: the front with its interval rows, and the figure."""

    table: pd.DataFrame
    figure: object


def pareto_step(surrogates: dict, spec: MaterialSpec) -> MaterialPareto:
    """Non-dominated grid points (error of one observable vs a second objective) and their figure."""
    from .admissibility import predict_grid
    from .pareto import pareto_analysis
    from .plots import pareto_figure

    par = spec.pareto
    grid = predict_grid(surrogates, spec.domain, spec.grid_points)
    result = pareto_analysis(grid, spec.factor_names, par.error_of, spec.targets[par.error_of], par.minimise,
                             par.max_error)
    return MaterialPareto(result.to_frame(), pareto_figure(grid, result.front, spec))

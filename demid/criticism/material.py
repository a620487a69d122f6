"""The per-material criticism step: level 1 for every response, the identifiability
effect of any extension, level 2, and where the reference point lies.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from ..data import implausible_targets
from ..formulas import relative_error
from ..plots.criticism import residual_figure
from ..sampling import uses_grid
from ..sampling.evaluate import uses_exact
from ..surrogate import fit_response
from ..scenario import JudgedScenario, reference_scenario
from ..tolerance import relative_tolerances
from .level1 import criticize
from .level2 import calibration_check
from .run_order import assess_run_order

if TYPE_CHECKING:
    from ..design import Coding
    from ..spec import MaterialSpec


# =========================================================================== per-material step
@dataclass
class MaterialCriticism:
    """What the pipeline writes for one material: per-response JSON, tables, summary, figure."""

    response_json: dict[str, dict]
    findings: pd.DataFrame
    calibration: pd.DataFrame
    summary: dict
    figure: object


def _effect_points(n: int, d: int) -> int:
    """Grid points per axis (Sobol points above 3 factors) for the before/after and level-2 searches."""
    if d <= 2:
        return min(n, 401)
    if uses_grid(d):
        return min(n, 61)
    return min(n, 2 ** 14)


class _ScenarioSets:
    """Each scenario's strict set (each observable at its own tolerance), evaluated on first use and then
    shared by every criticism step."""

    def __init__(self, surrogates: dict, spec: MaterialSpec, n: int):
        self.surrogates, self.spec, self.n = surrogates, spec, n
        self.sets: dict = {}

    def __call__(self, scen):
        if scen.name not in self.sets:
            judged = JudgedScenario(self.spec, scen, self.surrogates, 0.0)  # strict sets: z unused
            self.sets[scen.name] = judged.strict_set(self.n, reference=self.spec.reference_point or None)
        return self.sets[scen.name]


def _identifiability_effect(surrogates: dict, extended, response: str, spec: MaterialSpec, n: int,
                            scenario_sets: _ScenarioSets | None = None) -> list[dict]:
    """Feasible fraction and spans of every scenario that uses ``response``, before and after the extension."""
    domain = spec.domain
    scenario_sets = scenario_sets or _ScenarioSets(surrogates, spec, n)
    rows = []
    for scen in spec.scenarios:
        if response not in scen.observables:
            continue
        before = scenario_sets(scen)
        after = JudgedScenario(spec, scen, {**surrogates, response: extended}, 0.0).strict_set(n)
        rows.append({"scenario": scen.name, "fraction_pct_before": 100 * before.fraction,
                     "fraction_pct_after": 100 * after.fraction,
                     "width_before": dict(zip(domain.factors, before.width)),
                     "width_after": dict(zip(domain.factors, after.width))})
    return rows


def reference_point_position(surrogates: dict, spec: MaterialSpec, n: int,
                             scenario_sets: _ScenarioSets | None = None) -> list[dict]:
    """Where the source's chosen point lies relative to each scenario's admissible set.

    ``inside`` is evaluated at the point itself; ``nearest`` is the closest admissible point (of the
    exact set for polynomial surrogates, else the closest admissible grid node)
    (distance in units of the search ranges, in percent, so factors of different scale compare).
    ``spec`` is the material's :class:`~demid.spec.MaterialSpec`.
    """
    ref = spec.reference_point
    if not ref:
        return []
    domain, targets = spec.domain, spec.targets
    scenario_sets = scenario_sets or _ScenarioSets(surrogates, spec, n)
    point = np.array([[ref[f] for f in domain.factors]], dtype=float)
    lo, hi = domain.search_bounds()
    u_ref = (domain.to_search(point)[0] - lo) / (hi - lo)
    rows = []
    for scen in spec.scenarios:
        name, obs = scen.name, scen.observables
        errors = {o: float(relative_error(surrogates[o].predict(point)[0], targets[o])) for o in obs}
        own = relative_tolerances(spec, obs, scen.tolerance)
        inside = all(abs(e) <= own[o] for o, e in errors.items())
        aset = scenario_sets(scen)
        nearest, distance = None, None
        if aset.exact is not None:
            # the exact set: the nearest point of the set itself, not of a grid
            if np.isfinite(aset.exact.reference_distance):  # inf: the set is empty
                nearest = dict(zip(domain.factors, map(float, aset.exact.nearest_point)))
                distance = 0.0 if inside else float(100 * aset.exact.reference_distance)
        elif aset.mask.any():
            nodes = (aset.points if aset.points is not None else domain.grid(n))[aset.mask]
            u = (domain.to_search(nodes) - lo) / (hi - lo)
            k = int(np.argmin(np.sum((u - u_ref) ** 2, axis=1)))
            nearest = dict(zip(domain.factors, map(float, nodes[k])))
            distance = 0.0 if inside else float(100 * np.sqrt(np.sum((u[k] - u_ref) ** 2)))
        rows.append({"scenario": name, "inside": bool(inside), "errors": errors, "nearest_admissible": nearest,
                     "distance_pct_of_range": distance})
    return rows


def material_run_order(table: pd.DataFrame, spec: MaterialSpec, coding):
    """The material's run order, assessed once on every run and response (criticism.run_order)."""
    from ..design import model_units

    coded = coding.to_coded(model_units(table[spec.factor_names].to_numpy(dtype=float), spec.factor_names,
                                        spec.log_factors))
    runs = table["run"].to_numpy() if "run" in table.columns else np.arange(1, len(table) + 1)
    responses = {r: table[r].to_numpy(dtype=float) for r in spec.response_names if r in table.columns}
    return assess_run_order(runs, coded, responses, spec.run_order)


def criticize_material(table: pd.DataFrame, surrogates: dict, spec: MaterialSpec, n: int | None = None,
                       title: str | None = None, strict_sets: dict | None = None,
                       coding: Coding | None = None, fits: dict | None = None,
                       run_candidates: np.ndarray | None = None, simulated: bool = False) -> MaterialCriticism:
    """Level 1 for every response (with the identifiability effect of any extension) and level 2.

    ``spec`` is the material's :class:`~demid.spec.MaterialSpec`; ``n`` and ``title`` default to its evaluation size and label.  ``strict_sets`` (scenario name -> the
    exact strict set the admissibility step stored, with its reference distance) are reused, and so
    are ``coding``, the one validation inferred (None: inferred here the same way), and ``fits``
    (response -> its SurrogateFit in that coding; None: fitted here).  ``run_candidates`` (actual units):
    the points the proposed runs are chosen from (a next wave's box grid; None: the design's levels).
    ``simulated``: the table is demid's own simulations (see :func:`~demid.criticism.level1.criticize`).
    """
    from ..design_check import infer_coding

    n = spec.grid_points if n is None else n
    title = spec.label if title is None else title
    factors, log_factors, alpha = spec.factor_names, spec.log_factors, spec.axial_alpha
    if coding is None:
        coding = infer_coding(table, factors, spec.design, spec.data, log_factors)
    run_order = material_run_order(table, spec, coding)
    # Identifiability before/after is evaluated on a coarser grid than the main one: it is a
    # comparison of two surrogates, and 3-factor grids would otherwise dominate the run time.
    n_effect = _effect_points(n, len(factors))
    n_level2 = n_effect if uses_grid(len(factors)) else max(5, int(2e5 ** (1 / len(factors))))
    scenario_sets = _ScenarioSets(surrogates, spec, n_effect)
    scenario_sets.sets.update(strict_sets or {})
    fits = dict(fits or {})
    for response in spec.response_names:
        if response not in fits:
            fits[response] = fit_response(table, factors, response, coding=coding, log_factors=log_factors)
    response_json, frames, results = {}, [], []
    for response in spec.response_names:
        result = criticize(table, factors, response, alpha=alpha, log_factors=log_factors, run_order=run_order,
                           fit=fits[response], run_candidates=run_candidates, simulated=simulated)
        payload = result.to_json()
        if result.findings:
            payload["identifiability"] = _identifiability_effect(surrogates, result.extended_surrogate(), response,
                                                                 spec, n_effect, scenario_sets)
        response_json[response] = payload
        frame = result.to_frame()
        if frame.empty:  # says "checked, nothing found" rather than looking like a check that never ran
            frame = pd.DataFrame([{"response": response, "cause": "none", "detail": "", "aliases": "",
                                   "message": result.verdict_message, "verdict": result.verdict}],
                                 columns=frame.columns)
        frames.append(frame)
        results.append(result)
    findings = pd.concat(frames, ignore_index=True) if frames else pd.DataFrame()

    targets, domain = spec.targets, spec.domain
    level2 = None
    if targets:
        with_targets = [r for r in targets if r in surrogates]
        same = [sc for sc in spec.scenarios if set(sc.observables) == set(with_targets)
                and sc.tolerance == spec.reference_tolerance]
        strict = None
        if with_targets and same:  # the scenario's own set, exact or sampled: the one identifiability shows
            strict = scenario_sets(same[0])
        elif with_targets and uses_exact(surrogates, with_targets, domain):
            strict = JudgedScenario(spec, reference_scenario(spec, with_targets), surrogates, 0.0).strict_set(n_level2)
        simulated = table[[r for r in spec.response_names if r in table.columns]].notna().any(axis=1)
        level2 = calibration_check({r: surrogates[r] for r in targets}, domain, targets,
                                   spec.reference_tolerance, n_level2, spec.reference_point, strict_set=strict,
                                   runs=table.loc[simulated, factors].to_numpy(dtype=float),
                                   tolerances=relative_tolerances(spec, list(targets), spec.reference_tolerance),
                                   implausible=tuple(implausible_targets(table, targets)))
    calibration = level2.to_frame() if level2 is not None else pd.DataFrame()
    summary = {
        "level1": {r: {"findings": len(p["findings"]), "messages": [f["message"] for f in p["findings"]],
                       "verdict": p["verdict"], "verdict_message": p["verdict_detail"].get("message", ""),
                       "scenarios": [sc.name for sc in spec.scenarios if r in sc.observables]}
                   for r, p in response_json.items()},
        "level2": level2.to_json() if level2 is not None else None,
        "reference_point": reference_point_position(surrogates, spec, n_effect, scenario_sets),
        "run_order": run_order.to_json(),
    }
    figure = residual_figure([fits[r] for r in spec.response_names], results, title,
                             units={r.name: r for r in spec.responses})
    return MaterialCriticism(response_json, findings, calibration, summary, figure)

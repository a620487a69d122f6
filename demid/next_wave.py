"""The next wave of simulations: a refocused search box and the runs to simulate in it.

After a first design, the global quadratic locates the admissible set only roughly.  The next
wave refocuses (history-matching style) on the *plausible* set of one scenario, i.e. the
plausible set of :mod:`demid.uncertainty` (surrogate standard error and measurement sigma
included, ``robust_z`` standard deviations), computed once by the uncertainty step:

* **next domain** = the plausible set's spans, widened by ``margin`` times the current range
  on each side, clipped to the current range (search units: log10 for log-scale factors).
  With an empty plausible set nothing can be refocused and the current range is kept.
* **design runs**: a small design in that box, chosen greedily (D-optimal for the full
  quadratic, given the earlier runs that already lie in the box).  A quarter of them
  (:data:`demid.wave_runs.BOX_SHARE`) come from the box's 5-level grid {-1, -1/2, 0, 1/2, 1}^k (3 levels above
  three factors), so the box's own quadratic is supported at its edges and corners; the rest from
  the grid points of the *band*, the plausible set at twice ``robust_z`` (:data:`BAND_Z_FACTOR`),
  where the set's boundary is decided.  Where the band cannot determine a quadratic (a set on a
  conic), or is empty, the remaining runs come from the box's grid too.
  On the benchmark (``benchmarks/next_wave.py``: 6 simulators x 8 seeds, the user's flow against
  the same number of random runs in the box) the median symmetric-difference ratio is 0.79 with
  35/48 wins (a third of the runs on the box: 0.82, 32/48; all runs on the plausible set: 0.99, 24/48).
* **separating runs**: when the criticism named a missing third-order term that the design
  cannot tell apart from others (an alias set), runs in the box that make each member
  separately estimable (:func:`demid.criticism.separating_runs`, in the box's coding).

The next wave is an ordinary study: bounds = next domain, data = earlier runs inside it plus
the new runs, ``design: {type: custom}``.

A simulated material's waves analyse every run over the search range Omega, so their runs are not held to a
box: :func:`plan_omega_wave` places them anywhere in Omega where they decide the set
(:mod:`demid.boundary_runs`: where the classification is most uncertain, and exploring where the set could
still be), after the criticism's runs and the separating runs, all inside ``count``.

Every step takes the material's :class:`~demid.spec.MaterialSpec`.  The module imports neither scipy nor statsmodels at load time, so the workflow's
parse step can run :func:`check_next_runs`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from . import run_purposes
from .design import quadratic_terms, term_name
from .errors import InputError
from .spec import MaterialSpec, join_observables
from .wave_runs import (candidate_points, deciding_reason, full_rank, aliased_findings,
                        box_support_count, criticism_runs_in_box, d_optimal_augment, deciding_runs, design_count)

if TYPE_CHECKING:
    from .sampling import Domain
    from .scenario import JudgedScenario

DOMAIN_COLUMNS = ["material", "factor", "lower", "upper"]
PURPOSE_DESIGN = ("design: D-optimal quadratic run on the band near the plausible set in the refocused box (where "
                  "the set's boundary is decided)")
PURPOSE_SUPPORT = ("design: D-optimal quadratic run over the whole refocused box (supports its edges and corners, "
                   "so the box's fit does not extrapolate there)")
PURPOSE_DESIGN_BOX = ("design: D-optimal quadratic run in the refocused box, off the plausible set (the plausible "
                      "points alone cannot determine the quadratic)")
# The band: the plausible set at BAND_Z_FACTOR x robust_z, so the band runs straddle the boundary of the
# plausible set instead of sitting inside it (benchmarks/next_wave.py: chosen over 1 and 3).
BAND_Z_FACTOR = 2.0
PURPOSE_SEPARATE = "separate aliased terms {terms} ({responses})"
PURPOSE_BOUNDARY = ("design: where the classification of the set is most uncertain over the search range (the set's "
                    "boundary is decided there)")
PURPOSE_EXPLORE = ("design: where the surrogate is least certain over the search range (a part of the set it "
                   "missed can appear there)")
PURPOSE_DECIDE = run_purposes.DECIDE
PURPOSE_CONFIRM = run_purposes.CONFIRM


@dataclass
class NextWave:
    """Next domain (one row per factor), proposals and a sentence for the report."""

    domain: pd.DataFrame
    runs: pd.DataFrame
    reason: str
    value: dict | None = None  # what the wave can still buy (demid.wave_value.expected_contraction)


def refocus_scenario(spec: MaterialSpec) -> str:
    """The scenario the next wave refocuses on: ``next_runs.scenario``, else the one with the most
    observables (ties: the smallest tolerance, then config order)."""
    if spec.next_runs and spec.next_runs.scenario:
        return spec.next_runs.scenario
    order = {sc.name: i for i, sc in enumerate(spec.scenarios)}
    return min(spec.scenarios, key=lambda sc: (-len(sc.observables), sc.tolerance, order[sc.name])).name


def check_next_runs(config: dict, source: str = "config") -> None:
    """Cross-references of ``next_runs``; raises InputError naming the key."""
    for name, mat in config["materials"].items():
        nr = mat.get("next_runs")
        if not nr:
            continue
        key = f"materials.{name}.next_runs"
        scenarios = mat.get("scenarios") or {}
        if not scenarios:
            raise InputError(f"config key {key}: needs at least one scenario (the set the next wave refocuses on)",
                             source=source)
        if nr.get("scenario") and nr["scenario"] not in scenarios:
            raise InputError(f"config key {key}.scenario: unknown scenario '{nr['scenario']}' "
                             f"(known: {', '.join(scenarios)})", source=source)


def next_box(domain: Domain, plausible_lower, plausible_upper, margin: float) -> tuple[np.ndarray, np.ndarray]:
    """Plausible spans widened by ``margin`` x range per side and clipped, in search units."""
    lo_u, hi_u = domain.search_bounds()
    plausible_lower = np.asarray(plausible_lower, dtype=float)
    if not np.isfinite(plausible_lower).all():
        return lo_u, hi_u
    p_lo = domain.to_search(np.asarray(plausible_lower, dtype=float))[0]
    p_hi = domain.to_search(np.asarray(plausible_upper, dtype=float))[0]
    pad = margin * (hi_u - lo_u)
    return np.maximum(lo_u, p_lo - pad), np.minimum(hi_u, p_hi + pad)


def planned_box(spec: MaterialSpec, plausible: pd.DataFrame) -> tuple[np.ndarray, np.ndarray, bool]:
    """The next box (search units) of a material with ``next_runs``: the plausible spans of its refocus
    scenario (the plausible-identifiability frame) widened by the margin and clipped; and whether the plausible
    set is empty (the range is then kept)."""
    rows = plausible[plausible["scenario"] == refocus_scenario(spec)].set_index("factor").loc[spec.factor_names]
    empty = float(rows["robust_fraction_pct"].iloc[0]) == 0 or not np.isfinite(rows["robust_lower"]).all()
    lo, hi = next_box(spec.domain, rows["robust_lower"].to_numpy(), rows["robust_upper"].to_numpy(),
                      spec.next_runs.margin)
    return lo, hi, empty


def box_points(domain: Domain, lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """The box's grid (the one its design runs come from) in actual units: where the criticism chooses the
    runs a next wave makes, so that they lie where the wave's table keeps them."""
    grid = candidate_points(len(lo))
    return domain.to_actual(lo + (grid + 1.0) / 2.0 * (hi - lo))


def _design(existing: np.ndarray, count: int, k: int, plausible: np.ndarray,
            share: float | None = None) -> tuple[np.ndarray, list[str]]:
    """Design points and their kinds (``support``, ``band``, ``box``).

    Support runs first (a share :data:`~demid.wave_runs.BOX_SHARE` of the runs): D-optimal over the box's 5-level grid
    given the earlier runs, so the box's quadratic is not extrapolated at the box's edges and corners.
    Then D-optimal points on the band (the plausible part of the box) given earlier + support runs.
    Where those cannot determine the box's quadratic (a band thin enough to lie on a conic), the missing
    coefficients get runs from the box's grid (``box``).  Without band points every run comes from the grid."""
    if not len(plausible):
        return d_optimal_augment(existing, count, k), ["support"] * count
    support = d_optimal_augment(existing, box_support_count(count, share), k)
    base = np.vstack([existing, support])
    n_band = count - len(support)
    band = d_optimal_augment(base, n_band, k, plausible)
    short = min(full_rank(np.vstack([base, band]), k), n_band)
    if short:
        band = d_optimal_augment(base, n_band - short, k, plausible)
        band = np.vstack([band, d_optimal_augment(np.vstack([base, band]), short, k)])
    return (np.vstack([support, band]).reshape(-1, k),
            ["support"] * len(support) + ["band"] * (n_band - short) + ["box"] * short)


def propose_runs(box_lower: np.ndarray, box_upper: np.ndarray, earlier: np.ndarray, count: int,
                 alias_sets=(), plausible=None, share: float | None = None) -> tuple[np.ndarray, list]:
    """Proposals (search units) and, per proposal, its kind (``support``, ``band`` or ``box``, see
    :func:`_design`) or the (members, responses) alias set it separates.  ``earlier``: earlier runs
    (search units) inside the box.

    Separating runs are chosen after the design, given earlier + design runs; the design gives up
    as many of the ``count`` runs as the separation needs.
    """
    from .criticism import separating_runs

    k = len(box_lower)
    center, half = (box_lower + box_upper) / 2, (box_upper - box_lower) / 2
    existing = (np.asarray(earlier, dtype=float).reshape(-1, k) - center) / half
    plausible = (np.empty((0, k)) if plausible is None else (np.asarray(plausible).reshape(-1, k) - center) / half)
    base = quadratic_terms(k)
    for reserved in range(count + 1):
        design, kinds = _design(existing, count - reserved, k, plausible, share)
        separating, labels = [], []
        for members, responses in alias_sets:
            pts = separating_runs(np.vstack([existing, design] + separating), base, list(members), 1.0)
            separating += list(pts)
            labels += [(members, responses)] * len(pts)
        if len(separating) <= reserved:
            break
    separating, labels = separating[:count], labels[:count]
    fill = d_optimal_augment(np.vstack([existing, design] + separating), count - len(design) - len(separating), k)
    points = np.vstack([design] + [np.reshape(p, (1, k)) for p in separating] + [fill])
    return center + points * half, list(kinds) + labels + ["support"] * len(fill)


def plausible_points(judged: JudgedScenario, lo: np.ndarray, hi: np.ndarray, n: int = 41) -> np.ndarray:
    """Points of an n^k grid of the box (search units) in the judged scenario's plausible set."""
    k = len(lo)
    n = n if k <= 2 else max(5, int(round(4096 ** (1 / k))))
    axes = [np.linspace(a, b, n) for a, b in zip(lo, hi)]
    grid_u = np.column_stack([g.ravel() for g in np.meshgrid(*axes, indexing="ij")])
    return grid_u[judged.contains(judged.spec.domain.to_actual(grid_u))]


def _box_reason(spec: MaterialSpec, refocus, lo, hi, lower_actual, upper_actual, empty: bool) -> str:
    """How the next box was found, in words: refocused (the factors it narrows), or the range kept."""
    scenario, observables = refocus.name, join_observables(refocus.observables)
    cur_lo, cur_hi = spec.domain.search_bounds()
    narrowed = [f"{f} {a:.4g}–{b:.4g}" for f, a, b, u0, u1, v0, v1 in
                zip(spec.factor_names, lower_actual, upper_actual, lo, hi, cur_lo, cur_hi)
                if u0 > v0 + 1e-12 * (v1 - v0) or u1 < v1 - 1e-12 * (v1 - v0)]
    if empty:
        return f"Scenario '{scenario}' ({observables}) has no plausible point, so the current range is kept"
    if narrowed:
        return (f"Refocused on the plausible set of scenario '{scenario}' ({observables}) with a margin of "
                f"{spec.next_runs.margin:g} of the range: " + ", ".join(narrowed))
    return (f"The plausible set of scenario '{scenario}' ({observables}) reaches (within the margin) every "
            f"edge of the current range, so the range is kept")


def _wave_value(judged: JudgedScenario, lo: np.ndarray, hi: np.ndarray, points: np.ndarray, n_deciding: int,
                earlier_inside: np.ndarray, n_design: int, alias_sets, aim: bool) -> dict:
    """What the wave can still buy (:func:`~demid.wave_value.expected_contraction`).

    With ``aim`` it is judged on the same number of runs all aimed at the plausible set (at robust_z, no
    support runs): the support runs and the wider band make the box's own refit trustworthy, which the
    current surrogate's standard error cannot credit, so counting them would advise stopping only because
    part of the runs is not aimed at the set."""
    from .wave_value import expected_contraction

    if not aim:
        return expected_contraction(judged, points)
    domain = judged.spec.domain
    aimed = plausible_points(judged, lo, hi)
    band_u = propose_runs(lo, hi, earlier_inside, n_design, alias_sets, aimed, share=0.0)[0]
    wave_runs = domain.to_actual(band_u)
    if n_deciding:
        wave_runs = np.vstack([points[:n_deciding], wave_runs])
    return expected_contraction(judged, wave_runs)


def plan_next_wave(material: str, table: pd.DataFrame, surrogates: dict, spec: MaterialSpec,
                   plausible: pd.DataFrame, findings: pd.DataFrame | None = None, *, z: float,
                   analysed_over_omega: bool = False) -> NextWave:
    """The next domain and runs of one material with ``next_runs``.

    ``spec``: the material's :class:`~demid.spec.MaterialSpec`.
    ``plausible``: the material's plausible-identifiability frame (:func:`demid.uncertainty.analyse_material`);
    its plausible spans of the refocus scenario are used as they are.  ``findings``: the material's
    criticism findings (missing terms with aliases get separating runs).  ``z``: the config's
    ``robust_z``, the same as for the plausible set, so that the plausible grid points used for the
    design are those of that set.  ``analysed_over_omega``: the next wave analyses every run over the search
    range (a simulated material's waves), so the criticism's runs outside the box are made too; by hand the
    next wave is studied in the box and they are left out.
    """
    if analysed_over_omega:
        return plan_omega_wave(material, table, surrogates, spec, findings, z=z)
    request = spec.next_runs
    factors = spec.factor_names
    domain = spec.domain
    scenario = refocus_scenario(spec)
    lo, hi, empty = planned_box(spec, plausible)
    lower_actual, upper_actual = domain.to_actual(lo)[0], domain.to_actual(hi)[0]
    dom_frame = pd.DataFrame({"material": material, "factor": factors, "lower": lower_actual,
                              "upper": upper_actual})

    earlier_u = domain.to_search(table[factors].to_numpy(dtype=float))
    inside = np.all((earlier_u >= lo - 1e-12 * (hi - lo)) & (earlier_u <= hi + 1e-12 * (hi - lo)), axis=1)
    alias_sets = aliased_findings(findings, factors)
    from .scenario import JudgedScenario

    # first: they decide what the surrogate can be trusted with; inside the wave's count, not on top of it
    proposed = deciding_runs(findings, factors)
    deciding, left_out = criticism_runs_in_box(proposed, factors, domain, lo, hi)  # over Omega: plan_omega_wave
    n_design = design_count(request.count, len(deciding), earlier_u[inside], lo, hi)
    over_budget = len(deciding) - (request.count - n_design)
    deciding = deciding[:request.count - n_design]
    refocus = next(sc for sc in spec.scenarios if sc.name == scenario)
    judged = JudgedScenario(spec, refocus, surrogates, z)  # the plausible set; its band at twice z below
    cands = plausible_points(JudgedScenario(spec, refocus, surrogates, BAND_Z_FACTOR * z), lo, hi)
    points_u, labels = propose_runs(lo, hi, earlier_u[inside], n_design, alias_sets, cands)
    points = domain.to_actual(points_u)
    cand_u = np.asarray(cands, dtype=float).reshape(-1, len(factors))
    kind_purpose = {"band": PURPOSE_DESIGN, "box": PURPOSE_DESIGN_BOX, "support": PURPOSE_SUPPORT}
    purposes = [kind_purpose[lab] if isinstance(lab, str) else
                PURPOSE_SEPARATE.format(terms=" = ".join(term_name(t, factors) for t in lab[0]),
                                        responses=", ".join(lab[1])) for lab in labels]
    if deciding:
        points = np.vstack([np.array([[d[f] for f in factors] for d in deciding]), points])
        purposes = [d["purpose"] for d in deciding] + purposes
    # support runs sit on the next domain's edges: rounded for the sheet, they stay inside it
    runs = _runs_frame(material, spec, points, purposes, lower_actual, upper_actual, surrogates)

    reason = _box_reason(spec, refocus, lo, hi, lower_actual, upper_actual, empty)
    n_sep = sum(not isinstance(lab, str) for lab in labels)
    n_box = labels.count("box")
    n_support = labels.count("support")
    reason += deciding_reason(deciding)
    if left_out:
        reason += (f"; {left_out} run(s) the criticism proposed lie outside the refocused box and are left out (the "
                   f"next wave's table keeps only runs inside it)")
    if over_budget > 0:
        reason += (f"; {over_budget} more run(s) the criticism proposed do not fit in the wave's {request.count} "
                   f"runs and are left out")
    n_band = n_design - n_sep - n_box - n_support
    reason += (f"; {n_design} new runs from a D-optimal quadratic design given the {int(inside.sum())} earlier "
               f"run(s) inside the box: {n_support} over the whole box (its edges and corners)"
               + (f", {n_band} on the band near the plausible set" if n_band else "")
               + (f", {n_box} off the band where its {len(cand_u)} grid point(s) cannot determine "
                  f"the quadratic" if n_box else "")
               + (f", {n_sep} to separate aliased terms the criticism found" if n_sep else "") + ".")
    aim = bool(z > 0 and (n_support or BAND_Z_FACTOR != 1) and len(cand_u))
    value = (_wave_value(judged, lo, hi, points, len(deciding), earlier_u[inside], n_design, alias_sets, aim)
             if z > 0 else None)
    return NextWave(dom_frame, runs, reason, value)


def _separating_over_omega(alias_sets, existing_u: np.ndarray, lo: np.ndarray, hi: np.ndarray,
                           budget: int) -> tuple[np.ndarray, list]:
    """Runs (search units) that make each aliased term the criticism found separately estimable given the
    ``existing_u`` runs, in Omega's coding; at most ``budget``; and their (members, responses) labels."""
    from .criticism import separating_runs

    k = len(lo)
    center, half = (lo + hi) / 2, (hi - lo) / 2
    coded = [(np.asarray(existing_u, dtype=float).reshape(-1, k) - center) / half]
    labels = []
    for members, responses in alias_sets:
        pts = separating_runs(np.vstack(coded), quadratic_terms(k), list(members), 1.0)
        coded += [np.reshape(p, (1, k)) for p in pts]
        labels += [(members, responses)] * len(pts)
    new = np.vstack(coded[1:])[:budget] if len(coded) > 1 else np.empty((0, k))
    return center + new * half, labels[:budget]


def _runs_frame(material: str, spec: MaterialSpec, points: np.ndarray, purposes: list[str], lower: np.ndarray,
                upper: np.ndarray, surrogates: dict) -> pd.DataFrame:
    """The proposals' table: rounded for the sheet (a run inside [lower, upper] stays inside), purpose and the
    surrogates' predictions."""
    runs = pd.DataFrame({"material": material, "proposal": np.arange(1, len(points) + 1)})
    for i, f in enumerate(spec.factor_names):
        lo_i, hi_i = lower[i], upper[i]
        runs[f] = [min(max(float(f"{v:.10g}"), lo_i), hi_i) if lo_i <= v <= hi_i else float(f"{v:.10g}")
                   for v in points[:, i]]
    runs["purpose"] = purposes
    for r, sur in surrogates.items():
        runs[f"predicted_{r}"] = sur.predict(points)
    return runs


def plan_omega_wave(material: str, table: pd.DataFrame, surrogates: dict, spec: MaterialSpec,
                    findings: pd.DataFrame | None = None, *, z: float) -> NextWave:
    """The next wave of a material whose waves analyse every run over the search range Omega (a simulated
    material): its runs anywhere in Omega where they decide the refocus scenario's set
    (:mod:`demid.boundary_runs`), after the criticism's deciding runs and replicates and the runs that separate
    aliased terms, all inside ``next_runs.count``.  The next domain is the box that holds the wave's runs (where
    they were placed; the analysis stays over Omega).  Arguments as :func:`plan_next_wave`."""
    from .boundary_runs import boundary_runs, classification_error
    from .scenario import JudgedScenario

    count, factors, domain = spec.next_runs.count, spec.factor_names, spec.domain
    refocus = next(sc for sc in spec.scenarios if sc.name == refocus_scenario(spec))
    judged = JudgedScenario(spec, refocus, surrogates, z)
    omega_lo, omega_hi = domain.search_bounds()
    earlier_u = domain.to_search(table[factors].to_numpy(dtype=float)).reshape(-1, len(factors))
    proposed = deciding_runs(findings, factors)
    n_design = design_count(count, len(proposed), earlier_u, omega_lo, omega_hi)
    deciding = proposed[:count - n_design]
    deciding_u = domain.to_search(np.array([[d[f] for f in factors] for d in deciding], dtype=float)
                                  .reshape(-1, len(factors))).reshape(-1, len(factors))
    separating_u, sep_labels = _separating_over_omega(aliased_findings(findings, factors),
                                                      np.vstack([earlier_u, deciding_u]), omega_lo, omega_hi, n_design)
    design_u, kinds = boundary_runs(judged, np.vstack([earlier_u, deciding_u, separating_u]),
                                    n_design - len(separating_u))
    points = domain.to_actual(np.vstack([deciding_u, separating_u, design_u]).reshape(-1, len(factors)))
    purposes = ([d["purpose"] for d in deciding]
                + [PURPOSE_SEPARATE.format(terms=" = ".join(term_name(t, factors) for t in members),
                                           responses=", ".join(responses)) for members, responses in sep_labels]
                + [PURPOSE_BOUNDARY if kind == "boundary" else PURPOSE_EXPLORE for kind in kinds])
    lower_actual, upper_actual = domain.to_actual(omega_lo)[0], domain.to_actual(omega_hi)[0]
    runs = _runs_frame(material, spec, points, purposes, lower_actual, upper_actual, surrogates)
    placed = runs[factors].to_numpy(dtype=float)
    dom_frame = pd.DataFrame({"material": material, "factor": factors, "lower": placed.min(axis=0),
                              "upper": placed.max(axis=0)})
    n_boundary, n_explore = kinds.count("boundary"), kinds.count("explore")
    design_x = domain.to_actual(design_u[:n_boundary].reshape(-1, len(factors)))
    error = float(classification_error(judged, design_x).max()) if n_boundary else 0.0
    reason = (f"Runs placed over the whole search range for scenario '{refocus.name}' "
              f"({join_observables(refocus.observables)})" + deciding_reason(deciding))
    if len(proposed) > len(deciding):
        reason += (f"; {len(proposed) - len(deciding)} more run(s) the criticism proposed do not fit in the wave's "
                   f"{count} runs and are left out")
    reason += (f"; {n_boundary} where the classification of the set is most uncertain (the largest probability of "
               f"misclassifying one of their points is {error:.2f}), spread apart"
               + (f", {n_explore} where the surrogate is least certain, so that a part of the set it missed can "
                  f"appear" if n_explore else "")
               + (f", {len(sep_labels)} to separate aliased terms the criticism found" if sep_labels else "") + ".")
    from .wave_value import expected_contraction

    value = expected_contraction(judged, points) if z > 0 else None
    return NextWave(dom_frame, runs, reason, value)


def plan_waves(specs: dict, frames: dict, *, z: float, analysed_over_omega: bool = False) -> dict[str, NextWave]:
    """:func:`plan_next_wave` for every material given (``analysed_over_omega``: see there).

    ``specs``: material -> :class:`~demid.spec.MaterialSpec`.
    ``frames``: ``tables``, ``fits``, ``plausible``, ``findings`` -> material -> frame (the pipeline's
    validated table, fits, plausible-identifiability and criticism-findings intermediates), and optionally
    ``statistics`` (the fit statistics: where a wave's sets used kriging, the runs are placed by it too).
    """
    from .surrogate import surrogates_from_frame
    from .surrogate_choice import chosen_surrogates

    waves = {}
    for m, spec in specs.items():
        table = frames["tables"][m]
        if "status" in table:
            table = table[table["status"] != "failed"]
        surrogates = chosen_surrogates(table, spec, surrogates_from_frame(frames["fits"][m], spec.factor_names),
                                       frames.get("statistics", {}).get(m))
        waves[m] = plan_next_wave(m, table, surrogates, spec, frames["plausible"][m], frames["findings"][m], z=z,
                                  analysed_over_omega=analysed_over_omega)
    return waves


def tabulate_waves(specs: dict, waves: dict[str, NextWave]) -> tuple[pd.DataFrame, pd.DataFrame, dict]:
    """The two long tables (next domain, next runs) and the reasons of the planned waves."""
    factors = list(dict.fromkeys(f for spec in specs.values() for f in spec.factor_names))
    predicted = list(dict.fromkeys(c for w in waves.values() for c in w.runs.columns if c.startswith("predicted_")))
    run_cols = ["material", "proposal"] + factors + ["purpose"] + predicted
    domain = (pd.concat([w.domain for w in waves.values()], ignore_index=True) if waves
              else pd.DataFrame(columns=DOMAIN_COLUMNS))
    runs = (pd.concat([w.runs for w in waves.values()], ignore_index=True).reindex(columns=run_cols) if waves
            else pd.DataFrame(columns=run_cols))
    return domain, runs, {m: w.reason for m, w in waves.items()}


def plan_materials(specs: dict, frames: dict, *, z: float) -> tuple[pd.DataFrame, pd.DataFrame, dict]:
    """:func:`plan_next_wave` for every material given; the two long tables and the reasons
    (arguments as :func:`plan_waves`)."""
    return tabulate_waves(specs, plan_waves(specs, frames, z=z))

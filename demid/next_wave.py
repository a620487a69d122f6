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
  (:data:`BOX_SHARE`) come from the box's 5-level grid {-1, -1/2, 0, 1/2, 1}^k (3 levels above
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

Every step takes the material's :class:`~demid.spec.MaterialSpec`.  The module imports neither scipy nor statsmodels at load time, so the workflow's
parse step can run :func:`check_next_runs`.
"""

from __future__ import annotations

from dataclasses import dataclass
from itertools import product
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from . import run_purposes
from .design import model_matrix, parse_term, quadratic_terms, term_name
from .errors import InputError
from .spec import MaterialSpec, join_observables

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
# A share of the design runs supports the whole refocused box: with every run on the band, the box's
# fit extrapolates at its edges and corners and admits false regions there (benchmarks/next_wave.py).
# A quarter rather than a third: where the set is small in the box, each corner run sits far from the
# set's boundary, which decides the symmetric difference, so a third of the runs there lost to random
# runs (benchmarks/next_wave.py, 32 seeds: wins 0.69 -> 0.73, confirmed on seeds 100-131: 0.63 -> 0.69).
BOX_SHARE = 1 / 4
# The band: the plausible set at BAND_Z_FACTOR x robust_z, so the band runs straddle the boundary of the
# plausible set instead of sitting inside it (benchmarks/next_wave.py: chosen over 1 and 3).
BAND_Z_FACTOR = 2.0
PURPOSE_SEPARATE = "separate aliased terms {terms} ({responses})"
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
    grid = _candidates(len(lo))
    return domain.to_actual(lo + (grid + 1.0) / 2.0 * (hi - lo))


def _candidates(k: int) -> np.ndarray:
    levels = (-1.0, -0.5, 0.0, 0.5, 1.0) if k <= 3 else (-1.0, 0.0, 1.0)
    return np.array(list(product(levels, repeat=k)))


def d_optimal_augment(existing: np.ndarray, count: int, k: int, candidates: np.ndarray | None = None) -> np.ndarray:
    """``count`` coded points from ``candidates`` (default: the box's grid), added one at a time, each
    maximising det(X'X) of the full quadratic over existing + chosen points.  By the rank-one update
    det(M + f f') = det(M) (1 + f' M^-1 f) that is the candidate of largest prediction variance
    f' M^-1 f.  A candidate is used once before any repeats; ties go to the candidate farthest from
    the points already there (then candidate order)."""
    terms = quadratic_terms(k)
    cands = _candidates(k) if candidates is None or not len(candidates) else np.asarray(candidates, dtype=float)
    f = model_matrix(cands, terms)
    current = np.asarray(existing, dtype=float).reshape(-1, k)
    # A tiny ridge keeps M invertible while the first runs are still fewer than the coefficients.
    info = model_matrix(current, terms).T @ model_matrix(current, terms) + 1e-9 * np.eye(len(terms))
    dist = (np.min(np.linalg.norm(cands[:, None, :] - current[None, :, :], axis=2), axis=1)
            if len(current) else np.full(len(cands), np.inf))
    used = dist < 1e-9
    chosen = []
    for _ in range(count):
        if used.all():
            used[:] = False
        variance = np.einsum("ij,ij->i", f @ np.linalg.inv(info), f)
        key = np.where(used, -np.inf, np.round(np.log1p(np.maximum(variance, 0.0)), 9))
        top = np.flatnonzero(key == key.max())
        best = int(top[np.argmax(np.round(dist[top], 9))])
        used[best] = True
        chosen.append(cands[best])
        info += np.outer(f[best], f[best])
        dist = np.minimum(dist, np.linalg.norm(cands - cands[best], axis=1))
    return np.array(chosen).reshape(-1, k)


def aliased_findings(findings: pd.DataFrame | None, factors: list[str]) -> list[tuple[tuple, list[str]]]:
    """Alias sets (as term tuples) named by missing-term findings, with the responses naming them."""
    if findings is None or not len(findings) or "cause" not in findings:
        return []
    out: dict[tuple, list[str]] = {}
    for _, row in findings[findings["cause"] == "missing_term"].iterrows():
        names = [n for n in str(row["aliases"]).split(";") if n]
        if len(names) < 2:
            continue
        members = tuple(parse_term(n, factors) for n in names)
        out.setdefault(members, []).append(str(row["response"]))
    return list(out.items())


def deciding_runs(findings: pd.DataFrame | None, factors: list[str]) -> list[dict]:
    """The runs the criticism proposes for the next wave (a row's ``discriminating_runs``): those that decide
    between causes it cannot tell apart first, then those that would confirm or correct a named cause; in the
    order proposed, each with its ``purpose``.  A replicate is kept (replicates are what tell a wild run from
    unequal scatter); a point that several responses propose is made as often as the one that proposes it
    most often, not once for each."""
    import json

    if findings is None or not len(findings) or "discriminating_runs" not in findings:
        return []
    proposed = []
    for _, row in findings.iterrows():
        text = row["discriminating_runs"]
        if isinstance(text, str) and text:
            proposed += [(run, str(row["response"])) for run in json.loads(text)]
    # decide first: until then no cause can be trusted (sorted is stable: the proposed order within each)
    proposed.sort(key=lambda item: item[0].get("purpose", PURPOSE_DECIDE) != PURPOSE_DECIDE)
    out, made, asked = [], {}, {}
    for run, response in proposed:
        key = tuple(float(run[f]) for f in factors)
        asked[key, response] = asked.get((key, response), 0) + 1
        if asked[key, response] > made.get(key, 0):
            made[key] = made.get(key, 0) + 1
            out.append({**{f: float(run[f]) for f in factors}, "response": response,
                        "purpose": run.get("purpose", PURPOSE_DECIDE)})
    return out


#: A criticism run this far (a share of the search range) outside the next box is taken as meant on its bound: the
#: criticism writes its points rounded (criticism.models._Data.point_dict: on the box's grid to 6 significant
#: digits, as this module writes its own runs; on the design's levels to 4 digits of the design's range).
CRITICISM_ROUNDING = 1e-3


def criticism_runs_in_box(runs: list[dict], factors: list[str], domain: Domain, lo: np.ndarray,
                          hi: np.ndarray) -> tuple[list[dict], int]:
    """The criticism's runs that the next wave can use, and how many it cannot: its table keeps only runs inside
    the next box [lo, hi] (search units), so a run outside would be simulated for nothing.  A run outside by
    no more than the criticism's rounding is put on the bound."""
    if not runs:
        return [], 0
    u = domain.to_search(np.array([[r[f] for f in factors] for r in runs], dtype=float))
    cur_lo, cur_hi = domain.search_bounds()
    slack = CRITICISM_ROUNDING * (cur_hi - cur_lo)
    usable = np.all((u >= lo - slack) & (u <= hi + slack), axis=1)
    box = domain.to_actual(np.array([lo, hi]))
    out = []
    for run, ok, point in zip(runs, usable, u):
        if ok:
            out.append({**run, **{f: float(box[0, i] if point[i] < lo[i] else box[1, i] if point[i] > hi[i]
                                         else run[f]) for i, f in enumerate(factors)}})
    return out, int(np.sum(~usable))


def _deciding_reason(deciding: list[dict]) -> str:
    """The reason's clause for the criticism's runs: how many, what for, for which responses."""
    parts = []
    for purpose, what in ((PURPOSE_DECIDE, "to decide between causes the criticism cannot tell apart"),
                          (PURPOSE_CONFIRM, "to confirm or correct a cause the criticism named")):
        runs = [d for d in deciding if d["purpose"] == purpose]
        if runs:
            parts.append(f"{len(runs)} run(s) {what} ({', '.join(dict.fromkeys(d['response'] for d in runs))})")
    return "; first " + ", then ".join(parts) if parts else ""


def _full_rank(points: np.ndarray, k: int) -> int:
    """How many quadratic coefficients short of full rank the points are (0: estimable)."""
    m = model_matrix(points, quadratic_terms(k))
    return m.shape[1] - int(np.linalg.matrix_rank(m, tol=1e-8 * max(np.abs(m).max(), 1.0) * len(m)))


def design_count(count: int, n_deciding: int, earlier: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> int:
    """How many of a wave's ``count`` runs are design runs, the criticism's ``n_deciding`` runs taking the others:
    ``count`` is the wave's whole budget.  The design keeps at least the runs the box's quadratic is short of
    given the ``earlier`` runs inside the box (search units), so that the next wave's fit is determined whatever
    the criticism's runs are (they may all be replicates of one point)."""
    k = len(lo)
    coded = (np.asarray(earlier, dtype=float).reshape(-1, k) - (lo + hi) / 2) / ((hi - lo) / 2)
    short = _full_rank(coded, k) if len(coded) else len(quadratic_terms(k))
    return max(count - n_deciding, min(short, count))


def box_support_count(count: int, share: float | None = None) -> int:
    """How many of ``count`` design runs support the whole refocused box (the rest go on the band)."""
    return int(round((BOX_SHARE if share is None else share) * count))


def _design(existing: np.ndarray, count: int, k: int, plausible: np.ndarray,
            share: float | None = None) -> tuple[np.ndarray, list[str]]:
    """Design points and their kinds (``support``, ``band``, ``box``).

    Support runs first (a share :data:`BOX_SHARE` of the runs): D-optimal over the box's 5-level grid
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
    short = min(_full_rank(np.vstack([base, band]), k), n_band)
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
    deciding, left_out = (proposed, 0) if analysed_over_omega else criticism_runs_in_box(proposed, factors, domain,
                                                                                         lo, hi)
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
    runs = pd.DataFrame({"material": material, "proposal": np.arange(1, len(points) + 1)})
    for i, f in enumerate(factors):
        # rounded for the sheet; a run inside the next domain (support runs sit on its edges) stays inside
        lo_i, hi_i = lower_actual[i], upper_actual[i]
        runs[f] = [min(max(float(f"{v:.10g}"), lo_i), hi_i) if lo_i <= v <= hi_i else float(f"{v:.10g}")
                   for v in points[:, i]]
    runs["purpose"] = purposes
    for r, sur in surrogates.items():
        runs[f"predicted_{r}"] = sur.predict(points)

    reason = _box_reason(spec, refocus, lo, hi, lower_actual, upper_actual, empty)
    n_sep = sum(not isinstance(lab, str) for lab in labels)
    n_box = labels.count("box")
    n_support = labels.count("support")
    reason += _deciding_reason(deciding)
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


def plan_waves(specs: dict, frames: dict, *, z: float, analysed_over_omega: bool = False) -> dict[str, NextWave]:
    """:func:`plan_next_wave` for every material given (``analysed_over_omega``: see there).

    ``specs``: material -> :class:`~demid.spec.MaterialSpec`.
    ``frames``: ``tables``, ``fits``, ``plausible``, ``findings`` -> material -> frame (the pipeline's
    validated table, fits, plausible-identifiability and criticism-findings intermediates).
    """
    from .surrogate import surrogates_from_frame

    waves = {}
    for m, spec in specs.items():
        table = frames["tables"][m]
        if "status" in table:
            table = table[table["status"] != "failed"]
        surrogates = surrogates_from_frame(frames["fits"][m], spec.factor_names)
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

"""The report's first section: per material, the answer a researcher acts on.

A recommended parameter set, the admissible interval and a verdict per factor and scenario,
the criticism verdicts in one line each and the next step.  Every number is read from the
results tree; nothing is recomputed here.  The verdicts on the plausible interval and the advice
are :mod:`demid.story`'s (``tables/verdicts.csv``, ``tables/advice.csv``, the verdict rule in
:mod:`demid.story.verdicts`); this module writes the criticism and combination lines.
"""

from __future__ import annotations

import numpy as np

from ..sampling.domain import SIDES_OF, sides_at_limit
from ..story.words import in_order, labelled, level2_own_tolerances, level2_within

#: The criticism verdicts in the report's words.
VERDICT_WORDS = {"adequate": "adequate (within the tests' power)", "defect": "defect named",
                 "unexplained": "misfit unexplained", "does_not_predict": "does not predict",
                 "ambiguous": "ambiguous cause"}


def verdict_sentence(response: str, res: dict) -> str:
    """The verdict message without its leading "<response>: <verdict> — " (the report names both)."""
    text = res.get("verdict_message", "")
    head = f"{response}: "
    if text.startswith(head) and " — " in text:
        return text.split(" — ", 1)[1]
    return text[len(head):] if text.startswith(head) else text


def unpredictive_responses(info: dict) -> list[str]:
    """Responses whose surrogate does not predict left-out runs (verdict ``does_not_predict``)."""
    from ..surrogate_choice import sets_do_not_predict

    return [r for r, res in in_order(info.get("level1") or {}) if sets_do_not_predict(res)]


def unreliable_surrogate_lines(info: dict, spec) -> list[str]:
    """One warning per scenario (and the Pareto front) that relies on a surrogate that does not predict."""
    bad = unpredictive_responses(info)
    lines = []
    for sc in spec.scenarios:
        used = [r for r in sc.observables if r in bad]
        if used:
            names = ", ".join(spec.response_labels.get(r, r) for r in used)
            lines.append(f"⚠ Scenario *{sc.label}* uses {names}, whose surrogate does not predict left-out runs "
                         f"(Q² < 0): its admissible set should not be used to decide admissibility.")
    pareto = spec.pareto
    used = [r for r in (pareto.error_of, pareto.minimise) if r in bad] if pareto is not None else []
    if used:
        names = ", ".join(spec.response_labels.get(r, r) for r in dict.fromkeys(used))
        lines.append(f"⚠ The Pareto front uses {names}, whose surrogate does not predict left-out runs (Q² < 0): "
                     f"treat the front as indicative only.")
    return lines


def criticism_lines(info: dict, spec) -> list[str]:
    """One line per response (surrogate vs runs) and one for simulation vs experiment."""
    lines = []
    level1 = info.get("level1", {})
    for response in [r for r in spec.response_names if r in level1]:
        res = level1[response]
        label = spec.response_labels.get(response, response)
        if res.get("verdict_message"):
            lines.append(f"Surrogate of {label} — **{VERDICT_WORDS.get(res['verdict'], res['verdict'])}**: "
                         + labelled(verdict_sentence(response, res), spec))
        elif res["messages"]:
            lines.append(f"Surrogate of {label}: " + labelled(" ".join(res["messages"]), spec))
        else:
            lines.append(f"Surrogate of {label}: no defect found — the quadratic fits the simulation runs.")
    run_order = info.get("run_order") or {}
    if run_order.get("drift_tested") is False:
        lines.append(f"Run order: {run_order['message']}")
    lines += unreliable_surrogate_lines(info, spec)
    level2 = info.get("level2")
    if level2:
        from ..criticism.messages import level2_miss_text
        from ..precision import percent_text

        tol = 100 * level2["tolerance"]
        own = level2_own_tolerances(level2)
        uniform = own is None
        within = level2_within(level2, spec)
        best = percent_text(level2["best_max_error"])
        own_miss = labelled(level2_miss_text(level2["best_errors"], level2["tolerance"], own), spec) if not uniform else ""
        if level2["feasible"]:
            lines.append(f"Simulation vs experiment: every target can be met within {within} "
                         f"(best point misses {f'by at most {best}' if uniform else own_miss}).")
        else:
            lines.append(f"Simulation vs experiment: the targets cannot all be met within {within}; the best point "
                         f"misses {f'by {best}' if uniform else own_miss}"
                         + (f", limited by {spec.response_labels.get(limit, limit)}"
                            if (limit := level2.get("bottleneck")) else "") + ".")
        if level2.get("reference_max_error") is not None:
            inside = level2.get("reference_within")
            inside = level2["reference_max_error"] <= level2["tolerance"] if inside is None else inside
            lines.append(f"Reference point: largest error {percent_text(level2['reference_max_error'])} "
                         f"({'within' if inside else 'outside'} "
                         + (f"the {tol:g} % tolerance)." if uniform else
                            level2_within(level2, spec, brackets=False) + ")."))
        # a best point on a bound is told by the advice (demid.story), where widening can reach something
        lines += list(level2.get("extrapolation") or [])
    return lines


def combination_lines(combinations: dict, spec) -> list[str]:
    """One line per scenario and set: what the set identifies in combination (its text in
    ``combinations/{material}.json``), and a band's curve as a table row of values."""
    lines = []
    labels = {sc.name: sc.label for sc in spec.scenarios}
    for entry in combinations.get("sets", []):
        line = f"*{labels.get(entry['scenario'], entry['scenario'])}*, {entry['set']} set: {entry['text']}"
        curve = entry.get("curve")
        if curve and entry.get("identified") and "curved band" in entry["text"]:
            along, across = spec.factor(curve["along"]), spec.factor(curve["across"])
            pairs = "; ".join(f"{a:.3g} → {m:.3g} [{lo:.3g}, {hi:.3g}]" for a, lo, m, hi in
                              zip(curve["along_actual"], curve["lower"], curve["mid"], curve["upper"]))
            line += f" Curve ({along.label} → {across.label} mid [lowest, highest]): {pairs}."
        lines.append(line)
    return lines


def point_on_edge_text(spec, point: dict, runs, verdicts: dict, widened: set) -> str:
    """What a reader must know of a recommended point that sits on a search bound or outside the region the
    design runs cover (their convex hull): per factor on a bound, whether the advice widens that bound, and
    that outside the runs the surrogate extrapolates.  Empty for a point inside the runs, off every bound.

    ``runs``: the design runs (rows, factor columns in the spec's order, actual units) or None; ``verdicts``:
    factor -> its verdict in the point's scenario; ``widened``: the (factor, side) pairs the advice widens."""
    from ..criticism.edges import in_hull

    domain = spec.domain
    sides = domain.at_bound([point[f] for f in spec.factor_names], [point[f] for f in spec.factor_names])
    groups: dict[tuple, list[str]] = {}  # factors that get the same words, named together
    for f, side in zip(spec.factors, sides):
        for s in SIDES_OF[side]:
            if s in sides_at_limit((f.lower, f.upper), f.limits):
                groups.setdefault(("limit", s, ""), []).append(f.label)
            else:
                kind = "widened" if (f.name, s) in widened else "kept"
                why = verdicts.get(f.name, "") if kind == "kept" else ""
                groups.setdefault((kind, s, why if why in ("unresolved", "bounded", "identified") else ""),
                                  []).append(f.label)
    clauses = []
    for (kind, s, why), labels in groups.items():
        many = len(labels) > 1
        names = ", ".join(labels[:-1]) + " and " + labels[-1] if many else labels[0]
        if kind == "limit":
            clauses.append(f"{names} {'are' if many else 'is'} at {'their' if many else 'its'} physical {s} "
                           f"limit{'s' if many else ''}, beyond which no value lies")
        elif kind == "widened":
            clauses.append(f"{names} {'lie' if many else 'lies'} on {'their' if many else 'its'} {s} search "
                           f"bound{'s' if many else ''}, which the advice below widens: the plausible set may "
                           "continue beyond it, and the recommended value with it")
        else:
            clauses.append(f"{names} {'lie' if many else 'lies'} on {'their' if many else 'its'} {s} search "
                           f"bound{'s' if many else ''}; no widening is advised there"
                           + (f" (the plausible interval{'s are' if many else ' is'} {why}: a wider range would "
                              f"not narrow {'them' if many else 'it'})" if why else ""))
    outside = False
    if runs is not None and len(runs):
        lo, hi = domain.search_bounds()
        span = np.where(hi > lo, hi - lo, 1.0)
        z = (domain.to_search(np.asarray(runs, dtype=float)) - lo) / span
        u = (domain.to_search(np.array([[point[f] for f in spec.factor_names]], dtype=float))[0] - lo) / span
        outside = not in_hull(z, u, 1e-3)
    if not clauses and not outside:
        return ""
    text = "⚠ " + "; ".join(clauses) + ("." if clauses else "")
    if outside:
        text += (" " if clauses else "") + (
            "The point lies outside the region the design runs cover (their convex hull): its predictions are the "
            "quadratic's extrapolation, backed by no simulation, so simulate it before relying on it.")
    return text

"""The report's first section: per material, the answer a researcher acts on.

A recommended parameter set, the admissible interval and a verdict per factor and scenario,
the criticism verdicts in one line each and the next step.  Every number is read from the
results tree; nothing is recomputed here.  The verdicts on the plausible interval and the advice
are :mod:`demid.story`'s (``tables/verdicts.csv``, ``tables/advice.csv``); this module holds the
verdict rule they share and the criticism lines.
"""

from __future__ import annotations

import re

import numpy as np
import pandas as pd

from ..sampling.domain import BOUND_TOUCH, SIDES_OF, Domain, sides_at_limit

#: Width of the admissible interval, as a fraction of the search range, up to which a factor is *identified*.
IDENTIFIED_MAX_WIDTH = 0.10
#: Width from which a factor is *unresolved*: the data leave (almost) the whole search range open.
UNRESOLVED_MIN_WIDTH = 0.90

VERDICT_TEXT = (
    f"**identified**: admissible interval at most {100 * IDENTIFIED_MAX_WIDTH:g} % of the search range wide and "
    f"clear of both bounds (or ending at a physical limit); **bounded**: narrower than "
    f"{100 * UNRESOLVED_MIN_WIDTH:g} % of the range and clear of both bounds (or at a limit); **unresolved**: "
    f"{100 * UNRESOLVED_MIN_WIDTH:g} % of the range or more is admissible, the observables say (almost) nothing "
    f"about the factor; **cut by the search range**: narrower than that but touching a search bound (within "
    f"{100 * BOUND_TOUCH:g} % of the range), so the true interval may extend beyond it (a bound at the factor's "
    f"physical limit, `limits` in the config, cuts nothing: no value lies beyond it); **no admissible point**: no "
    f"point of the domain meets every target. Widths are measured in search units (log10 for log-scaled factors)."
)


_SUPERSCRIPT = str.maketrans("-0123456789.", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹·")


def unit_text(unit: str) -> str:
    """A config unit for running text: ``J m^-2`` -> ``J m⁻²``; dimensionless -> ``–``."""
    if not unit or unit.strip() == "-":
        return "–"
    return re.sub(r"\^\{?(-?[0-9.]+)\}?", lambda m: m.group(1).translate(_SUPERSCRIPT), unit)


def factor_verdict(lower: float, upper: float, bound_lower: float, bound_upper: float, log: bool = False,
                   at_bound: str | None = None, limits: tuple = (None, None)) -> tuple[str, float]:
    """Verdict and width (fraction of the search range) of one admissible interval.

    ``at_bound`` is the interval's ``at_bound`` value from the identifiability table (which
    ends of the search range the set reaches); without it, it is derived the same way
    (:meth:`~demid.sampling.domain.Domain.at_bound`).  An end of the range at the factor's physical
    ``limits`` does not cut the set: no value lies beyond it.
    """
    if not (np.isfinite(lower) and np.isfinite(upper)):
        return "no admissible point", float("nan")
    f = np.log10 if log else (lambda v: v)
    width = (f(upper) - f(lower)) / (f(bound_upper) - f(bound_lower))
    if width >= UNRESOLVED_MIN_WIDTH:
        return "unresolved", width
    if not isinstance(at_bound, str):  # not given (or an older table without the column)
        at_bound = interval_at_bound(lower, upper, bound_lower, bound_upper, log)
    cut = [side for side in SIDES_OF[at_bound] if side not in sides_at_limit((bound_lower, bound_upper), limits)]
    if cut:
        return f"cut by the search range ({' and '.join(cut)} bound)", width
    return ("identified" if width <= IDENTIFIED_MAX_WIDTH else "bounded"), width


def interval_at_bound(lower: float, upper: float, bound_lower: float, bound_upper: float, log: bool = False) -> str:
    """The ``at_bound`` value of one interval in its factor's range (:meth:`Domain.at_bound`)."""
    return Domain(("x",), (bound_lower,), (bound_upper,), (log,)).at_bound([lower], [upper])[0]


def verdict_table(identifiability: pd.DataFrame, spec) -> pd.DataFrame:
    """One row per scenario x factor: interval, width in % of the range and verdict."""
    rows = []
    for _, row in identifiability.iterrows():
        factor = spec.factor(row["factor"])
        verdict, width = factor_verdict(float(row["lower"]), float(row["upper"]), factor.lower, factor.upper, factor.log,
                                        row.get("at_bound"), factor.limits)
        label = next((sc.label for sc in spec.scenarios if sc.name == row["scenario"]), row["scenario"])
        rows.append({"scenario": label, "factor": factor.label, "unit": unit_text(factor.unit),
                     "admissible interval": "–" if verdict == "no admissible point"
                     else f"[{row['lower']:.4g}, {row['upper']:.4g}]",
                     "width [% of range]": 100 * width, "verdict": verdict})
    return pd.DataFrame(rows)


#: The criticism verdicts in the report's words.
VERDICT_WORDS = {"adequate": "adequate (within the tests' power)", "defect": "defect named",
                 "unexplained": "misfit unexplained", "does_not_predict": "does not predict",
                 "ambiguous": "ambiguous cause"}


def natural_key(name: str) -> list:
    """Sort key that reads digits as numbers: d5, d10, d15 (not d10, d15, d5)."""
    import re

    return [int(part) if part.isdigit() else part for part in re.split(r"(\d+)", str(name))]


def in_order(mapping: dict, names=()) -> list[tuple]:
    """``mapping``'s items in the order of ``names`` (the config's), then any other key in natural order:
    JSON read back has its keys sorted as text, which puts d10 before d5."""
    known = [n for n in names if n in mapping]
    rest = sorted((k for k in mapping if k not in set(known)), key=natural_key)
    return [(k, mapping[k]) for k in known + rest]


def level2_own_tolerances(level2: dict) -> dict | None:
    """Level 2's own tolerance per observable in config order, or None when every observable is judged at
    the scenario's (also for results written before own tolerances were recorded)."""
    from ..tolerance import same_tolerances

    own = dict(in_order(level2.get("tolerances") or {}, level2.get("observables") or ()))  # JSON sorts its keys
    return None if same_tolerances(level2["tolerance"], own) else own


def level2_within(level2: dict, spec, brackets: bool = True) -> str:
    """Level 2's tolerance in words: "2 %", or each observable's own (labelled)."""
    from ..criticism.messages import level2_tolerance_text

    own = level2_own_tolerances(level2)
    if own is None:
        return f"{100 * level2['tolerance']:g} %"
    return labelled(level2_tolerance_text(level2["tolerance"], own, brackets=brackets), spec)


def labelled(text: str, spec) -> str:
    """``text`` with every factor and response key that stands as a word (``mu_s=0.9``, ``angle_of_repose
    under-predicted``) written as its configured label; keys inside a config path (``responses.d5.target``)
    or a file name stay as they are."""
    import re

    names = {**{f.name: f.label for f in spec.factors}, **{r.name: r.label for r in spec.responses}}
    names = {k: v for k, v in names.items() if v and v != k}
    if not names or not text:
        return text
    words = [k for k in names if k in _ENGLISH_WORDS]  # "a": a factor only where a value or a bracket follows
    others = [k for k in names if k not in _ENGLISH_WORDS]

    def alternation(keys):
        return "|".join(re.escape(k) for k in sorted(keys, key=len, reverse=True))

    if others:
        text = re.compile(r"(?<![\w./`])(" + alternation(others) + r")(?![\w`]|\.\w)").sub(
            lambda m: names[m.group(1)], text)
    if words:
        text = re.compile(r"(?<![\w./`])(" + alternation(words) + r")(?=\s*[=≈]|[,;:)]|\.(?:\s|$)|$)").sub(
            lambda m: names[m.group(1)], text)
    return text


#: Short English words a factor or response may be called (``a``, ``in``): in running text they are read as
#: words, and replaced by the label only where a value, a bracket or punctuation follows (``a=0.1``, ``(a ≈ 2)``).
_ENGLISH_WORDS = frozenset({"a", "an", "and", "any", "are", "as", "at", "be", "but", "by", "can", "do", "for", "if",
                            "in", "is", "it", "its", "may", "no", "not", "of", "on", "one", "or", "per", "so", "the",
                            "to", "up", "was", "we"})


def verdict_sentence(response: str, res: dict) -> str:
    """The verdict message without its leading "<response>: <verdict> — " (the report names both)."""
    text = res.get("verdict_message", "")
    head = f"{response}: "
    if text.startswith(head) and " — " in text:
        return text.split(" — ", 1)[1]
    return text[len(head):] if text.startswith(head) else text


def unpredictive_responses(info: dict) -> list[str]:
    """Responses whose surrogate does not predict left-out runs (verdict ``does_not_predict``)."""
    return [r for r, res in in_order(info.get("level1") or {}) if res.get("verdict") == "does_not_predict"]


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

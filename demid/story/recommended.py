"""Where the recommended point stands: on a search bound or at a physical limit, and inside or outside the
region the design runs cover, with what follows for the reader (whether the advice widens that bound, whether
the surrogate extrapolates there).

The judgement is the story's, like the verdicts and the advice it refers to; the report prints the sentence.
"""

from __future__ import annotations

import numpy as np

from ..sampling.domain import SIDES_OF, sides_at_limit

#: How far outside the design runs' convex hull a point may lie, per factor in fractions of its search range,
#: and still count as covered by them (the slack :func:`~demid.criticism.edges.extrapolation_warnings` gives
#: the reference point): a point on the hull's face is inside whatever the linear program's round-off.
HULL_TOLERANCE = 1e-3


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
        outside = not in_hull(z, u, HULL_TOLERANCE)
    if not clauses and not outside:
        return ""
    text = "⚠ " + "; ".join(clauses) + ("." if clauses else "")
    if outside:
        text += (" " if clauses else "") + (
            "The point lies outside the region the design runs cover (their convex hull): its predictions are the "
            "quadratic's extrapolation, backed by no simulation, so simulate it before relying on it.")
    return text

"""Model-criticism figure: residuals of the quadratic and of its extension per response."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
from scipy import stats

from .layout import RASTER_ABOVE_POINTS as RASTER_RUNS  # a module global, read at draw time

#: What a row's first panel says when no cause is named: the verdict, never "no finding" beside a misfit.
_NO_CAUSE = {"adequate": "no finding (within the tests' power)",
             "unexplained": "misfit unexplained: no cause singled out",
             "does_not_predict": "does not predict left-out runs (Q² < 0)"}

if TYPE_CHECKING:
    from ..criticism.level1 import CriticismResult
    from ..surrogate import SurrogateFit


# =========================================================================== figure
def residual_figure(fits: list[SurrogateFit], results: list[CriticismResult], title: str, units: dict | None = None):
    """Residual diagnostics, one row per response: vs fitted, vs run order, normal QQ.

    Residuals are those of the baseline quadratic; the QQ panel uses externally
    studentised residuals.  Named findings are marked: an outlier run is ringed
    and labelled in every panel, a drift gets its trend line, other causes are
    written in the first panel.  Returns a :class:`matplotlib.figure.Figure`
    (no pyplot state, no dates; save with ``metadata={'Software': None}`` etc.).
    """
    import textwrap

    from matplotlib.figure import Figure

    from .labels import PALETTE, tex_label, tex_unit
    from .layout import PAGE_WIDTH_IN

    units = units or {}

    by_response = {r.response: r for r in results}
    rows = max(len(fits), 1)
    fig = Figure(figsize=(PAGE_WIDTH_IN, 2.7 * rows + 0.3), layout="constrained")
    axes = fig.subplots(rows, 3, squeeze=False)
    for row, fit in zip(axes, fits):
        res = by_response.get(fit.response)
        infl = fit.influence()
        runs = infl["run"].to_numpy()
        resid = infl["residual"].to_numpy()
        fitted = infl["fitted"].to_numpy()
        stud = infl["student_resid"].to_numpy()
        order = np.argsort(stud)
        theo = stats.norm.ppf((np.arange(1, len(stud) + 1) - 0.375) / (len(stud) + 0.25))
        qq_x = np.empty_like(theo)
        qq_x[order] = theo
        item = units.get(fit.response)
        unit = f" [{tex_unit(item.unit)}]" if item is not None else ""
        name = tex_label(item.label) if item is not None else fit.response
        panels = [(fitted, resid, f"fitted {name}{unit}", f"residual{unit}"),
                  (runs.astype(float), resid, "run order [–]", f"residual{unit}"),
                  (qq_x, stud, "normal quantile [–]", "ext. studentised residual [–]")]
        for ax, (x, y, xl, yl) in zip(row, panels):
            # thousands of runs: one image in the SVG, not a vector marker per run (the PNG is the same)
            ax.scatter(x, y, s=18, color="0.25", zorder=3, rasterized=len(x) > RASTER_RUNS)
            ax.set_xlabel(xl)
            ax.set_ylabel(yl)
            ax.grid(alpha=0.3)
        row[0].axhline(0, color="0.5", lw=0.8)
        row[1].axhline(0, color="0.5", lw=0.8)
        lim = np.nanmax(np.abs(np.concatenate([qq_x, stud[np.isfinite(stud)]]))) if len(stud) else 1.0
        row[2].plot([-lim, lim], [-lim, lim], color="0.5", lw=0.8)
        row[1].set_title(f"{name}: residual vs run order", fontsize=9)
        row[2].set_title(f"{name}: normal QQ", fontsize=9)
        notes = []
        for f in (res.findings if res is not None else []):
            if f.cause == "outlier":
                hit = runs == f.detail
                for ax, (x, y, _, _) in zip(row, panels):
                    ax.scatter(x[hit], y[hit], s=110, facecolors="none", edgecolors=PALETTE[5], lw=1.5, zorder=4)
                    for xi, yi in zip(x[hit], y[hit]):
                        ax.annotate(f"run {f.detail}", (xi, yi), textcoords="offset points", xytext=(6, 6),
                                    color=PALETTE[5], fontsize=8)
            elif f.cause == "drift":
                slope, icpt = np.polyfit(runs.astype(float), resid, 1)
                xs = np.array([runs.min(), runs.max()], dtype=float)
                row[1].plot(xs, icpt + slope * xs, color=PALETTE[5], lw=1.2)
            label = {"missing_term": "missing term", "response_transform": "transform",
                     "heteroscedasticity": "unequal scatter vs"}.get(f.cause, f.cause)
            alias = " = " + " = ".join(f.aliases[1:]) if f.cause == "missing_term" and len(f.aliases) > 1 else ""
            notes.append(f"{label} {f.detail}{alias} (p={f.p_value:.3g})")
        # The verdict goes in the panel title, never over the points.
        verdict = res.verdict if res is not None else "adequate"
        text = "; ".join(notes) if notes else _NO_CAUSE.get(verdict, verdict)
        row[0].set_title(f"{name}: residual vs fitted\n" + "\n".join(textwrap.wrap(text, 40)), fontsize=8,
                         color=PALETTE[5] if notes or verdict != "adequate" else "0.2")
    fig.suptitle(title)
    return fig

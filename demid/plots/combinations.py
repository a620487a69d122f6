"""Identified combinations: each scenario's set with its narrowest direction drawn.

Two factors: the set (plausible light, strict dark) with the band's centre line and the
identified direction as an arrow across the band at the set's centre.  Three or more factors:
pairwise projections of the set with the narrowest direction's loadings on each pair as an
arrow (the pairs of the three largest loadings).  Axes in search units, log-scaled factors
labelled with actual values.
"""

from __future__ import annotations

from itertools import combinations as pairs
from typing import TYPE_CHECKING

import numpy as np

from .labels import PALETTE, axis_label, tex_label
from .style import plt, styled

if TYPE_CHECKING:
    from ..combinations import MaterialCombinations

#: Points drawn per set and panel (a seeded subsample: the figure stays light and deterministic).
MAX_POINTS = 6000
SET_COLORS = {"plausible": "#BBD7EC", "strict": PALETTE[0]}
WIDTH_IN = 7.2


def _subsample(points: np.ndarray) -> np.ndarray:
    if len(points) <= MAX_POINTS:
        return points
    # a seeded random subsample: an evenly strided one draws moiré stripes on grid nodes
    return points[np.sort(np.random.default_rng(0).choice(len(points), MAX_POINTS, replace=False))]


def _log_ticks(ax, spec, i: int, j: int):
    import matplotlib.ticker

    for k, axis in ((i, ax.xaxis), (j, ax.yaxis)):
        if spec.factors[k].log:
            axis.set_major_formatter(matplotlib.ticker.FuncFormatter(lambda v, _: f"{10 ** v:.3g}"))


@styled
def combinations_figure(result: MaterialCombinations, title: str):
    """One row per scenario: the band (2 factors) or the pairwise projections (3+ factors)."""
    spec, coding = result.spec, result.coding
    d = spec.dim
    scenarios = [sc for sc in spec.scenarios if any(r.scenario == sc.name for r in result.results)]
    if d == 2:
        cols = min(3, max(1, len(scenarios)))
        rows = int(np.ceil(len(scenarios) / cols)) or 1
        panels = [(sc, (0, 1)) for sc in scenarios]
    else:
        cols, rows = 3, max(1, len(scenarios))
        panels = []
        for sc in scenarios:
            strict = next((r for r in result.results if r.scenario == sc.name and r.axes is not None), None)
            top = (np.argsort(-np.abs(strict.axes.directions[:, 0]))[:3] if strict is not None
                   else np.arange(min(3, d)))
            panels += [(sc, (int(a), int(b))) for a, b in pairs(sorted(top), 2)]
    fig, axes = plt.subplots(rows, cols, figsize=(WIDTH_IN, 2.5 * rows + 0.5), squeeze=False, layout="constrained")
    lo_s, hi_s = spec.domain.search_bounds()
    unit = np.asarray(coding.unit, dtype=float)
    for ax, (sc, (i, j)) in zip(axes.ravel(), panels):
        for set_name in ("plausible", "strict"):
            coded = result.points.get((sc.name, set_name))
            if coded is None or not len(coded):
                continue
            search = coding.to_actual(_subsample(coded))
            ax.scatter(search[:, i], search[:, j], s=1.5, lw=0, color=SET_COLORS[set_name], rasterized=True,
                       label=f"{set_name} set")
        res = next((r for r in result.results if r.scenario == sc.name and r.set == "strict" and r.axes), None)
        if res is not None:
            centre = coding.to_actual(res.axes.centre[None, :])[0]
            if d == 2 and res.curve is not None and len(res.curve):
                line = np.zeros((len(res.curve), 2))
                line[:, res.wide] = res.curve["along"].to_numpy()
                line[:, res.narrow] = res.curve["mid"].to_numpy()
                line = coding.to_actual(line)
                ax.plot(line[:, 0], line[:, 1], color=PALETTE[5], lw=0.8, ls=(0, (4, 2)), label="band centre line")
            v = res.axes.directions[:, 0]
            # the identified direction, one fifth of the coded box long, drawn in search units
            span = 0.2 * float(np.min(result.upper - result.lower))
            tip = centre + v * unit * span / 2
            tail = centre - v * unit * span / 2
            ax.annotate("", xy=(tip[i], tip[j]), xytext=(tail[i], tail[j]),
                        arrowprops=dict(arrowstyle="<->", color="black", lw=1.0))
            if d > 2:
                ax.text(0.02, 0.98, f"loadings {v[i]:+.2f}, {v[j]:+.2f}", transform=ax.transAxes, fontsize=7,
                        va="top")
        ax.set_xlim(lo_s[i], hi_s[i])
        ax.set_ylim(lo_s[j], hi_s[j])
        ax.set_xlabel(axis_label(spec.factors[i]), fontsize=8)
        ax.set_ylabel(axis_label(spec.factors[j]), fontsize=8)
        ax.tick_params(labelsize=7)
        _log_ticks(ax, spec, i, j)
        cut = res is not None and res.cut != "none"
        # above two factors each panel is a projection: the pair goes first, the scenario on a second line
        head = (f"projection on {tex_label(spec.factors[i].label)}, {tex_label(spec.factors[j].label)}\n"
                if d > 2 else "")
        ax.set_title(head + sc.label + (" (cut by the range)" if cut else ""), fontsize=8)
    for ax in axes.ravel()[len(panels):]:
        ax.set_visible(False)
    handles, labels = axes.ravel()[0].get_legend_handles_labels()
    if handles:
        fig.legend(handles, labels, loc="outside lower center", ncol=len(handles), fontsize=7, markerscale=4,
                   frameon=False)
    fig.suptitle(f"{title}: sets and their narrowest direction (arrow)", fontsize=9)
    return fig

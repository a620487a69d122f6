"""Response-surface contour panels with design runs and target levels."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from ..sampling import Domain
from .labels import axis_label, tex_label, tex_unit
from .layout import RASTER_ABOVE_POINTS, panel_grid
from .style import plt, styled, _axis_scale

if TYPE_CHECKING:
    from ..spec import MaterialSpec


@styled
def surface_figure(domain: Domain, spec: MaterialSpec, grid: pd.DataFrame, n: int,
                   table: pd.DataFrame | None = None, title: str = "") -> plt.Figure:
    """Contour panel per response over the first two factors (others at their mid-range)."""
    names = list(domain.factors)
    d = domain.dim
    responses = [r for r in spec.response_names if r in grid.columns]
    nrow, ncol, (width, height) = panel_grid(len(responses), 3.6, 3.0)
    legend_in = 0.3
    fig, axes = plt.subplots(nrow, ncol, figsize=(width, height + legend_in), squeeze=False)
    lo, hi = domain.search_bounds()
    step = max(1, (n - 1) // 200)
    for ax, r in zip(axes.ravel(), responses):
        values = grid[r].to_numpy().reshape((n,) * d)
        if d > 2:
            values = values[(slice(None), slice(None)) + (n // 2,) * (d - 2)]
        if d == 1:
            ax.plot(np.linspace(lo[0], hi[0], n), values, color="k")
            continue
        z = values[::step, ::step].T
        xs = np.linspace(lo[0], hi[0], n)[::step]
        ys = np.linspace(lo[1], hi[1], n)[::step]
        cs = ax.contourf(xs, ys, z, levels=14, cmap="viridis")
        fig.colorbar(cs, ax=ax, label=axis_label(spec.response(r)))
        target = spec.response(r).target
        if target is not None and z.min() < target < z.max():
            ax.contour(xs, ys, z, levels=[target], colors="w", linewidths=1.4, linestyles="--")
            ax.plot([], [], color="k", lw=1.4, ls="--", label="target contour")
        if table is not None and len(table):
            pts = domain.to_search(table[names[:2]].to_numpy())
            # not clipped: runs on the bounds of the search range are drawn whole
            ax.plot(pts[:, 0], pts[:, 1], "o", ms=3.5, mfc="w", mec="k", mew=0.6, ls="none",
                    label="design runs", clip_on=False, zorder=5, rasterized=len(pts) > RASTER_ABOVE_POINTS)
        ax.set_xlabel(axis_label(spec.factor(names[0])))
        ax.set_ylabel(axis_label(spec.factor(names[1])))
        missed = target is not None and not (z.min() < target < z.max())
        ax.set_title(tex_label(spec.response(r).label) + (f" (target {target:g} not on this plot)" if missed else ""),
                     fontsize=9)
        _axis_scale(ax, domain, 0, 1)
    for ax in axes.ravel()[len(responses):]:
        ax.set_visible(False)
    handles = {}
    for ax in axes.ravel():
        for h, lab in zip(*ax.get_legend_handles_labels()):
            handles.setdefault(lab, h)
    sub = "" if d <= 2 else f" (other factors at mid-range: {', '.join(names[2:])})"
    if title or sub:
        fig.suptitle(f"{title}{sub}")
    # laid out when drawn (demid.io.save_figure), once, at the resolution it is saved at
    fig.set_layout_engine("tight", rect=(0, legend_in / (height + legend_in) if handles else 0, 1, 1))
    if handles:  # below the panels, never over a run
        fig.legend(handles.values(), handles.keys(), loc="lower center", ncol=len(handles), frameon=False)
    return fig


def runs_on_slice(table: pd.DataFrame | None, domain: Domain, held: np.ndarray) -> pd.DataFrame | None:
    """The design runs whose factors beyond the first two sit at the held values (runs elsewhere
    would be read against a surface they do not lie on)."""
    if table is None:
        return None
    names = list(domain.factors)
    runs = domain.to_search(table[names].to_numpy())
    centre = domain.to_search(held[None, :])[0]
    lo, hi = domain.search_bounds()
    off = np.abs(runs[:, 2:] - centre[2:]) / (hi[2:] - lo[2:])
    return table[(off < 1e-3).all(axis=1)]


@styled
def surface_figure_from_surrogates(surrogates: dict, spec: MaterialSpec, table: pd.DataFrame | None,
                                   n: int = 201) -> plt.Figure:
    """Surface panels on an n x n slice through the first two factors (others at mid-range)."""
    from ..sampling import predict_grid

    domain, title = spec.domain, spec.label
    d = domain.dim
    if d > 2:
        # A 2-D slice: the remaining factors at the centre of their (search-unit) range.
        lo, hi = domain.search_bounds()
        mid = domain.to_actual(((lo + hi) / 2)[None, :])[0]
        names = list(domain.factors)
        slice_domain = Domain(tuple(names[:2]), tuple(domain.lower[:2]), tuple(domain.upper[:2]), domain.log[:2])
        pts = slice_domain.grid(n)
        full = np.column_stack([pts] + [np.full(len(pts), mid[k]) for k in range(2, d)])
        grid = pd.DataFrame(full, columns=names)
        for name, sur in surrogates.items():
            grid[name] = sur.predict(full)
        values = {r: grid[r].to_numpy() for r in surrogates}
        grid2 = pd.DataFrame(pts, columns=names[:2]).assign(**values)
        held = ", ".join(
            f"{tex_label(spec.factor(f).label)} = {mid[k + 2]:.3g}"
            + (f" {tex_unit(spec.factor(f).unit)}" if spec.factor(f).unit != "-" else "")
            for k, f in enumerate(names[2:]))
        return surface_figure(slice_domain, spec, grid2, n, runs_on_slice(table, domain, mid),
                              f"{title} — slice at {held} (held at mid-range)")
    grid = predict_grid(surrogates, domain, n)
    return surface_figure(domain, spec, grid, n, table, title)

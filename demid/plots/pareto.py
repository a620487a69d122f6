"""Pareto trade-off figure: objective cloud and front (paper Fig. 4)."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from ..formulas import relative_error
from .labels import PALETTE, axis_label, tex_label
from .layout import PAGE_WIDTH_IN
from .style import plt, styled

if TYPE_CHECKING:
    from ..spec import MaterialSpec
    import pandas as pd


@styled
def pareto_figure(grid: pd.DataFrame, front: pd.DataFrame, spec: MaterialSpec, cloud_points: int = 60_000) -> plt.Figure:
    """Objective cloud (a seeded random subsample of the grid) and the Pareto front, with a zoom on
    the low-error end where the front's intervals are read."""
    error_of, minimise, max_error = spec.pareto.error_of, spec.pareto.minimise, spec.pareto.max_error
    target, title = spec.targets[error_of], spec.label
    error = 100 * np.abs(relative_error(grid[error_of].to_numpy(), target))
    objective = grid[minimise].to_numpy()
    rng = np.random.default_rng(0)  # a random subsample avoids the moire of a strided one
    pick = np.sort(rng.choice(len(error), size=min(cloud_points, len(error)), replace=False))
    fig, axes = plt.subplots(1, 2, figsize=(PAGE_WIDTH_IN, 3.6))
    front_err = 100 * front["error"].to_numpy()
    front_obj = front["objective"].to_numpy()
    for ax, zoom in zip(axes, (False, True)):
        ax.plot(error[pick], objective[pick], ".", ms=1.2, color="#bdbdbd", alpha=0.6, rasterized=True,
                label="grid points (random subsample)")
        ax.plot(front_err, front_obj, "-", color=PALETTE[0], lw=1.8, label="Pareto front")
        ax.axvline(100 * max_error, color=PALETTE[5], ls="--", lw=1, label=f"error = {100 * max_error:g} %")
        ax.set_xlabel(f"relative error of {tex_label(spec.response(error_of).label)} [%]")
        ax.set_ylabel(axis_label(spec.response(minimise)))
        if zoom:
            xmax = 3 * 100 * max_error
            near = front_obj[front_err <= xmax]
            lo, hi = (near.min(), near.max()) if len(near) else (front_obj.min(), front_obj.max())
            pad = 0.5 * (hi - lo) + 1e-9 * max(abs(hi), 1.0)
            ax.set_xlim(0, xmax)
            ax.set_ylim(lo - pad, hi + 4 * pad)
            ax.set_title(f"zoom: error ≤ {xmax:g} %")
        else:
            ax.set_title("objective cloud")
    # below the panels, never over the cloud
    fig.legend(*axes[0].get_legend_handles_labels(), loc="lower center", ncol=2, frameon=False, markerscale=6,
               bbox_to_anchor=(0.5, 0.0))
    if title:
        fig.suptitle(title)
    fig.set_layout_engine("tight", rect=(0, 0.14, 1, 1))  # laid out when drawn (demid.io.save_figure), once
    return fig

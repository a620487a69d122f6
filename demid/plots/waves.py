"""The admissible sets wave by wave: the feasible fraction of Omega against the runs spent, and each
factor's admissible interval against the wave."""

from __future__ import annotations

import pandas as pd

from .labels import axis_label, tex_label
from .layout import panel_grid
from .style import SCENARIO_COLORS, styled


@styled
def waves_figure(history: pd.DataFrame, spec):
    """One panel for the feasible fraction of Omega (per scenario, against runs simulated), one per factor
    with its admissible interval per wave (scenarios side by side) over the wave's box (a grey bar)
    and the search range (a light band)."""
    import matplotlib.pyplot as plt

    scenarios = list(dict.fromkeys(history["scenario"]))
    labels = {sc.name: sc.label for sc in spec.scenarios}
    nrow, ncol, size = panel_grid(1 + spec.dim, 3.2, 3.0)  # panels wrap into rows within the page width
    fig, grid = plt.subplots(nrow, ncol, figsize=size, squeeze=False)
    axes = grid.ravel()
    for ax in axes[1 + spec.dim:]:
        ax.set_visible(False)
    per_wave = history.drop_duplicates(["wave", "scenario"])
    for i, scenario in enumerate(scenarios):
        rows = per_wave[per_wave["scenario"] == scenario]
        axes[0].plot(rows["runs_simulated"], rows["feasible_fraction_of_omega_pct"], marker="o",
                     color=SCENARIO_COLORS[i % len(SCENARIO_COLORS)], label=tex_label(labels.get(scenario, scenario)))
    from matplotlib.ticker import MaxNLocator

    axes[0].xaxis.set_major_locator(MaxNLocator(integer=True))  # runs are counted: no tick at 12.5 runs
    axes[0].set_xlabel("runs simulated")
    axes[0].set_ylabel("feasible fraction of Ω [%]")
    axes[0].legend(frameon=False)
    # scenarios side by side within a wave
    offsets = [0.0] if len(scenarios) == 1 else [-0.15 + 0.3 * i / (len(scenarios) - 1) for i in range(len(scenarios))]
    for ax, factor in zip(axes[1:], spec.factors):
        ax.axhspan(factor.lower, factor.upper, color="0.95", zorder=0)
        boxes = history[history["factor"] == factor.name].drop_duplicates("wave")
        ax.bar(boxes["wave"], boxes["box_upper"] - boxes["box_lower"], bottom=boxes["box_lower"], width=0.5,
               color="0.82", zorder=1)
        for i, scenario in enumerate(scenarios):
            rows = history[(history["scenario"] == scenario) & (history["factor"] == factor.name)].dropna(
                subset=["lower", "upper"])
            ax.vlines(rows["wave"] + offsets[i], rows["lower"], rows["upper"], linewidth=3,
                      color=SCENARIO_COLORS[i % len(SCENARIO_COLORS)], zorder=2)
        ax.set_xticks(sorted(history["wave"].unique()))
        ax.set_xlabel("wave")
        ax.set_ylabel(axis_label(factor))
        if factor.log:
            ax.set_yscale("log")
    fig.tight_layout()
    return fig

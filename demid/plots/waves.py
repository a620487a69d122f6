"""The sets wave by wave: the plausible share of Omega against the runs spent, and per factor each wave's
plausible interval beside the runs that wave simulated, over the last wave's plausible interval."""

from __future__ import annotations

import numpy as np
import pandas as pd

from .labels import axis_label, tex_label
from .layout import panel_grid
from .style import SCENARIO_COLORS, styled

#: Where a wave's runs are drawn beside its intervals (in waves along the x axis).
RUNS_OFFSET = -0.3


@styled
def waves_figure(history: pd.DataFrame, spec, runs: pd.DataFrame | None = None):
    """One panel for the share of Omega per scenario against the runs simulated: the plausible share (solid, the
    number the report's Waves table prints; the y axis from 0 so a change of a hundredth of a percent does not look
    like a collapse) and the strict share (dashed); one panel per factor with each wave's plausible interval per
    scenario (the strict one thin beside it), the factor values of the runs the wave simulated (grey dots, failed
    runs as crosses) and, as a light band across all waves, the last wave's plausible interval: where the runs
    went against the set they decided.  ``runs``: every run simulated (a wave's table, with ``wave`` and
    ``status``); without it no runs are drawn.  Without plausible columns (a history of before they existed) the
    strict numbers stand alone."""
    import matplotlib.pyplot as plt
    from matplotlib.ticker import MaxNLocator

    scenarios = list(dict.fromkeys(history["scenario"]))
    labels = {sc.name: sc.label for sc in spec.scenarios}
    colors = {s: SCENARIO_COLORS[i % len(SCENARIO_COLORS)] for i, s in enumerate(scenarios)}
    plausible = "plausible_fraction_of_omega_pct" in history and history["plausible_fraction_of_omega_pct"].notna().any()
    nrow, ncol, size = panel_grid(1 + spec.dim, 3.2, 3.0)  # panels wrap into rows within the page width
    fig, grid = plt.subplots(nrow, ncol, figsize=size, squeeze=False)
    axes = grid.ravel()
    for ax in axes[1 + spec.dim:]:
        ax.set_visible(False)
    _share_panel(axes[0], history.drop_duplicates(["wave", "scenario"]), scenarios, labels, colors, plausible)
    axes[0].xaxis.set_major_locator(MaxNLocator(integer=True))  # runs are counted: no tick at 12.5 runs
    offsets = [0.0] if len(scenarios) == 1 else [-0.1 + 0.3 * i / (len(scenarios) - 1) for i in range(len(scenarios))]
    last = history["wave"].max()
    for ax, factor in zip(axes[1:], spec.factors):
        ax.axhspan(factor.lower, factor.upper, color="0.96", zorder=0)
        for i, scenario in enumerate(scenarios):
            rows = history[(history["scenario"] == scenario) & (history["factor"] == factor.name)]
            _intervals(ax, rows, offsets[i], colors[scenario], plausible, last)
        if runs is not None and factor.name in runs:
            _runs(ax, runs, factor.name)
        ax.set_xticks(sorted(history["wave"].unique()))
        ax.set_xlim(min(history["wave"]) - 0.6, last + 0.5)
        ax.set_xlabel("wave")
        ax.set_ylabel(axis_label(factor))
        if factor.log:
            ax.set_yscale("log")
    fig.tight_layout()
    return fig


def _share_panel(ax, per_wave: pd.DataFrame, scenarios, labels, colors, plausible: bool) -> None:
    for scenario in scenarios:
        rows = per_wave[per_wave["scenario"] == scenario]
        label = tex_label(labels.get(scenario, scenario))
        if plausible:
            ax.plot(rows["runs_simulated"], rows["plausible_fraction_of_omega_pct"], marker="o",
                    color=colors[scenario], label=f"{label}: plausible")
        ax.plot(rows["runs_simulated"], rows["feasible_fraction_of_omega_pct"], marker="." if plausible else "o",
                linestyle="--" if plausible else "-", linewidth=1 if plausible else 1.5, color=colors[scenario],
                label=f"{label}: strict" if plausible else label)
    ax.set_ylim(bottom=0)
    ax.set_xlabel("runs simulated")
    ax.set_ylabel("share of Ω [%]")
    ax.legend(frameon=False, fontsize="small")


def _intervals(ax, rows: pd.DataFrame, offset: float, color, plausible: bool, last: int) -> None:
    strict = rows.dropna(subset=["lower", "upper"])
    if not plausible:
        ax.vlines(strict["wave"] + offset, strict["lower"], strict["upper"], linewidth=3, color=color, zorder=2)
        return
    wide = rows.dropna(subset=["plausible_lower", "plausible_upper"])
    ax.vlines(wide["wave"] + offset, wide["plausible_lower"], wide["plausible_upper"], linewidth=3, color=color,
              zorder=2)
    ax.vlines(strict["wave"] + offset + 0.08, strict["lower"], strict["upper"], linewidth=1, color=color, zorder=2)
    final = wide[wide["wave"] == last]
    if len(final):
        ax.axhspan(float(final["plausible_lower"].iloc[0]), float(final["plausible_upper"].iloc[0]), color=color,
                   alpha=0.12, zorder=1)


def _runs(ax, runs: pd.DataFrame, factor: str) -> None:
    """The runs each wave simulated, as dots left of the wave's intervals (crosses: failed)."""
    failed = runs["status"].eq("failed") if "status" in runs else pd.Series(False, index=runs.index)
    wave = runs["wave"].to_numpy(dtype=float) if "wave" in runs else np.ones(len(runs))
    values = pd.to_numeric(runs[factor], errors="coerce").to_numpy(dtype=float)
    ok = ~failed.to_numpy()
    ax.scatter(wave[ok] + RUNS_OFFSET, values[ok], s=9, color="0.35", zorder=3, linewidths=0)
    if (~ok).any():
        ax.scatter(wave[~ok] + RUNS_OFFSET, values[~ok], s=14, marker="x", color="0.35", zorder=3, linewidths=0.8)

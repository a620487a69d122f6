"""Uncertainty figures: the tolerance sweep and the posterior marginals."""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

from ..spec import join_observables
from .labels import PALETTE
from .layout import hold_constant_axis, panel_grid

_LINESTYLES = ["-", "--", "-.", ":"]
_MARKERS = ["o", "s", "^", "D", "v", "P", "X", "*"]


def _style(k: int) -> dict:
    """Colour, line style and marker of the k-th observable set: told apart without colour too."""
    return {"color": PALETTE[k % len(PALETTE)], "ls": _LINESTYLES[k % len(_LINESTYLES)],
            "marker": _MARKERS[k % len(_MARKERS)]}


def spaced_ticks(values: list[float], min_decades: float = 0.15) -> set[float]:
    """The tick values to label on a log axis: none closer than ``min_decades`` to the last one
    labelled (7.5 beside 10 would print as "7.510" on a narrow panel)."""
    import math

    kept: list[float] = []
    for v in sorted(values):
        if not kept or math.log10(v) - math.log10(kept[-1]) >= min_decades:
            kept.append(v)
    return set(kept)


def _panel_axes(fig, n_panels: int, nrow: int, ncol: int):
    """The first ``n_panels`` axes of an nrow x ncol grid; the rest hidden."""
    grid = fig.subplots(nrow, ncol, squeeze=False).ravel()
    for ax in grid[n_panels:]:
        fig.delaxes(ax)  # an empty cell of the grid, not a panel
    return grid[:n_panels]


def _plain_log_axis(axis) -> None:
    """Log axis labelled at its decades in plain numbers, without minor labels (no 6x10^0)."""
    from matplotlib.ticker import LogLocator, NullFormatter, FuncFormatter

    axis.set_major_locator(LogLocator(base=10))
    axis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
    axis.set_minor_formatter(NullFormatter())

if TYPE_CHECKING:
    import pandas as pd


# =========================================================================== figures
def tolerance_sweep_figure(frame: pd.DataFrame, title: str, *, factor_labels: dict[str, str] | None = None,
                           scenario_labels: dict[str, str] | None = None):
    """Phi(eps) on a log scale (one curve per observable set) and one span panel per factor.

    ``scenario_labels`` are the legend texts (the configured scenario labels); a scenario
    without one is named by its key and observables."""
    from matplotlib.figure import Figure
    from matplotlib.ticker import FixedLocator, FuncFormatter, NullFormatter

    factor_labels = factor_labels or {}
    scenario_labels = scenario_labels or {}
    factors = list(dict.fromkeys(frame["factor"]))
    nrow, ncol, (width, height) = panel_grid(1 + len(factors), 3.6, 2.8)
    fig = Figure(figsize=(width, height + 0.4), layout="constrained")
    axes = _panel_axes(fig, 1 + len(factors), nrow, ncol)
    for k, (scenario, rows) in enumerate(frame.groupby("scenario", sort=False)):
        style = _style(k)
        color = style["color"]
        label = scenario_labels.get(scenario) or f"{scenario}: {rows['observables'].iloc[0]}"
        first = rows.drop_duplicates("tolerance").sort_values("tolerance")
        tol_pct = 100 * first["tolerance"].to_numpy()
        frac = first["feasible_fraction_pct"].to_numpy()
        positive = frac > 0
        axes[0].plot(tol_pct[positive], frac[positive], label=label, **style)
        if "fraction_error_pct" in first:
            err = first["fraction_error_pct"].to_numpy()
            axes[0].errorbar(tol_pct[positive], frac[positive], yerr=err[positive], fmt="none", color=color)
        for ax, factor in zip(axes[1:], factors):
            sub = rows[rows["factor"] == factor].sort_values("tolerance")
            ax.plot(100 * sub["tolerance"], sub["width"], label=label, **style)
    if (frame["feasible_fraction_pct"] > 0).any():
        axes[0].set_yscale("log")
        _plain_log_axis(axes[0].yaxis)
    else:  # a log axis of all zeros cannot be drawn; say what the empty panel means
        axes[0].text(0.5, 0.5, "no admissible point at any swept tolerance:\nthe targets are out of reach",
                     transform=axes[0].transAxes, ha="center", va="center")
    axes[0].set_xlabel("tolerance ε [%]")
    axes[0].set_ylabel("feasible fraction Φ(ε) [% of Ω]")
    fig.legend(*axes[0].get_legend_handles_labels(), loc="outside lower center", ncol=min(3, len(frame["scenario"].unique())),
               fontsize="small", frameon=False)
    for ax, factor in zip(axes[1:], factors):
        ax.set_xlabel("tolerance ε [%]")
        ax.set_ylabel(f"admissible width of {factor_labels.get(factor, factor)}")
        hold_constant_axis(ax)
    swept = sorted(set(100 * frame["tolerance"].astype(float)))
    for ax in axes:
        ax.set_xscale("log")
        if len(swept) <= 10:  # ticks at the swept tolerances, written as plain percentages (2, not 2x10^0)
            ax.xaxis.set_major_locator(FixedLocator(swept))
            labelled = spaced_ticks(swept)
            ax.xaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}" if v in labelled else ""))
            ax.xaxis.set_minor_formatter(NullFormatter())
        ax.grid(True, which="both", alpha=0.3)
    fig.suptitle(title)
    return fig


def posterior_figure(posteriors: dict, title: str, *, factor_labels: dict[str, str] | None = None,
                     unreachable=(), observable_labels: dict[str, str] | None = None):
    """Marginal posterior densities per factor, one curve per observable set; the 95 % credible
    intervals as bars below zero, in the same order, colours, line styles and end markers (told
    apart in grey print too).  Sets named in ``unreachable`` (``d5+d10``) have a target out of
    reach: labelled so, without an information gain.  ``observable_labels`` name the observables
    in the legend (the configured labels); a key without one is shown as it is."""
    from matplotlib.figure import Figure

    factor_labels = factor_labels or {}
    observable_labels = observable_labels or {}
    posts = list(posteriors.values())
    factors = posts[0].factors
    legend_cols = 1 if len(posts) <= 3 else 2
    nrow, ncol, (width, height) = panel_grid(len(factors), 3.6, 2.9)
    legend_in = 0.3 + 0.2 * -(-len(posts) // legend_cols)
    fig = Figure(figsize=(width, height + legend_in), layout="constrained")
    axes = _panel_axes(fig, len(factors), nrow, ncol)
    intervals = [[] for _ in factors]
    for k, post in enumerate(posts):
        name = join_observables(post.observables)
        shown = " + ".join(observable_labels.get(o, o) for o in post.observables)
        label = (f"{shown} (targets out of reach: misfit)" if name in unreachable
                 else f"{shown} ({post.information_gain_bits:.2f} bits)")
        style = _style(k)
        for i, ax in enumerate(axes):
            x = post.axes_actual[i]
            ax.plot(x, post.marginals[i], label=label, markevery=max(1, len(x) // 6), ms=4, **style)
            # 95 % intervals as a bar under the curves: filled areas of many sets would hide each other.
            intervals[i].append((post.credible_lower[i], post.credible_upper[i], style))
            if post.log[i]:
                ax.set_xscale("log")
    for i, ax in enumerate(axes):
        ax.set_xlabel(factor_labels.get(factors[i], factors[i]))
        unit = re.search(r"\[(.*)\]$", ax.get_xlabel())
        unit = unit.group(1) if unit else "–"
        if posts[0].log[i]:
            ax.set_ylabel("posterior density [per log10 unit]")
            _plain_log_axis(ax.xaxis)
        else:
            ax.set_ylabel("posterior density [" + ("–" if unit == "–" else f"1/({unit})") + "]")
        top = max(max(post.marginals[i]) for post in posts)
        step = 0.06 * top
        for k, (lo, hi, style) in enumerate(intervals[i]):
            ax.plot([lo, hi], [-step * (k + 1)] * 2, color=style["color"], ls=style["ls"], lw=2.0,
                    marker=style["marker"], ms=4, solid_capstyle="butt")
        ax.axhline(0, color="0.6", lw=0.6)
        ax.set_ylim(-step * (len(intervals[i]) + 1), 1.05 * top)
        ax.set_yticks([t for t in ax.get_yticks() if 0 <= t <= 1.05 * top])  # no negative density ticks
    fig.legend(*axes[0].get_legend_handles_labels(), loc="outside lower center", ncol=legend_cols,
               fontsize="small", frameon=False)
    fig.suptitle(f"{title}: posterior densities\nbars below zero: 95 % credible intervals", fontsize="medium")
    return fig

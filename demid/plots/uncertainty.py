"""Uncertainty figures: the tolerance sweep and the posterior marginals."""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

from ..spec import join_observables
from .labels import PALETTE

_LINESTYLES = ["-", "--", "-.", ":"]

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
    fig = Figure(figsize=(4.2 * (1 + len(factors)), 3.6), layout="constrained")
    axes = fig.subplots(1, 1 + len(factors), squeeze=False)[0]
    for k, (scenario, rows) in enumerate(frame.groupby("scenario", sort=False)):
        color = PALETTE[k % len(PALETTE)]
        label = scenario_labels.get(scenario) or f"{scenario}: {rows['observables'].iloc[0]}"
        first = rows.drop_duplicates("tolerance").sort_values("tolerance")
        tol_pct = 100 * first["tolerance"].to_numpy()
        frac = first["feasible_fraction_pct"].to_numpy()
        positive = frac > 0
        axes[0].plot(tol_pct[positive], frac[positive], "o-", color=color, label=label)
        if "fraction_error_pct" in first:
            err = first["fraction_error_pct"].to_numpy()
            axes[0].errorbar(tol_pct[positive], frac[positive], yerr=err[positive], fmt="none", color=color)
        for ax, factor in zip(axes[1:], factors):
            sub = rows[rows["factor"] == factor].sort_values("tolerance")
            ax.plot(100 * sub["tolerance"], sub["width"], "o-", color=color, label=label)
    if (frame["feasible_fraction_pct"] > 0).any():
        axes[0].set_yscale("log")
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
    swept = sorted(set(100 * frame["tolerance"].astype(float)))
    for ax in axes:
        ax.set_xscale("log")
        if len(swept) <= 10:  # ticks at the swept tolerances, written as plain percentages (2, not 2x10^0)
            ax.xaxis.set_major_locator(FixedLocator(swept))
            ax.xaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
            ax.xaxis.set_minor_formatter(NullFormatter())
        ax.grid(True, which="both", alpha=0.3)
    fig.suptitle(title)
    return fig


def posterior_figure(posteriors: dict, title: str, *, factor_labels: dict[str, str] | None = None,
                     unreachable=()):
    """Marginal posterior densities per factor, one curve per observable set; the 95 % credible
    intervals as bars below zero, in the same order and colours.  Sets named in ``unreachable``
    (``d5+d10``) have a target out of reach: labelled so, without an information gain."""
    from matplotlib.figure import Figure

    factor_labels = factor_labels or {}
    posts = list(posteriors.values())
    factors = posts[0].factors
    fig = Figure(figsize=(4.2 * len(factors), 3.4), layout="constrained")
    axes = fig.subplots(1, len(factors), squeeze=False)[0]
    intervals = [[] for _ in factors]
    for k, post in enumerate(posts):
        name = join_observables(post.observables)
        label = (f"{name} (targets out of reach: misfit)" if name in unreachable
                 else f"{name} ({post.information_gain_bits:.2f} bits)")
        for i, ax in enumerate(axes):
            x = post.axes_actual[i]
            color = PALETTE[k % len(PALETTE)]
            ax.plot(x, post.marginals[i], color=color, ls=_LINESTYLES[k // len(PALETTE) % 4] if k >= len(PALETTE)
                    else _LINESTYLES[k % 4], label=label)
            # 95 % intervals as a bar under the curves: filled areas of many sets would hide each other.
            intervals[i].append((post.credible_lower[i], post.credible_upper[i], color))
            if post.log[i]:
                ax.set_xscale("log")
    for i, ax in enumerate(axes):
        ax.set_xlabel(factor_labels.get(factors[i], factors[i]))
        unit = re.search(r"\[(.*)\]$", ax.get_xlabel())
        unit = unit.group(1) if unit else "–"
        if posts[0].log[i]:
            ax.set_ylabel("posterior density [per log10 unit]")
        else:
            ax.set_ylabel("posterior density [" + ("–" if unit == "–" else f"1/({unit})") + "]")
        top = max(max(post.marginals[i]) for post in posts)
        step = 0.05 * top
        for k, (lo, hi, color) in enumerate(intervals[i]):
            ax.plot([lo, hi], [-step * (k + 1)] * 2, color=color, lw=2.5, solid_capstyle="butt")
        ax.axhline(0, color="0.6", lw=0.6)
        ax.set_ylim(-step * (len(intervals[i]) + 1), 1.05 * top)
        ax.set_yticks([t for t in ax.get_yticks() if 0 <= t <= 1.05 * top])  # no negative density ticks
    fig.legend(*axes[0].get_legend_handles_labels(), loc="outside lower center", ncol=min(3, len(posts)),
               fontsize="small", frameon=False)
    fig.suptitle(f"{title}: posterior densities; bars below zero are 95 % credible intervals")
    return fig

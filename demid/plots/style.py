"""Shared figure style: the Agg backend, rcParams, scenario colours and axis helpers.

Imported by the set, surface and Pareto figures only, so the uncertainty and
criticism figures keep matplotlib's defaults exactly as before.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after selecting the backend)

if TYPE_CHECKING:
    from ..sampling import Domain


plt.rcParams.update({
    "figure.dpi": 150, "font.size": 9, "axes.titlesize": 10, "axes.labelsize": 9,
    "legend.fontsize": 8, "svg.hashsalt": "demid", "axes.spines.top": False, "axes.spines.right": False,
})

SCENARIO_COLORS = ["#9ecae1", "#08519c", "#fdae6b", "#a63603", "#74c476", "#006d2c"]
MAX_PIXELS = 500


def _extent(domain: Domain, i: int, j: int):
    lo, hi = domain.search_bounds()
    return [lo[i], hi[i], lo[j], hi[j]]


def _axis_scale(ax, domain: Domain, i: int, j: int):
    # imshow works in search units; label log factors with actual values.
    for k, setter in ((i, ax.xaxis), (j, ax.yaxis)):
        if domain.log[k]:
            setter.set_major_formatter(matplotlib.ticker.FuncFormatter(lambda v, _: f"{10 ** v:.3g}"))

"""Shared figure style: the Agg backend, rcParams, scenario colours and axis helpers.

Used by the set, surface and Pareto figures only (:func:`styled`); the uncertainty and
criticism figures keep matplotlib's defaults.
"""

from __future__ import annotations

import functools
from typing import TYPE_CHECKING

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402,F401  (after selecting the backend; the figure modules import it from here)

from .labels import PALETTE  # noqa: E402

if TYPE_CHECKING:
    from ..sampling import Domain


#: rcParams of the set, surface and Pareto figures.  Applied per figure (:func:`styled`), not to the
#: process: the uncertainty and criticism figures, drawn in the same process, keep matplotlib's defaults.
STYLE = {
    "figure.dpi": 150, "axes.prop_cycle": matplotlib.cycler(color=PALETTE), "font.size": 9, "axes.titlesize": 10, "axes.labelsize": 9,
    "legend.fontsize": 8, "svg.hashsalt": "demid", "axes.spines.top": False, "axes.spines.right": False,
}


def styled(make):
    """Build the figure under :data:`STYLE` and remember it there (``figure_style``), so that
    :func:`demid.io.save_figure` draws it under the same rcParams (tick labels are made at draw time)."""

    @functools.wraps(make)
    def build(*args, **kwargs):
        with matplotlib.rc_context(STYLE):
            fig = make(*args, **kwargs)
        fig.figure_style = STYLE
        return fig

    return build

# Scenarios are drawn in order over each other (a later, larger observable set is a subset),
# in the colour-blind-safe palette.
SCENARIO_COLORS = [PALETTE[4], PALETTE[0], PALETTE[1], PALETTE[5], PALETTE[2], PALETTE[3]]
MAX_PIXELS = 500


def _extent(domain: Domain, i: int, j: int):
    lo, hi = domain.search_bounds()
    return [lo[i], hi[i], lo[j], hi[j]]


def _axis_scale(ax, domain: Domain, i: int, j: int):
    # imshow works in search units; label log factors with actual values.
    for k, setter in ((i, ax.xaxis), (j, ax.yaxis)):
        if domain.log[k]:
            setter.set_major_formatter(matplotlib.ticker.FuncFormatter(lambda v, _: f"{10 ** v:.3g}"))

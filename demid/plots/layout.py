"""Figure geometry for print: page width, panel grids and axes that hold a constant.

No pyplot import and no style: shared by every figure module.
"""

from __future__ import annotations

import math

#: Full text width of a two-column journal page: every figure is at most this wide, so its text
#: (9–10 pt, legends 8 pt) keeps its size in print.  Panels wrap into rows instead of shrinking.
PAGE_WIDTH_IN = 7.2

#: Markers of one artist above which it is drawn as an image inside the SVG (the PNG is the same either way):
#: a vector marker per run makes a 10,000-run figure's SVG several MB and seconds to write.  Every point is
#: still drawn; tables of a CCD's size stay vector.
RASTER_ABOVE_POINTS = 2000


def panel_grid(n_panels: int, panel_width: float, panel_height: float, max_width: float = PAGE_WIDTH_IN
               ) -> tuple[int, int, tuple[float, float]]:
    """Rows, columns and figure size (inches) for ``n_panels`` equal panels within ``max_width``."""
    ncol = max(1, min(n_panels, int(max_width // panel_width)))
    nrow = max(1, math.ceil(n_panels / ncol))
    return nrow, ncol, (min(max_width, ncol * panel_width), nrow * panel_height)


def hold_constant_axis(ax, axis: str = "y", rel: float = 1e-9) -> None:
    """An axis whose plotted data do not vary gets a range of ±5 % around the value instead of an
    offset axis spelling out round-off (0.3364 + 1e-12)."""
    data = [line.get_ydata() if axis == "y" else line.get_xdata() for line in ax.get_lines()]
    values = [float(v) for column in data for v in column if math.isfinite(float(v))]
    if not values:
        return
    lo, hi = min(values), max(values)
    if hi - lo > rel * max(abs(hi), abs(lo), 1e-300):
        return
    half = 0.05 * abs(hi) if hi else 1.0
    (ax.set_ylim if axis == "y" else ax.set_xlim)(hi - half, hi + half)
    formatter = (ax.yaxis if axis == "y" else ax.xaxis).get_major_formatter()
    if hasattr(formatter, "set_useOffset"):
        formatter.set_useOffset(False)

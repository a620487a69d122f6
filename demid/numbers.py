"""Which numbers demid computes with: finite, and zero or of a magnitude between 1e-30 and 1e30.

A table cell or config value beyond that (1e308, a denormal 5e-324, 1e5000 read as infinity, 1e-400
read as 0) is a slip or a unit far off, and squared sums and grids of such numbers overflow or lose
every digit: each is refused with one line naming the cell or key.  DEM quantities (Young's moduli of
1e12 Pa, Hamaker constants of 1e-20 J) are well inside.
"""

from __future__ import annotations

import math
import re

SMALLEST, LARGEST = 1e-30, 1e30
_NONZERO_DIGIT = re.compile(r"[1-9]")


def unusable_number(value: float, text: str | None = None) -> str:
    """Why ``value`` (read from ``text``, when given) is no number to compute with ("" when it is)."""
    shown = f"'{text.strip()}'" if text is not None else f"{value:g}"
    if text is not None and value == 0 and _NONZERO_DIGIT.search(re.split(r"[eE]", text)[0]):
        return f"found {shown}, too small for a float (it reads as 0); give it in another unit"
    if math.isnan(value):
        return f"found {shown}, not a number"
    if math.isinf(value):
        spelled = text is not None and text.strip().lstrip("+-").lower() in ("inf", "infinity")
        return f"found {shown}, " + ("an infinite value" if spelled else "too large for a float (it overflows "
                                                                          "to infinity)")
    if value != 0 and not SMALLEST <= abs(value) <= LARGEST:
        return (f"found {shown}, outside the magnitudes demid computes with (0, or 1e-30 to 1e30); "
                "check the value, or give it in another unit")
    return ""

"""A strict set judged on the grid (a surrogate that is no polynomial of the search units: linear in b on a
log10 b axis), over generated targets of either sign, tolerances, slopes and grid sizes (odd and even): its
fraction of Ω and its spans (actual units) are those of the set counted on a fine grid written out here, and its error
covers the difference."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from demid.admissibility import Domain
from demid.design import quadratic_terms
from demid.surrogate import Surrogate
from demid.uncertainty.plausible import summarise_set

DOMAIN = Domain(("a", "b"), (0.0, 1.0), (1.0, 10.0), (False, True))


def _linear(intercept: float, slope_a: float, slope_b: float) -> Surrogate:
    terms = quadratic_terms(2)
    coef = np.zeros(len(terms))
    coef[:3] = intercept, slope_a, slope_b
    return Surrogate("y", ["a", "b"], terms, coef, np.zeros((len(terms), len(terms))), 0.0, 1, ())


def _counted(coef, target: float, tolerance: float, m: int = 1200):
    """The set's fraction of Ω and its spans (search units) on an m x m midpoint grid of (a, log10 b)."""
    u = (np.arange(m) + 0.5) / m
    a, t = np.meshgrid(u, u, indexing="ij")
    b = 10.0 ** t
    y = coef[0] + coef[1] * a + coef[2] * b
    inside = np.abs(y - target) <= tolerance * abs(target)
    spans = [(c[inside].min(), c[inside].max()) if inside.any() else (np.nan, np.nan) for c in (a, t)]
    return inside.mean(), spans


@given(sign=st.sampled_from([1.0, -1.0]), tolerance=st.sampled_from([0.03, 0.1, 0.25]),
       slope_a=st.floats(0.2, 3.0), slope_b=st.floats(0.05, 0.5), level=st.floats(0.3, 0.7),
       n=st.sampled_from([31, 40, 41]))
@settings(max_examples=12, deadline=None, derandomize=True)
def test_a_strict_set_on_the_grid_has_the_counted_fraction_and_spans(sign, tolerance, slope_a, slope_b, level, n):
    # the target: the response's value at a level of its range, so the set crosses the square
    low, high = 1.0 + slope_b, 1.0 + slope_a + 10.0 * slope_b
    target = sign * (low + level * (high - low))
    coef = (sign * 1.0, sign * slope_a, sign * slope_b)
    sur = _linear(*coef)
    found = summarise_set({"y": sur}, DOMAIN, ["y"], {"y": target}, tolerance, n)
    fraction, spans = _counted(coef, target, tolerance)
    assert found.method.startswith(f"grid {n}^2")
    assert abs(found.fraction - fraction) <= 0.02 * fraction + 2e-3
    assert found.error <= 0.05 * fraction + 2e-3 and found.error >= 0.0
    # spans in actual units: b's compared on its log10 axis
    lower = [found.lower[0], np.log10(found.lower[1])]
    upper = [found.upper[0], np.log10(found.upper[1])]
    for j, (lo, hi) in enumerate(spans):
        assert abs(lower[j] - lo) <= 2e-3 and abs(upper[j] - hi) <= 2e-3
